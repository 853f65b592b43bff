#!/usr/bin/env bash
# Configures and builds into build/ (or $DW_BUILD_DIR). Called by run.sh and test.sh.
# Arguments go to 'cmake --build' (run.sh: --target deferred-workbench, the window alone).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DW_BUILD_DIR:-$root/build}
type=${DW_BUILD_TYPE:-Release}
werror=OFF
if [[ "${CI:-}" == "true" ]]; then werror=ON; fi
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE="$type" -DDW_WERROR=$werror >/dev/null
cmake --build "$build" --parallel "$(nproc)" "$@"

#!/usr/bin/env bash
# Installs what is missing, builds, and renders the built-in "default" scene
# headless to out/default.png. Extra arguments go to `render` (e.g. --scene street).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh"
"$root/scripts/build.sh"
bin=${DW_BUILD_DIR:-$root/build}/deferred-workbench
mkdir -p "$root/out"
exec "$bin" render --scene default --size 1280x720 --out "$root/out/default.png" "$@"

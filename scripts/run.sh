#!/usr/bin/env bash
# Installs what is missing, builds, and opens the workbench on the built-in
# "default" scene. Extra arguments go to the workbench (e.g. --scene street).
# Without a display it renders the scene headless and says where the image is.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh"
# The window needs the one binary; the test command builds the suite.
"$root/scripts/build.sh" --target deferred-workbench
bin=${DW_BUILD_DIR:-$root/build}/deferred-workbench
if [[ -z "${DISPLAY:-}" && -z "${WAYLAND_DISPLAY:-}" ]]; then
  mkdir -p "$root/out"
  echo "run: no display, so no window; rendering headless instead, to out/frame.png"
  # No --scene here: the default scene is the default, and a --preset naming
  # its own scene should get it (an explicit --scene would win over it).
  exec "$bin" render --size 1280x720 --out "$root/out/frame.png" "$@"
fi
exec "$bin" gui "$@"

#!/usr/bin/env bash
# Installs the Debian packages the workbench needs, and nothing else.
# Idempotent and non-interactive: packages already present are not touched, and
# apt is not called at all when nothing is missing.
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build pkg-config
  # libraries (DESIGN.md: Debian packages only, nothing vendored)
  libimgui-dev libstb-dev libglfw3-dev libglm-dev libtinygltf-dev
  libopenimageio-dev libepoxy-dev nlohmann-json3-dev
  # sha256 of images and scene files in experiment records (render --record, replay)
  libssl-dev
  # the CPU reference renderer: Embree 3 ray queries, oneTBB threads
  libembree-dev libtbb-dev
  # RenderDoc's in-app API header (the library is loaded only when asked)
  librenderdoc-dev
  # headless OpenGL through EGL (Mesa llvmpipe where there is no GPU)
  libegl-dev libegl1 libegl-mesa0 libgl1-mesa-dri libgl-dev
  # the Python module deferred_workbench (python/): pybind11, the headers of
  # Debian's python3 and numpy, which its arrays are
  pybind11-dev python3-dev python3-numpy
  # tests
  libgtest-dev xvfb xauth
)
if [[ "${1:-}" == "--tests" ]]; then
  # Real glTF files, valid and broken, for the loader tests (they skip without it);
  # matplotlib for bench --plot (scripts/bench_plot.py), which the CLI test draws.
  packages+=(assimp-testmodels python3-matplotlib)
  # scikit-image: the SSIM test compares against its structural_similarity (tests/metrics)
  packages+=(python3-skimage)
  # real X key and mouse events for the window's input test (tests/gui/GuiInputTest.cpp)
  packages+=(xdotool)
  # librenderdoc.so, for the frame-capture test (it skips without it)
  packages+=(librenderdoc)
  # the example notebook (docs/ssao-study.ipynb), run headless by the suite
  packages+=(python3-nbconvert python3-nbclient python3-ipykernel python3-nbformat)
fi
if [[ "${1:-}" == "--fuzz" ]]; then
  # clang 14 and libFuzzer's runtime for the fuzz targets (fuzz/README.md).
  packages+=(clang-14 libclang-rt-14-dev)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null; then sudo=(sudo); else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null

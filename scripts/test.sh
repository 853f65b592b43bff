#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite (ctest).
#   scripts/test.sh             the suite (with CI=true also the readers' test
#                               under AddressSanitizer + UndefinedBehaviorSanitizer)
#   scripts/test.sh --sanitize  the whole suite under ASan + UBSan, in its own
#                               build folder (build-sanitize/ or $DW_SANITIZE_BUILD_DIR)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup-deps.sh" --tests

# What the sanitizers report and stop on. Mesa's EGL/llvmpipe driver leaks at
# exit; tests/sanitizer/lsan.supp names its libraries (and nothing of ours).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:check_initialization_order=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/sanitizer/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

# Configures a sanitizer build in $1. -O1, as the sanitizers' documentation
# advises: reports keep their frames, and the build is far quicker than -O3.
# -Werror stays off there: GCC's warnings change with the instrumentation, and
# the plain CI build already has it.
configure_sanitized() {
  cmake -S "$root" -B "$1" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
    -DDW_SANITIZE=ON -DDW_WERROR=OFF >/dev/null
}

if [[ "${1:-}" == "--sanitize" ]]; then
  build=${DW_SANITIZE_BUILD_DIR:-$root/build-sanitize}
  configure_sanitized "$build"
  cmake --build "$build" --parallel "$(nproc)"
  cd "$build"
  ctest --output-on-failure --parallel "$(nproc)" --timeout 1800
  exit 0
fi

(
  unset ASAN_OPTIONS LSAN_OPTIONS UBSAN_OPTIONS
  "$root/scripts/build.sh"
  build=${DW_BUILD_DIR:-$root/build}
  cd "$build"
  ctest --output-on-failure --parallel "$(nproc)" --timeout 600
)

# CI: the readers (every file a user hands over, the fuzz regression corpus)
# under the sanitizers; one small binary, so it adds little to CI's time.
if [[ "${CI:-}" == "true" ]]; then
  build=${DW_SANITIZE_CI_BUILD_DIR:-$root/build-sanitize-readers}
  configure_sanitized "$build"
  cmake --build "$build" --parallel "$(nproc)" --target reader_tests
  "$build/reader_tests"
fi

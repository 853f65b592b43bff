// libFuzzer target: see fuzz/README.md for the command that runs it.
#include "fuzz/FuzzEntries.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    dw::fuzz::gltf(data, size);
    return 0;
}

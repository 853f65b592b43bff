#pragma once
// The entry functions the libFuzzer targets (fuzz_*.cpp) and the regression
// test (tests/readers/FuzzRegressionTest.cpp) share: one input in, the reader
// run on it. A refusal (dw::Error) is a correct answer; anything else that
// escapes (another exception type, a crash, a sanitizer report) is a bug.
// An accepted input must hold only finite values, and a refusal's message must
// name the file and say what is wrong in the format's terms (never a JSON
// library's exception text, never "unknown error"); either failing aborts, so
// libFuzzer keeps the input. Each returns the refusal's message, or "" when
// the input was accepted.
#include <cstddef>
#include <cstdint>
#include <string>

namespace dw::fuzz {

// Scene JSON text, parsed as "<dir>/fuzz.json" (relative files resolve there).
std::string sceneJson(const std::uint8_t* data, std::size_t size);
// Preset JSON text; the knobs it sets are applied to a registry of one knob
// of each type.
std::string preset(const std::uint8_t* data, std::size_t size);
// A .gltf or .glb (by the GLB magic), written to a file and imported.
std::string gltf(const std::uint8_t* data, std::size_t size);

}  // namespace dw::fuzz

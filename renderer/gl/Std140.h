#pragma once
// The C++ half of the parameter blocks in shaders/params/*.h (see
// shaders/params/prelude.h): GLSL's type names as glm types, std140's
// alignment rules, and the description of a block's fields that the
// prelude's DW_PARAM_BLOCK generates. Blocks use glm types, which pack at
// 4 bytes, so a C++ struct has std140's layout exactly when every field
// already sits at a multiple of its std140 alignment and no field is a type
// whose std140 size differs from its C++ size (mat3, bool, arrays of
// anything narrower than 16 bytes); DW_PARAM_BLOCK static_asserts both.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <type_traits>
#include <vector>

namespace dw::gpu {

// GLSL's names, so a block's fields read the same in both languages.
using uint = std::uint32_t;
using vec2 = glm::vec2;
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using ivec2 = glm::ivec2;
using ivec3 = glm::ivec3;
using ivec4 = glm::ivec4;
using uvec2 = glm::uvec2;
using uvec4 = glm::uvec4;
using mat4 = glm::mat4;

// One field of a block, as DW_PARAM_BLOCK describes it (for tests that
// compare it with what the GLSL compiler made of the same declaration).
struct ParamField {
    const char*
        name;  // as in GLSL: the member "radius" is "SsaoParams.radius" in program introspection
    const char* type;    // the GLSL type name: "int", "vec4", ...
    std::size_t offset;  // byte offset in the C++ struct
    int arraySize;       // 0 for a plain field
};

}  // namespace dw::gpu

namespace dw::std140 {

// std140 base alignment (GL 4.5 core, section 7.6.2.2): scalars 4, two
// components 8, three and four components 16, a mat4 (four vec4 columns) 16.
// Types std140 lays out differently from C++ (bool, mat3, double) have none,
// so using them in a block fails to compile.
template <typename T>
constexpr std::size_t alignment() {
    if constexpr (std::is_same_v<T, int> || std::is_same_v<T, float> ||
                  std::is_same_v<T, gpu::uint>)
        return 4;
    else if constexpr (std::is_same_v<T, gpu::vec2> || std::is_same_v<T, gpu::ivec2> ||
                       std::is_same_v<T, gpu::uvec2>)
        return 8;
    else if constexpr (std::is_same_v<T, gpu::vec3> || std::is_same_v<T, gpu::ivec3> ||
                       std::is_same_v<T, gpu::vec4> || std::is_same_v<T, gpu::ivec4> ||
                       std::is_same_v<T, gpu::uvec4> || std::is_same_v<T, gpu::mat4>)
        return 16;
    else
        static_assert(sizeof(T) == 0,
                      "std140 parameter blocks take int, uint, float, [iu]vec2-4 and mat4 fields");
}

// std140 rounds an array element's stride up to 16 bytes; C++ does not, so
// only element types that already are 16 bytes (or a multiple) are allowed.
template <typename T>
constexpr bool arrayElementMatches() {
    return alignment<T>() == 16 && sizeof(T) % 16 == 0;
}

}  // namespace dw::std140

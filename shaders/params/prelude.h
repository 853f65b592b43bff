// Parameter blocks shared by C++ and GLSL (DESIGN.md: "GPU parameters are
// one named std140 struct per pass shared by C++ and GLSL"). A pass's header
// in this folder is included by the pass's .cpp (as
// "shaders/params/NAME.h") and by its shaders (as "../params/NAME.h"), and
// says everything once:
//
//   DW_PARAM_CONST(int, SSAO_MAX_SAMPLES, 64)
//   #define DW_SSAO_PARAMS(FIELD, ARRAY)     (one field a line, each line
//       FIELD(int, sampleCount)                ending in a backslash)
//       ...
//       ARRAY(vec4, kernel, SSAO_MAX_SAMPLES)
//   DW_PARAM_BLOCK(SsaoParams, ssao, DW_SSAO_PARAMS)
//   DW_PARAM_SIZE(SsaoParams, 1056)
//
// In GLSL that is `const int SSAO_MAX_SAMPLES = 64;` and
// `layout(std140, binding = PASS_UBO) uniform SsaoParams { int sampleCount;
// ... vec4 kernel[SSAO_MAX_SAMPLES]; } ssao;`. In C++ it is
// `dw::gpu::SSAO_MAX_SAMPLES` and `struct dw::gpu::SsaoParams` with the same
// fields as glm types, plus compile-time checks that every field sits where
// std140 puts it (renderer/gl/Std140.h) and that the size is the one written
// in DW_PARAM_SIZE, and SsaoParams::fields(), which the GL tests compare with
// the compiled program's own idea of the block.
//
// A block at another binding point than the pass's (the camera's, at
// CAMERA_UBO) is DW_PARAM_BLOCK_AT(Block, instance, CAMERA_UBO, FIELDS);
// DW_PARAM_BLOCK is DW_PARAM_BLOCK_AT(..., PASS_UBO, ...). The binding names
// come from shaders/common/bindings.glsl in both languages, and C++ has the
// block's as Block::kBinding.
//
// Rules: int, uint, float, vecN, ivecN and mat4 fields only (no bool: GLSL's
// is 4 bytes); arrays only of 16-byte types (vec4, ivec4, mat4); put padding
// fields (pad0, pad1, ...) where std140 would leave a gap, and pad the block
// to a multiple of 16 bytes. Comments inside a field list are /* */ (a //
// comment would swallow the line continuation). Enum knob values are not
// written here: the pass passes KnobRegistry::choiceDefines() as defines.
// Values that are no knob's (the sky's kinds, the buffer view's mappings)
// are DW_PARAM_CONSTs in the header.
#ifndef DW_PARAMS_PRELUDE_H
#define DW_PARAMS_PRELUDE_H

#ifdef __cplusplus

// Angle brackets: the GLSL include resolver takes only "quoted" includes, and
// the GLSL preprocessor skips this branch.
#include <cstddef>
#include <renderer/gl/Std140.h>
#include <shaders/common/bindings.glsl>
#include <vector>

#define DW_PARAM_CONST(type, name, value) \
    namespace dw::gpu {                   \
    inline constexpr type name = value;   \
    }

#define DW_PARAM_CPP_FIELD(type, name) type name;
#define DW_PARAM_CPP_ARRAY(type, name, count) type name[count];
#define DW_PARAM_CPP_CHECK_FIELD(type, name)                                            \
    static_assert(offsetof(Self, name) % ::dw::std140::alignment<type>() == 0,          \
                  "std140 puts " #name " at the next multiple of its alignment: add a " \
                  "padding field before it");
#define DW_PARAM_CPP_CHECK_ARRAY(type, name, count)                                                \
    static_assert(::dw::std140::arrayElementMatches<type>(),                                       \
                  "std140 gives array elements a 16-byte stride: make " #name " an array of vec4"); \
    static_assert(offsetof(Self, name) % 16 == 0, "std140 puts the array " #name                     \
                                                  " at a multiple of 16: add a padding field before it");
#define DW_PARAM_CPP_DESCRIBE_FIELD(type, name) ::dw::gpu::ParamField{#name, #type, offsetof(Self, name), 0},
#define DW_PARAM_CPP_DESCRIBE_ARRAY(type, name, count) \
    ::dw::gpu::ParamField{#name, #type, offsetof(Self, name), static_cast<int>(count)},

// The C++ struct's fields, fields() and the std140 checks, for a block or a
// row. Member function bodies see the complete struct, so offsetof works
// there; checkStd140's static_asserts are evaluated when the struct is compiled.
#define DW_PARAM_CPP_MEMBERS(Name, FIELDS)                                             \
    FIELDS(DW_PARAM_CPP_FIELD, DW_PARAM_CPP_ARRAY)                                     \
    static std::vector<ParamField> fields() {                                          \
        using Self = Name;                                                             \
        return {FIELDS(DW_PARAM_CPP_DESCRIBE_FIELD, DW_PARAM_CPP_DESCRIBE_ARRAY)};     \
    }                                                                                  \
    static constexpr void checkStd140() {                                              \
        using Self = Name;                                                             \
        FIELDS(DW_PARAM_CPP_CHECK_FIELD, DW_PARAM_CPP_CHECK_ARRAY)                     \
    }
#define DW_PARAM_CPP_PLAIN(Name)                                                       \
    static_assert(std::is_standard_layout_v<Name>, #Name " must be plain data");       \
    static_assert(sizeof(Name) % 16 == 0, #Name ": pad it to a multiple of 16 bytes");

#define DW_PARAM_BLOCK_AT(Block, instance, bindingPoint, FIELDS) \
    namespace dw::gpu {                                          \
    struct Block {                                               \
        DW_PARAM_CPP_MEMBERS(Block, FIELDS)                      \
        static constexpr const char* kBlockName = #Block;        \
        static constexpr const char* kInstanceName = #instance;  \
        static constexpr unsigned kBinding = ::dw::binding::bindingPoint;       \
    };                                                           \
    DW_PARAM_CPP_PLAIN(Block)                                    \
    }
#define DW_PARAM_BLOCK(Block, instance, FIELDS) DW_PARAM_BLOCK_AT(Block, instance, PASS_UBO, FIELDS)

// A struct that is a row of a std430 storage buffer (the light table): vec4
// and mat4 fields only, where std430 and std140 lay out alike, so the same
// checks hold. GLSL gets `struct Name { ... };` for its buffer's array.
#define DW_PARAM_STRUCT(Name, FIELDS)       \
    namespace dw::gpu {                     \
    struct Name {                           \
        DW_PARAM_CPP_MEMBERS(Name, FIELDS)  \
    };                                      \
    DW_PARAM_CPP_PLAIN(Name)                \
    }

#define DW_PARAM_SIZE(Block, bytes) \
    static_assert(sizeof(::dw::gpu::Block) == (bytes), #Block " is not the size its header says");

#else  // GLSL

#include "../common/bindings.glsl"

#define DW_PARAM_CONST(type, name, value) const type name = value;
#define DW_PARAM_GLSL_FIELD(type, name) type name;
#define DW_PARAM_GLSL_ARRAY(type, name, count) type name[count];
#define DW_PARAM_BLOCK_AT(Block, instance, bindingPoint, FIELDS) \
    layout(std140, binding = bindingPoint) uniform Block { FIELDS(DW_PARAM_GLSL_FIELD, DW_PARAM_GLSL_ARRAY) } instance;
#define DW_PARAM_BLOCK(Block, instance, FIELDS) DW_PARAM_BLOCK_AT(Block, instance, PASS_UBO, FIELDS)
#define DW_PARAM_STRUCT(Name, FIELDS) struct Name { FIELDS(DW_PARAM_GLSL_FIELD, DW_PARAM_GLSL_ARRAY) };
#define DW_PARAM_SIZE(Block, bytes)

#endif
#endif

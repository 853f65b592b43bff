#pragma once
// Checks on a glTF file's container and JSON made before tinygltf reads it, so
// that its problems are named in the file's own terms (glTF 2.0 spec section
// and JSON path) and so that the importer accepts exactly what the scene JSON
// loader accepts for the same quantity:
//  - the GLB header and chunk headers (spec "GLB File Format Specification");
//  - `data:` URIs of buffers and images: a type tinygltf decodes, base64 payload;
//  - perspective cameras: 0 < yfov < 179 degrees, znear a normal float > 0,
//    zfar > znear, aspectRatio > 0 (spec "cameras");
//  - KHR_lights_punctual: known type, color and intensity not negative,
//    range > 0, spots 0 <= innerConeAngle < outerConeAngle <= pi/2.
// Every function throws FileError(path, "<what>: <problem>"); checkGltfValues
// names every object with a problem, not only the first or the last.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dw {

// The JSON chunk of a .glb after checking the 12-byte header (magic "glTF",
// version 2, a length that is the file's size) and every chunk header (JSON
// first, then at most one BIN chunk, each within the file). What breaks the
// spec but still reads (a chunk length that is not a multiple of 4) is added
// to `invalid`, when given, as "GLB: <what>".
std::string_view glbJsonChunk(const std::string& bytes, const std::string& path,
                              std::vector<std::string>* invalid = nullptr);

// The length of a .glb's binary chunk, when it has one; `bytes` has passed glbJsonChunk.
std::optional<std::uint32_t> glbBinLength(const std::string& bytes);

// Where a file's buffers can come from: a GLB's buffer 0 may leave out its
// uri and take the binary chunk (when there is one, of binLength bytes).
struct GltfContainer {
    bool glb = false;
    std::optional<std::uint32_t> binLength;
};

// The value checks above and the schema's (GltfSchema.h) on the parsed glTF
// JSON. Every object's first problem is collected (all bad cameras, lights,
// accessors...) and thrown as one FileError, "<what>; <what>; ..."; rules the
// importer reads past are added to `invalid`, when given.
// `container` says whether a buffer without a uri has bytes (spec "GLB-stored Buffer").
void checkGltfValues(const nlohmann::json& gltf, const std::string& path, std::vector<std::string>* invalid = nullptr,
                     const GltfContainer& container = {});

// Problems ("<json path>: <what>") in the order of their paths, joined with
// "; ", at most 12 shown ("...; and 3 more").
std::string joinProblems(std::vector<std::string> problems);

// Whether `uri` is a data: URI tinygltf decodes; `problem` says why not.
bool isDecodableDataUri(const std::string& uri, std::string& problem);

}  // namespace dw

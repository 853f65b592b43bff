#pragma once
// What the glTF 2.0 JSON schema demands of a file's objects (spec section 5,
// "Properties Reference"), checked on the parsed JSON before tinygltf reads
// it. tinygltf 2.7 refuses some of these without a word (a skin without
// `joints`), drops others silently (a texture reference without `index`, a
// primitive without `attributes`) and wraps integers beyond an int; here each
// one is named by the object's JSON path:
//  - the top-level arrays are arrays of objects, `asset.version` is a string;
//  - required properties: accessors (componentType, count, type, sparse's
//    count / indices / values), buffers (byteLength), bufferViews (buffer,
//    byteLength), cameras (type and its perspective or orthographic values),
//    meshes (primitives, each with attributes), skins (joints), animations
//    (channels, samplers), texture references (index), images (uri or
//    bufferView);
//  - integer properties (offsets, lengths, counts, indices of other objects,
//    enums) are integers in their range: not negative, not fractional,
//    within what the reader stores (an index fits an int; a size 2^53 - 1),
//    and enums one of their values.
// A break that the importer reads past (a sampler or buffer view enum it
// replaces by the default, an image without its mimeType, a node with both
// a matrix and TRS) is added to `invalid` instead, for the "invalid glTF (drawn
// anyway)" warning.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dw {

// Adds "<json path>: <problem>" to `problems` for every break of the rules
// above that stops the file from being read as written, and to `invalid`
// for those it can be read past.
void checkGltfSchema(const nlohmann::json& gltf, std::vector<std::string>& problems, std::vector<std::string>& invalid);

// For JsonGuardOptions::integerProblem: what is wrong with `number` (its text)
// at `path` when that is one of glTF's integer properties, else empty.
std::string gltfIntegerProblem(const std::string& path, double value, const std::string& number);

}  // namespace dw

#pragma once
// Reads a glTF accessor's elements as doubles (glTF 2.0 spec 3.6
// "Accessors": 3.6.2 component types, normalised integers, byte strides;
// 3.6.2.3 accessors without a bufferView, which hold zeros, and sparse
// accessors, whose values replace those; KHR_mesh_quantization's component
// types). `check` is the range check `read` relies on: the accessor's bytes,
// and its sparse indices and values, lie inside their buffer views.
#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace dw {

class GltfAccessorReader {
public:
    // `model` and `path` (the file, for messages) outlive the reader.
    GltfAccessorReader(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

    // Throws FileError naming accessor[index] when its component type or type
    // is invalid, its count implausibly large or its bytes outside its views.
    void check(int index) const;

    // The accessor's count * wantComponents values (an error when it has another
    // number of components). Non-finite values are an error unless
    // `allowNonFinite` (normals and tangents, which the caller repairs).
    std::vector<double> read(int index, int wantComponents, const std::string& what, bool allowNonFinite = false) const;

    // Component c of the element at p, normalised to [0, 1] or [-1, 1] when `normalized`.
    static double readComponent(const unsigned char* p, int c, int type, bool normalized);

private:
    [[noreturn]] void fail(const std::string& what) const;

    const tinygltf::Model& model_;
    const std::string& path_;
};

}  // namespace dw

#pragma once
// Checks on the model tinygltf built from a file, before anything indexes it
// (glTF 2.0 spec 3.5-3.8, "Concepts": "indices ... MUST" be in range, buffer
// views inside their buffers, accessors inside their views, nodes a forest),
// the spec rules a file breaks where the importer reads past them ("Skins",
// "Morph Targets"), and the valid features the workbench does not draw.
// GltfSchema.h checks the JSON before tinygltf reads it; this, what tinygltf made.
#include <tiny_gltf.h>

#include <string>
#include <vector>

#include "renderer/Error.h"

namespace dw {

// Throws FileError(path, "<what> refers to index i but there are only n") when
// `index` is not an element of `v` (-1, absent, is allowed when `optional`).
template <typename T>
void checkGltfIndex(int index, const std::vector<T>& v, const std::string& path, const std::string& what,
                    bool optional = true) {
    if (index < 0 && optional) return;
    if (index < 0 || static_cast<size_t>(index) >= v.size())
        throw FileError(path, what + " refers to index " + std::to_string(index) + " but there are only " +
                                  std::to_string(v.size()));
}

class GltfModelCheck {
public:
    GltfModelCheck(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

    // Every index later code follows, every byte range it reads, finite node
    // transforms, the node graph: one FileError naming every bad object.
    void validate() const;

    // Appends "<json path>: <rule broken> (spec: ...)" for the rules the file
    // breaks that do not stop it from drawing.
    void noteInvalid(std::vector<std::string>& invalid) const;

    // What the file uses that the workbench does not draw (a KHR_lights_punctual range, an extension, ...).
    std::vector<std::string> ignoredFeatures(bool ignoredUvSets) const;

    static bool isSupportedExtension(const std::string& ext);

private:
    template <typename F>
    void collect(std::vector<std::string>& problems, F check) const;
    void checkNodeGraph() const;
    [[noreturn]] void fail(const std::string& what) const { throw FileError(path_, what); }
    template <typename T>
    void checkIndex(int index, const std::vector<T>& v, const std::string& what, bool optional = true) const {
        checkGltfIndex(index, v, path_, what, optional);
    }

    const tinygltf::Model& model_;
    const std::string& path_;
};

}  // namespace dw

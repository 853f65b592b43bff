#pragma once
// The images, textures and materials of a glTF file (glTF 2.0 spec 3.8
// "Materials", 3.9 "Textures, Images, and Samplers"; KHR_texture_transform,
// KHR_materials_pbrSpecularGlossiness, KHR_materials_specular,
// KHR_materials_emissive_strength, EXT_texture_webp) added to a Scene:
// images decoded by OpenImageIO through tinygltf's image-loader hook (an
// image's buffer view range-checked before anything reads it), materials
// mapped to the workbench's Material with each texture's sampler, UV set
// and transform.
#include <tiny_gltf.h>

#include <map>
#include <string>
#include <vector>

#include "renderer/scene/Scene.h"

namespace dw {

class GltfMaterialImporter {
public:
    // `model`, `path` (the file) and `scene` outlive the importer.
    GltfMaterialImporter(tinygltf::Model& model, const std::string& path, Scene& scene)
        : model_(model), path_(path), scene_(scene) {}

    // tinygltf's image-loader hook (TinyGLTF::SetImageLoader, user data: the
    // importer): checks the bytes' range, decodes them to RGBA8.
    static bool decodeImageCallback(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
                                    int, int, const unsigned char* bytes, int size, void* user);
    // tinygltf's file reader (FsCallbacks::ReadWholeFile, user data: the
    // importer) for a buffer's or an image's external URI: the workbench's
    // bounded reader of regular files (renderer/io/TextFile.h), so a URI
    // naming a device (/dev/zero), a folder or a pipe is refused by name
    // rather than read forever, and what went wrong is kept for the image's message.
    static bool readExternalFileCallback(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                                         void* user);
    // The first image that failed, "image[i]: ..."; empty when none.
    const std::string& imageError() const { return imageError_; }

    // Moves the decoded images into the scene (data: URIs tinygltf leaves, webp, are decoded here).
    void importImages();
    // Adds every material (after importImages: textures refer to the scene's images).
    void importMaterials();
    // The scene's material for a primitive's `material` (-1: the glTF default material).
    int sceneMaterial(int gltfMaterial);
    // Whether a texture asked for a UV set beyond TEXCOORD_1 (TEXCOORD_0 was used).
    bool ignoredUvSets() const { return ignoredUvSets_; }

    // EXT_texture_webp's source, or -1.
    static int webpSource(const tinygltf::Texture& t);

private:
    std::string imageRangeProblem(const tinygltf::Image& image) const;
    void decodeDataUri(int index, tinygltf::Image& img);
    int imageOfTexture(int textureIndex) const;
    TextureMapping mappingOf(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions) const;
    int textureOf(const tinygltf::Value& obj, const char* key, TextureMapping& mapping) const;
    void applyMaterialExtensions(const tinygltf::Material& m, Material& out) const;
    int defaultMaterial();
    [[noreturn]] void fail(const std::string& what) const;

    tinygltf::Model& model_;
    const std::string& path_;
    Scene& scene_;
    std::string imageError_;
    // Why an external file could not be read, by its path as tinygltf joined it.
    std::map<std::string, std::string> externalFileErrors_;
    int imageBase_ = 0, materialBase_ = 0, defaultMaterial_ = -1;
    mutable bool ignoredUvSets_ = false;
};

}  // namespace dw

#include "renderer/scene/GltfMaterials.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/io/TextFile.h"
#include "renderer/scene/GltfModelCheck.h"

// tinygltf's base64 decoder: exported by Debian's libtinygltf, but declared
// only in tiny_gltf.h's implementation section.
namespace tinygltf {
std::string base64_decode(std::string const& encoded);
}  // namespace tinygltf

namespace dw {

namespace fs = std::filesystem;

namespace {

// glTF sampler wrap modes (the GL enums).
constexpr int kRepeat = 10497, kClampToEdge = 33071, kMirroredRepeat = 33648;

glm::vec3 vec3Of(const std::vector<double>& v, glm::vec3 fallback) {
    return v.size() >= 3 ? glm::vec3(v[0], v[1], v[2]) : fallback;
}

double number(const tinygltf::Value& obj, const char* key, double fallback) {
    if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsNumber()) return fallback;
    return obj.Get(key).GetNumberAsDouble();
}

glm::vec4 vector(const tinygltf::Value& obj, const char* key, glm::vec4 fallback, int n) {
    if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsArray()) return fallback;
    const auto& a = obj.Get(key);
    glm::vec4 v = fallback;
    for (int i = 0; i < n && i < static_cast<int>(a.ArrayLen()); ++i)
        if (a.Get(i).IsNumber()) v[i] = static_cast<float>(a.Get(i).GetNumberAsDouble());
    return v;
}

}  // namespace

void GltfMaterialImporter::fail(const std::string& what) const { throw FileError(path_, what); }

bool GltfMaterialImporter::readExternalFileCallback(std::vector<unsigned char>* out, std::string* err,
                                                    const std::string& path, void* user) {
    auto* self = static_cast<GltfMaterialImporter*>(user);
    try {
        // A regular file only: a pipe with a writer that never ends would be waited on, and one
        // without a writer reads as empty ("missing texture" for a file that is there).
        requireRegularFile(path, "file not found", "cannot read file");
        const std::string bytes = readWholeFile(path, "file not found", "cannot read file", kBinaryFileLimit);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const std::exception& e) {
        // FileError's text starts with the path.
        self->externalFileErrors_[fs::path(path).lexically_normal().string()] = e.what();
        if (err) *err += e.what();
        return false;
    }
}

bool GltfMaterialImporter::decodeImageCallback(tinygltf::Image* image, const int index, std::string* err,
                                               std::string* /*warn*/, int, int, const unsigned char* bytes,
                                               int size, void* user) {
    auto* self = static_cast<GltfMaterialImporter*>(user);
    const std::string name = image->uri.empty() ? "image[" + std::to_string(index) + "]"
                                                : "image[" + std::to_string(index) + "] '" + image->uri + "'";
    // tinygltf passes a bufferView's bytes without checking them against
    // the buffer: check the range before anything reads it.
    if (image->bufferView >= 0) {
        const std::string range = self->imageRangeProblem(*image);
        if (!range.empty()) {
            self->imageError_ = name + ": " + range;
            if (err) *err += self->imageError_;
            return false;
        }
    }
    try {
        Image decoded = decodeImage8(bytes, static_cast<size_t>(std::max(size, 0)), name, image->mimeType);
        image->width = decoded.width;
        image->height = decoded.height;
        image->component = 4;
        image->bits = 8;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        image->image = std::move(decoded.rgba);
        return true;
    } catch (const std::exception& e) {
        // FileError's text already starts with the image name.
        self->imageError_ = std::string("cannot decode ") + e.what();
        if (err) *err += self->imageError_;
        return false;
    }
}

// Empty when image.bufferView's bytes lie inside its buffer (tinygltf has
// parsed buffers and bufferViews into model_ before images).
std::string GltfMaterialImporter::imageRangeProblem(const tinygltf::Image& image) const {
    const size_t view = static_cast<size_t>(image.bufferView);
    if (view >= model_.bufferViews.size()) return "bufferView " + std::to_string(view) + " does not exist";
    const auto& bv = model_.bufferViews[view];
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model_.buffers.size())
        return "bufferView[" + std::to_string(view) + "] refers to a buffer that does not exist";
    const size_t size = model_.buffers[bv.buffer].data.size();
    if (bv.byteOffset > size || bv.byteLength > size - bv.byteOffset)
        return "bufferView[" + std::to_string(view) + "] (bytes " + std::to_string(bv.byteOffset) + " to " +
               std::to_string(bv.byteOffset + bv.byteLength) + ") runs past the end of buffer[" +
               std::to_string(bv.buffer) + "] (" + std::to_string(size) + " bytes)";
    if (bv.byteLength > static_cast<size_t>(std::numeric_limits<int>::max()))
        return "bufferView[" + std::to_string(view) + "] is larger than 2 GiB";
    return {};
}

void GltfMaterialImporter::importImages() {
    imageBase_ = static_cast<int>(scene_.images.size());
    for (size_t i = 0; i < model_.images.size(); ++i) {
        auto& img = model_.images[i];
        // tinygltf 2.7 decodes only the data: URIs of the media types it
        // lists (PNG, JPEG, BMP, GIF); any other (image/webp for
        // EXT_texture_webp) is decoded here, through the same decoder.
        if (img.image.empty() && img.uri.rfind("data:", 0) == 0) decodeDataUri(static_cast<int>(i), img);
        if (img.image.empty() || img.width <= 0 || img.height <= 0) {
            if (!img.uri.empty() && img.uri.rfind("data:", 0) != 0) {
                const fs::path full = fs::path(path_).parent_path() / img.uri;
                const auto unread = externalFileErrors_.find(full.lexically_normal().string());
                if (unread != externalFileErrors_.end())
                    fail("image[" + std::to_string(i) + "] '" + img.uri + "' cannot be read: " + unread->second);
                fail("missing texture: image[" + std::to_string(i) + "] '" + img.uri + "' (looked for " +
                     full.string() + ")");
            }
            fail("image[" + std::to_string(i) + "] has no decodable data");
        }
        if (img.image.size() < static_cast<size_t>(img.width) * img.height * 4)
            fail("image[" + std::to_string(i) + "] has fewer pixels than its size says");
        Image out;
        out.width = img.width;
        out.height = img.height;
        out.rgba = std::move(img.image);
        out.source = path_ + "#" + (img.uri.empty() ? "image" + std::to_string(i) : img.uri);
        scene_.addImage(std::move(out));
    }
}

void GltfMaterialImporter::decodeDataUri(int index, tinygltf::Image& img) {
    const std::string& uri = img.uri;
    const size_t comma = uri.find(',');
    const std::string header = uri.substr(0, comma);
    if (comma == std::string::npos || header.size() < 12 || header.compare(header.size() - 7, 7, ";base64") != 0)
        fail("image[" + std::to_string(index) + "]: a data: URI must be 'data:<media type>;base64,<data>'");
    const std::string bytes = tinygltf::base64_decode(uri.substr(comma + 1));
    if (img.mimeType.empty()) img.mimeType = header.substr(5, header.size() - 12);
    decodeImageCallback(&img, index, nullptr, nullptr, 0, 0, reinterpret_cast<const unsigned char*>(bytes.data()),
                        static_cast<int>(bytes.size()), this);
    if (!imageError_.empty()) fail(imageError_);
}

int GltfMaterialImporter::webpSource(const tinygltf::Texture& t) {
    auto it = t.extensions.find("EXT_texture_webp");
    if (it == t.extensions.end() || !it->second.Has("source") || !it->second.Get("source").IsNumber()) return -1;
    return it->second.Get("source").GetNumberAsInt();
}

// The image a texture shows: EXT_texture_webp's when there is one (the
// extension's rule: prefer it when supported), else `source`.
int GltfMaterialImporter::imageOfTexture(int textureIndex) const {
    if (textureIndex < 0) return -1;
    const int webp = webpSource(model_.textures[textureIndex]);
    const int src = webp >= 0 ? webp : model_.textures[textureIndex].source;
    return src < 0 ? -1 : imageBase_ + src;
}

// A textureInfo's UV set, its texture's sampler and KHR_texture_transform.
TextureMapping GltfMaterialImporter::mappingOf(int textureIndex, int texCoord,
                                               const tinygltf::ExtensionMap& extensions) const {
    TextureMapping out;
    out.texCoord = texCoord;
    if (textureIndex >= 0 && model_.textures[textureIndex].sampler >= 0) {
        const auto& smp = model_.samplers[model_.textures[textureIndex].sampler];
        // Values outside the glTF enums fall back to the defaults.
        auto wrap = [](int w, unsigned fallback) {
            return w == kRepeat || w == kClampToEdge || w == kMirroredRepeat ? static_cast<unsigned>(w) : fallback;
        };
        out.wrapS = wrap(smp.wrapS, out.wrapS);
        out.wrapT = wrap(smp.wrapT, out.wrapT);
        if (smp.magFilter == 9728 || smp.magFilter == 9729) out.magFilter = static_cast<unsigned>(smp.magFilter);
        if (smp.minFilter == 9728 || smp.minFilter == 9729 || (smp.minFilter >= 9984 && smp.minFilter <= 9987))
            out.minFilter = static_cast<unsigned>(smp.minFilter);
    }
    auto it = extensions.find("KHR_texture_transform");
    if (it != extensions.end()) {
        const auto& e = it->second;
        const glm::vec4 offset = vector(e, "offset", glm::vec4(0.0f), 2);
        const glm::vec4 scale = vector(e, "scale", glm::vec4(1.0f), 2);
        out.offset = glm::vec2(offset);
        out.scale = glm::vec2(scale);
        out.rotation = static_cast<float>(number(e, "rotation", 0.0));
        if (e.Has("texCoord") && e.Get("texCoord").IsNumber()) out.texCoord = e.Get("texCoord").GetNumberAsInt();
    }
    if (out.texCoord != 0 && out.texCoord != 1) {
        ignoredUvSets_ = true;
        out.texCoord = 0;
    }
    return out;
}

void GltfMaterialImporter::importMaterials() {
    materialBase_ = static_cast<int>(scene_.materials.size());
    for (const auto& m : model_.materials) {
        Material out;
        out.name = m.name;
        out.model = MaterialModel::MetallicRoughness;
        const auto& pbr = m.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            out.baseColor = glm::clamp(glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                                 pbr.baseColorFactor[2], pbr.baseColorFactor[3]),
                                       0.0f, 1.0f);  // the spec's range; a value outside it is named (GltfModelCheck)
        else
            out.baseColor = glm::vec4(1.0f);
        out.baseColorTexture = imageOfTexture(pbr.baseColorTexture.index);
        out.metallic = static_cast<float>(pbr.metallicFactor);
        out.roughness = static_cast<float>(pbr.roughnessFactor);
        out.metallicRoughnessTexture = imageOfTexture(pbr.metallicRoughnessTexture.index);
        out.specularColor = glm::vec3(0.04f);
        out.normalTexture = imageOfTexture(m.normalTexture.index);
        out.normalScale = static_cast<float>(m.normalTexture.scale);
        out.emissive = vec3Of(m.emissiveFactor, glm::vec3(0.0f));
        out.emissiveTexture = imageOfTexture(m.emissiveTexture.index);
        out.alphaMode = m.alphaMode == "MASK"    ? AlphaMode::Mask
                        : m.alphaMode == "BLEND" ? AlphaMode::Blend
                                                 : AlphaMode::Opaque;
        out.alphaCutoff = static_cast<float>(m.alphaCutoff);
        out.doubleSided = m.doubleSided;
        out.occlusionTexture = imageOfTexture(m.occlusionTexture.index);
        out.occlusionStrength = static_cast<float>(m.occlusionTexture.strength);
        out.mapping[Material::BaseColorSlot] =
            mappingOf(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, pbr.baseColorTexture.extensions);
        out.mapping[Material::NormalSlot] =
            mappingOf(m.normalTexture.index, m.normalTexture.texCoord, m.normalTexture.extensions);
        out.mapping[Material::SpecularSlot] = mappingOf(pbr.metallicRoughnessTexture.index,
                                                        pbr.metallicRoughnessTexture.texCoord,
                                                        pbr.metallicRoughnessTexture.extensions);
        out.mapping[Material::EmissiveSlot] =
            mappingOf(m.emissiveTexture.index, m.emissiveTexture.texCoord, m.emissiveTexture.extensions);
        out.mapping[Material::OcclusionSlot] =
            mappingOf(m.occlusionTexture.index, m.occlusionTexture.texCoord, m.occlusionTexture.extensions);
        applyMaterialExtensions(m, out);
        scene_.addMaterial(std::move(out));
    }
}

// A textureInfo inside a material extension: its image, and its sampling into `mapping`.
int GltfMaterialImporter::textureOf(const tinygltf::Value& obj, const char* key, TextureMapping& mapping) const {
    if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsObject()) return -1;
    const auto& t = obj.Get(key);
    if (!t.Has("index") || !t.Get("index").IsNumber()) return -1;
    const int idx = t.Get("index").GetNumberAsInt();
    checkGltfIndex(idx, model_.textures, path_, std::string("material extension texture ") + key);
    const int texCoord = t.Has("texCoord") && t.Get("texCoord").IsNumber() ? t.Get("texCoord").GetNumberAsInt() : 0;
    tinygltf::ExtensionMap ext;
    if (t.Has("extensions") && t.Get("extensions").IsObject() && t.Get("extensions").Has("KHR_texture_transform"))
        ext["KHR_texture_transform"] = t.Get("extensions").Get("KHR_texture_transform");
    mapping = mappingOf(idx, texCoord, ext);
    return imageOfTexture(idx);
}

void GltfMaterialImporter::applyMaterialExtensions(const tinygltf::Material& m, Material& out) const {
    auto it = m.extensions.find("KHR_materials_pbrSpecularGlossiness");
    if (it != m.extensions.end()) {
        const auto& e = it->second;
        out.model = MaterialModel::SpecularGlossiness;
        out.baseColor = vector(e, "diffuseFactor", glm::vec4(1.0f), 4);
        out.baseColorTexture = textureOf(e, "diffuseTexture", out.mapping[Material::BaseColorSlot]);
        out.specularColor = glm::vec3(vector(e, "specularFactor", glm::vec4(1.0f), 3));
        out.glossiness = static_cast<float>(number(e, "glossinessFactor", 1.0));
        out.specularTexture = textureOf(e, "specularGlossinessTexture", out.mapping[Material::SpecularSlot]);
    }
    it = m.extensions.find("KHR_materials_specular");
    if (it != m.extensions.end() && out.model == MaterialModel::MetallicRoughness) {
        // Dielectric F0 = min(0.04 * specularColorFactor, 1) * specularFactor.
        const auto& e = it->second;
        const float factor = static_cast<float>(number(e, "specularFactor", 1.0));
        const glm::vec3 color(vector(e, "specularColorFactor", glm::vec4(1.0f), 3));
        out.specularColor = glm::min(glm::vec3(0.04f) * color, glm::vec3(1.0f)) * factor;
    }
    it = m.extensions.find("KHR_materials_emissive_strength");
    if (it != m.extensions.end()) out.emissive *= static_cast<float>(number(it->second, "emissiveStrength", 1.0));
}

int GltfMaterialImporter::sceneMaterial(int gltfMaterial) {
    return gltfMaterial >= 0 ? materialBase_ + gltfMaterial : defaultMaterial();
}

int GltfMaterialImporter::defaultMaterial() {
    if (defaultMaterial_ < 0) {
        Material m;
        m.name = "glTF default";
        m.model = MaterialModel::MetallicRoughness;
        m.baseColor = glm::vec4(1.0f);
        defaultMaterial_ = scene_.addMaterial(m);
    }
    return defaultMaterial_;
}

}  // namespace dw

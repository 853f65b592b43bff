#include "renderer/reference/ReferenceCache.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <type_traits>
#include <unistd.h>

#include "renderer/io/JsonGuard.h"

namespace dw::reference {

namespace {

// FNV-1a, 64 bits, over the values' bytes (fields one by one: no padding).
class Hasher {
public:
    void bytes(const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 0x100000001B3ull;
    }
    template <typename T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof(T));
    }
    void text(const std::string& s) {
        value(s.size());
        bytes(s.data(), s.size());
    }
    template <typename T>
    void array(const std::vector<T>& v) {
        value(v.size());
        if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
    }
    std::uint64_t digest() const { return h_; }

private:
    std::uint64_t h_ = 0xCBF29CE484222325ull;
};

void hashVertices(Hasher& h, const std::vector<Vertex>& vs) {
    h.value(vs.size());
    for (const Vertex& v : vs) {
        h.value(v.position);
        h.value(v.normal);
        h.value(v.tangent);
        h.value(v.uv);
        h.value(v.color);
        h.value(v.uv1);
    }
}

void hashMaterial(Hasher& h, const Material& m) {
    h.value(static_cast<int>(m.model));
    h.value(m.baseColor);
    h.value(m.baseColorTexture);
    h.value(m.specularColor);
    h.value(m.specularExponent);
    h.value(m.glossiness);
    h.value(m.specularTexture);
    h.value(m.metallic);
    h.value(m.roughness);
    h.value(m.metallicRoughnessTexture);
    h.value(m.normalTexture);
    h.value(m.normalScale);
    h.value(m.emissive);
    h.value(m.emissiveTexture);
    h.value(static_cast<int>(m.alphaMode));
    h.value(m.alphaCutoff);
    h.value(m.doubleSided);
    h.value(m.occlusionTexture);
    h.value(m.occlusionStrength);
    for (const TextureMapping& t : m.mapping) {
        h.value(t.texCoord);
        h.value(t.wrapS);
        h.value(t.wrapT);
        h.value(t.minFilter);
        h.value(t.magFilter);
        h.value(t.offset);
        h.value(t.rotation);
        h.value(t.scale);
    }
}

void hashLight(Hasher& h, const Light& l) {
    h.value(static_cast<int>(l.type));
    h.value(l.position);
    h.value(l.direction);
    h.value(l.cutoffDegrees);
    h.value(l.exponent);
    h.value(static_cast<int>(l.falloff));
    h.value(l.innerConeDegrees);
    h.value(l.intensity);
    h.value(l.attenuation.constant);
    h.value(l.attenuation.linear);
    h.value(l.attenuation.quadratic);
    h.value(l.castShadows);
    h.value(l.enabled);
}

void hashFloatImage(Hasher& h, const FloatImage& img) {
    h.value(img.width);
    h.value(img.height);
    h.value(img.channels);
    h.array(img.pixels);
}

std::string hex(std::uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

nlohmann::json statsJson(const ReferenceStatistics& s) {
    return {{"seconds", s.seconds},
            {"build_seconds", s.buildSeconds},
            {"threads", s.threads},
            {"primary_rays", s.primaryRays},
            {"shadow_rays", s.shadowRays},
            {"ao_rays", s.aoRays},
            {"blended_hits", s.blendedHits},
            {"ao_standard_error_mean", s.aoStandardErrorMean},
            {"ao_standard_error_max", s.aoStandardErrorMax},
            {"triangles", s.triangles},
            {"pixel_samples", s.pixelSamples},
            {"spp_error_mean", s.sppErrorMean},
            {"spp_error_max", s.sppErrorMax}};
}

// What a RayScene is built from and its queries read: meshes, instances, materials, images.
void hashGeometry(Hasher& h, const Scene& scene) {
    h.value(scene.meshes.size());
    for (const Mesh& m : scene.meshes) {
        hashVertices(h, m.vertices);
        h.array(m.indices);
        h.value(m.material);
    }
    h.value(scene.instances.size());
    for (const MeshInstance& i : scene.instances) {
        h.value(i.mesh);
        h.value(i.transform);
    }
    h.value(scene.materials.size());
    for (const Material& m : scene.materials) hashMaterial(h, m);
    h.value(scene.images.size());
    for (const Image& img : scene.images) {
        h.value(img.width);
        h.value(img.height);
        h.array(img.rgba);
    }
}

}  // namespace

std::string sceneGeometryKey(const Scene& scene) {
    Hasher h;
    hashGeometry(h, scene);
    return hex(h.digest());
}

std::string referenceKey(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request) {
    Hasher h;
    h.value(kReferenceVersion);
    hashGeometry(h, scene);
    h.value(scene.lights.size());
    for (const Light& l : scene.lights) hashLight(h, l);
    h.value(scene.ambient);
    h.value(scene.background);
    const Sky& s = scene.sky;
    h.value(static_cast<int>(s.kind));
    h.value(s.zenith);
    h.value(s.horizon);
    h.value(s.ground);
    h.value(s.sunSizeDegrees);
    h.value(s.intensity);
    h.value(s.rotationDegrees);
    hashFloatImage(h, s.equirect);
    h.value(s.cubeFaces.size());
    for (const FloatImage& f : s.cubeFaces) hashFloatImage(h, f);
    const Camera& c = request.camera;
    h.value(c.position);
    h.value(c.target);
    h.value(c.up);
    h.value(c.fovYDegrees);
    h.value(c.nearPlane);
    h.value(c.farPlane);
    h.value(request.width);
    h.value(request.height);
    h.text(model.canonical());
    return hex(h.digest());
}

std::filesystem::path ReferenceCache::defaultDirectory() {
    if (const char* d = std::getenv("DW_REFERENCE_CACHE"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
        return std::filesystem::path(x) / "deferred-workbench" / "reference";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "deferred-workbench" / "reference";
    return std::filesystem::temp_directory_path() / "deferred-workbench-reference";
}

ReferenceCache::ReferenceCache(std::filesystem::path directory)
    : directory_(directory.empty() ? defaultDirectory() : std::move(directory)) {}

std::optional<ReferenceImages> ReferenceCache::load(const std::string& key) const {
    namespace fs = std::filesystem;
    const fs::path stats = directory_ / (key + ".json");
    std::error_code ec;
    if (!fs::exists(stats, ec)) return std::nullopt;
    try {
        ReferenceImages r;
        const nlohmann::json j = readJsonFile(stats.string());
        const auto& s = j.at("stats");
        r.stats.seconds = s.at("seconds").get<double>();
        r.stats.buildSeconds = s.at("build_seconds").get<double>();
        r.stats.threads = s.at("threads").get<int>();
        r.stats.primaryRays = s.at("primary_rays").get<long long>();
        r.stats.shadowRays = s.at("shadow_rays").get<long long>();
        r.stats.aoRays = s.at("ao_rays").get<long long>();
        r.stats.blendedHits = s.value("blended_hits", 0LL);
        r.stats.aoStandardErrorMean = s.at("ao_standard_error_mean").get<double>();
        r.stats.aoStandardErrorMax = s.at("ao_standard_error_max").get<double>();
        r.stats.triangles = s.at("triangles").get<size_t>();
        r.stats.pixelSamples = s.at("pixel_samples").get<int>();
        r.stats.sppErrorMean = s.at("spp_error_mean").get<double>();
        r.stats.sppErrorMax = s.at("spp_error_max").get<double>();
        r.lbuffer = loadImageFloat((directory_ / (key + ".lbuffer.exr")).string());
        r.final = loadImageFloat((directory_ / (key + ".final.exr")).string());
        r.ao = loadImageFloat((directory_ / (key + ".ao.exr")).string());
        r.shadow = loadImageFloat((directory_ / (key + ".shadow.exr")).string());
        r.sppError = loadImageFloat((directory_ / (key + ".spp_error.exr")).string());
        const FloatImage bg = loadImageFloat((directory_ / (key + ".background.exr")).string());
        r.background.resize(bg.pixels.size());
        for (size_t i = 0; i < bg.pixels.size(); ++i) r.background[i] = bg.pixels[i] != 0.0f ? 1 : 0;
        if (r.lbuffer.width != r.final.width || r.lbuffer.height != r.final.height ||
            r.sppError.width != r.lbuffer.width || r.sppError.height != r.lbuffer.height ||
            r.background.size() != static_cast<size_t>(r.lbuffer.width) * r.lbuffer.height)
            return std::nullopt;
        return r;
    } catch (const std::exception&) {
        return std::nullopt;  // a damaged entry is rendered again
    }
}

void ReferenceCache::store(const std::string& key, const ReferenceImages& images) const {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(directory_, ec);
    if (ec) throw FileError(directory_.string(), "cannot create the reference cache directory: " + ec.message());
    const std::string tmp = ".tmp" + std::to_string(::getpid());
    std::vector<std::pair<fs::path, fs::path>> renames;
    auto write = [&](const std::string& name, const FloatImage& img) {
        const fs::path final = directory_ / (key + "." + name + ".exr");
        const fs::path temp = directory_ / (key + "." + name + tmp + ".exr");
        writeImage(temp.string(), img);
        renames.emplace_back(temp, final);
    };
    write("lbuffer", images.lbuffer);
    write("final", images.final);
    write("ao", images.ao);
    write("shadow", images.shadow);
    write("spp_error", images.sppError);
    FloatImage bg;
    bg.width = images.lbuffer.width;
    bg.height = images.lbuffer.height;
    bg.channels = 1;
    bg.pixels.assign(images.background.begin(), images.background.end());
    write("background", bg);
    const fs::path statsFinal = directory_ / (key + ".json");
    const fs::path statsTemp = directory_ / (key + tmp + ".json");
    {
        std::ofstream f(statsTemp);
        f << nlohmann::json{{"key", key}, {"version", kReferenceVersion}, {"stats", statsJson(images.stats)}}.dump(2);
        if (!f) throw FileError(statsTemp.string(), "cannot write the reference cache entry");
    }
    // The images first, the statistics last: an entry exists once its JSON does.
    for (const auto& [from, to] : renames) {
        fs::rename(from, to, ec);
        if (ec) throw FileError(to.string(), "cannot write the reference cache entry: " + ec.message());
    }
    fs::rename(statsTemp, statsFinal, ec);
    if (ec) throw FileError(statsFinal.string(), "cannot write the reference cache entry: " + ec.message());
}

}  // namespace dw::reference

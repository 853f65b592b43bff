#include "app/ExperimentRecord.h"

#include <openssl/evp.h>
#include <sys/utsname.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "app/HostInfo.h"
#include "renderer/Error.h"
#include "renderer/inspect/OutputReadback.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"

namespace dw {

namespace {

using Json = nlohmann::ordered_json;

Json fieldsJson(const RecordFields& fields) {
    Json j = Json::object();
    for (const auto& [k, v] : fields) j[k] = v;
    return j;
}

RecordFields fieldsOf(const nlohmann::json& j) {
    RecordFields f;
    if (!j.is_object()) return f;
    for (auto it = j.begin(); it != j.end(); ++it)
        f.emplace_back(it.key(), it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
    return f;
}

Json vec3(const glm::vec3& v) { return Json::array({v.x, v.y, v.z}); }

glm::vec3 readVec3(const nlohmann::json& j, const std::string& path, const char* field) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
        throw FileError(path, std::string("camera.") + field + ": expected [x, y, z]");
    return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

}  // namespace

std::string ExperimentRecord::sha256(const void* data, size_t size) {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (!EVP_Digest(data, size, digest, &length, EVP_sha256(), nullptr)) throw Error("sha256 failed");
    std::string hex;
    char byte[3];
    for (unsigned int i = 0; i < length; ++i) {
        std::snprintf(byte, sizeof(byte), "%02x", digest[i]);
        hex += byte;
    }
    return hex;
}

std::string ExperimentRecord::sha256OfFile(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return "";
    const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    return sha256(bytes.data(), bytes.size());
}

std::vector<RecordedFile> ExperimentRecord::hashSceneFiles(const Scene& scene) {
    std::vector<std::string> paths;
    if (scene.source.rfind("builtin:", 0) != 0) paths.push_back(scene.source);
    if (!scene.sky.environmentSource.empty()) paths.push_back(scene.sky.environmentSource);
    for (const Image& image : scene.images) paths.push_back(image.source);
    std::vector<RecordedFile> files;
    std::set<std::string> seen;
    for (const std::string& p : paths) {
        std::error_code ec;
        if (p.empty() || !std::filesystem::is_regular_file(p, ec) || !seen.insert(p).second) continue;
        files.push_back({p, sha256OfFile(p)});
    }
    return files;
}

std::string ExperimentRecord::hashBuffer(RenderSession& session, const std::string& buffer, int& width, int& height,
                                         int& channels) {
    const PublishedOutput* o = session.pipeline().outputs().find(buffer);
    if (!o) throw Error("unknown buffer '" + buffer + "'");
    const FloatImage image = session.readRaw(buffer);
    width = image.width;
    height = image.height;
    channels = image.channels;
    if (!isDisplayReady(*o)) return sha256(image.pixels.data(), image.pixels.size() * sizeof(float));
    // The 8-bit values a .png of it holds (ImageIO's conversion).
    std::vector<std::uint8_t> bytes(image.pixels.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
        const float v = image.pixels[i];
        bytes[i] = static_cast<std::uint8_t>((std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f) * 255.0f + 0.5f);
    }
    return sha256(bytes.data(), bytes.size());
}

RecordFields ExperimentRecord::buildFields() {
    RecordFields f;
    f.emplace_back("version", DW_VERSION);
#ifdef DW_GIT_COMMIT
    f.emplace_back("commit", DW_GIT_COMMIT);
#else
    f.emplace_back("commit", "unknown");
#endif
    f.emplace_back("compiler", compilerName());
#ifdef DW_BUILD_TYPE
    f.emplace_back("build_type", DW_BUILD_TYPE);
#endif
    return f;
}

ExperimentRecord ExperimentRecord::capture(RenderSession& session, const RunConfig& run, const std::string& buffer,
                                           std::uint64_t firstCounted, const std::string& glPlatform) {
    ExperimentRecord r;
    r.sceneSpec = run.sceneSpec();
    r.sceneSource = session.scene().source;
    r.sceneFiles = hashSceneFiles(session.scene());
    r.camera = session.camera();
    const KnobRegistry& knobs = session.knobs();
    for (size_t i = 0; i < knobs.size(); ++i)
        r.knobs.emplace_back(knobs.spec(static_cast<int>(i)).name, knobs.format(static_cast<int>(i)));
    r.width = run.width;
    r.height = run.height;
    r.frames = run.frames;
    r.warmup = run.warmup;
    r.buffer = buffer;
    r.build = buildFields();
    const gl::GlInfo& info = session.glInfo();
    r.gl = {{"vendor", info.vendor}, {"renderer", info.renderer}, {"version", info.version}, {"platform", glPlatform}};
    r.host.emplace_back("cpu", cpuModel());
    r.host.emplace_back("cpu_threads", std::to_string(std::thread::hardware_concurrency()));
    utsname u{};
    if (uname(&u) == 0) r.host.emplace_back("os", std::string(u.sysname) + " " + u.release + " " + u.machine);
    PassTimer& timer = session.pipeline().timer();
    timer.collect(true);
    for (const PassTimer::Series& s : timer.series()) {
        RecordedSeries rs{s.name, {}, {}};
        for (const TimingSample& t : s.samples)
            if (t.frame >= firstCounted) {
                rs.gpuMs.push_back(t.gpuMs);
                rs.cpuMs.push_back(t.cpuMs);
            }
        if (!rs.gpuMs.empty()) r.timings.push_back(std::move(rs));
    }
    r.imageSha256 = hashBuffer(session, buffer, r.imageWidth, r.imageHeight, r.imageChannels);
    return r;
}

std::string ExperimentRecord::json() const {
    Json j;
    j["format"] = "deferred-workbench record";
    j["version"] = version;
    j["command"] = command;
    Json files = Json::array();
    for (const auto& f : sceneFiles) files.push_back({{"path", f.path}, {"sha256", f.sha256}});
    j["scene"] = {{"spec", sceneSpec}, {"source", sceneSource}, {"files", files}};
    j["camera"] = {{"position", vec3(camera.position)}, {"target", vec3(camera.target)}, {"up", vec3(camera.up)},
                   {"fov_y_degrees", camera.fovYDegrees}, {"near", camera.nearPlane}, {"far", camera.farPlane}};
    j["knobs"] = fieldsJson(knobs);
    j["size"] = Json::array({width, height});
    j["frames"] = frames;
    j["warmup"] = warmup;
    j["buffer"] = buffer;
    j["build"] = fieldsJson(build);
    j["gl"] = fieldsJson(gl);
    j["host"] = fieldsJson(host);
    Json series = Json::array();
    for (const auto& s : timings) series.push_back({{"name", s.name}, {"gpu_ms", s.gpuMs}, {"cpu_ms", s.cpuMs}});
    j["results"] = {{"timings", series},
                    {"image", {{"buffer", buffer}, {"sha256", imageSha256}, {"width", imageWidth},
                               {"height", imageHeight}, {"channels", imageChannels}}}};
    return j.dump(2) + "\n";
}

void ExperimentRecord::write(const std::string& path) const { writeFileAtomically(path, json()); }

ExperimentRecord ExperimentRecord::read(const std::string& path) {
    JsonGuardOptions options;
    options.numbersAreFloats = false;
    const nlohmann::json j = readJsonFile(path, options);
    if (!j.is_object() || j.value("format", "") != "deferred-workbench record")
        throw FileError(path, "not a deferred-workbench record (no \"format\": \"deferred-workbench record\")");
    if (!j.contains("version") || !j["version"].is_number_integer())
        throw FileError(path, "the record has no integer \"version\"");
    ExperimentRecord r;
    r.version = j["version"].get<int>();
    if (r.version > kVersion)
        throw FileError(path, "record version " + std::to_string(r.version) + " is newer than this build reads (" +
                                  std::to_string(kVersion) + "); replay it with a newer deferred-workbench");
    if (r.version < 1) throw FileError(path, "record version " + std::to_string(r.version) + " does not exist");
    try {
        r.command = j.at("command").get<std::string>();
        const auto& scene = j.at("scene");
        r.sceneSpec = scene.at("spec").get<std::string>();
        r.sceneSource = scene.value("source", "");
        for (const auto& f : scene.value("files", nlohmann::json::array()))
            r.sceneFiles.push_back({f.at("path").get<std::string>(), f.at("sha256").get<std::string>()});
        const auto& cam = j.at("camera");
        r.camera.position = readVec3(cam.at("position"), path, "position");
        r.camera.target = readVec3(cam.at("target"), path, "target");
        r.camera.up = readVec3(cam.at("up"), path, "up");
        r.camera.fovYDegrees = cam.at("fov_y_degrees").get<float>();
        r.camera.nearPlane = cam.at("near").get<float>();
        r.camera.farPlane = cam.at("far").get<float>();
        r.knobs = fieldsOf(j.at("knobs"));
        r.width = j.at("size").at(0).get<int>();
        r.height = j.at("size").at(1).get<int>();
        r.frames = j.at("frames").get<int>();
        r.warmup = j.at("warmup").get<int>();
        r.buffer = j.at("buffer").get<std::string>();
        r.build = fieldsOf(j.value("build", nlohmann::json::object()));
        r.gl = fieldsOf(j.value("gl", nlohmann::json::object()));
        r.host = fieldsOf(j.value("host", nlohmann::json::object()));
        const auto& results = j.at("results");
        for (const auto& s : results.value("timings", nlohmann::json::array()))
            r.timings.push_back({s.at("name").get<std::string>(), s.at("gpu_ms").get<std::vector<double>>(),
                                 s.at("cpu_ms").get<std::vector<double>>()});
        const auto& image = results.at("image");
        r.imageSha256 = image.at("sha256").get<std::string>();
        r.imageWidth = image.value("width", 0);
        r.imageHeight = image.value("height", 0);
        r.imageChannels = image.value("channels", 0);
    } catch (const nlohmann::json::exception& e) {
        throw FileError(path, "record version " + std::to_string(r.version) + ": " + jsonErrorText(e));
    }
    if (r.command != "render") throw FileError(path, "records of '" + r.command + "' cannot be replayed yet (render only)");
    if (r.width < 1 || r.height < 1 || r.width > 16384 || r.height > 16384 || r.frames < 1 || r.warmup < 0)
        throw FileError(path, "size, frames or warmup out of range");
    return r;
}

}  // namespace dw

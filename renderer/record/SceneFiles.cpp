#include "renderer/record/SceneFiles.h"

#include <openssl/evp.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "renderer/Error.h"
#include "renderer/io/JsonGuard.h"
#include "renderer/io/TextFile.h"
#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneContent.h"

namespace dw {

namespace fs = std::filesystem;

std::string sha256Hex(const void* data, size_t size) {
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

std::string sha256OfFile(const std::string& path) {
    // Bounded as the loaders' reads are: a device or an endless pipe is no scene file.
    std::string bytes;
    try {
        bytes = readWholeFile(path, "not found", "cannot read", kBinaryFileLimit);
    } catch (const FileError&) {
        return "";
    }
    return sha256Hex(bytes.data(), bytes.size());
}

namespace {

bool isExternalUri(const nlohmann::json& uri) {
    if (!uri.is_string()) return false;
    const std::string u = uri.get<std::string>();
    return !u.empty() && u.rfind("data:", 0) != 0;
}

// A relative name as the loaders resolve it: against the folder of the file that names it.
std::string resolved(const fs::path& from, const std::string& name) {
    const fs::path p(name);
    return (p.is_absolute() ? p : from.parent_path() / p).lexically_normal().string();
}

class SceneFileList {
public:
    // `gltfUris`: the loader's Scene::gltfExternalUris (a glTF it read is not parsed again).
    explicit SceneFileList(const std::map<std::string, std::vector<std::string>>& gltfUris) : gltfUris_(gltfUris) {}
    void add(const std::string& name) {
        const std::string path = fs::path(name).lexically_normal().string();
        std::error_code ec;
        if (path.empty() || !fs::is_regular_file(path, ec) || !seen_.insert(path).second) return;
        paths_.push_back(path);
        const std::string ext = fs::path(path).extension().string();
        // A file that cannot be parsed here was read by the loader all the
        // same (or refused): its own hash is what the record needs.
        try {
            if (ext == ".gltf") addGltfParts(path);
            else if (ext == ".json") addSceneParts(path);
        } catch (const Error&) {
        }
    }
    const std::vector<std::string>& paths() const { return paths_; }

private:
    void addGltfParts(const std::string& path) {
        if (const auto known = gltfUris_.find(path); known != gltfUris_.end()) {
            for (const std::string& uri : known->second) add(resolved(path, uri));
            return;
        }
        const nlohmann::json j = readJsonFile(path, {kMaxJsonDepth, false});
        for (const char* key : {"buffers", "images"})
            if (j.contains(key) && j[key].is_array())
                for (const auto& item : j[key])
                    if (item.is_object() && item.contains("uri") && isExternalUri(item["uri"]))
                        add(resolved(path, item["uri"].get<std::string>()));
    }
    // Every "gltf" an object names and the sky's "file" / "files".
    void addSceneParts(const std::string& path) {
        const nlohmann::json j = readJsonFile(path, {kMaxJsonDepth, false});
        if (!j.is_object()) return;
        if (j.contains("objects") && j["objects"].is_array())
            for (const auto& o : j["objects"])
                if (o.is_object() && o.contains("gltf") && o["gltf"].is_string())
                    add(resolved(path, o["gltf"].get<std::string>()));
        if (j.contains("sky") && j["sky"].is_object()) {
            const auto& sky = j["sky"];
            if (sky.contains("file") && sky["file"].is_string()) add(resolved(path, sky["file"].get<std::string>()));
            if (sky.contains("files") && sky["files"].is_array())
                for (const auto& f : sky["files"])
                    if (f.is_string()) add(resolved(path, f.get<std::string>()));
        }
    }

    const std::map<std::string, std::vector<std::string>>& gltfUris_;
    std::set<std::string> seen_;
    std::vector<std::string> paths_;
};

}  // namespace

bool isBuiltinSceneContent(const std::string& path) { return path.rfind("builtin:", 0) == 0; }

std::vector<RecordedFile> sceneFilesOf(const Scene& scene) {
    SceneFileList list(scene.gltfExternalUris);
    const bool builtin = isBuiltinSceneContent(scene.source);
    if (!builtin) list.add(scene.source);
    list.add(scene.sky.environmentSource);
    for (const Image& image : scene.images) list.add(image.source);
    std::vector<RecordedFile> files;
    // A built-in scene reads no file: what it generates is its content.
    if (builtin) files.push_back({scene.source, sceneContentSha256(scene)});
    for (const std::string& p : list.paths()) files.push_back({p, sha256OfFile(p)});
    return files;
}

namespace {

// `file` relative to the folder of `scene` (both made absolute against the
// working directory, lexically); a built-in scene's content by its name.
std::string keyOf(const std::string& file, const std::string& scene) {
    if (isBuiltinSceneContent(file)) return file;
    std::error_code ec;
    const fs::path f = fs::absolute(file, ec).lexically_normal();
    const fs::path base = fs::absolute(scene, ec).lexically_normal().parent_path();
    const fs::path rel = f.lexically_relative(base);
    return rel.empty() ? f.string() : rel.string();
}

}  // namespace

std::vector<SceneFileChange> compareSceneFiles(const std::vector<RecordedFile>& recorded, const std::string& recordedScene,
                                               const std::vector<RecordedFile>& now, const std::string& nowScene) {
    std::map<std::string, const RecordedFile*> current;
    for (const RecordedFile& f : now) current.emplace(keyOf(f.path, nowScene), &f);
    std::vector<SceneFileChange> changes;
    std::set<std::string> matched;
    for (const RecordedFile& f : recorded) {
        const std::string key = keyOf(f.path, recordedScene);
        const auto it = current.find(key);
        if (it == current.end()) {
            changes.push_back({SceneFileChange::Kind::Removed, f.path, f.sha256, ""});
            continue;
        }
        matched.insert(key);
        if (it->second->sha256 != f.sha256 || f.sha256.empty())
            changes.push_back({SceneFileChange::Kind::Changed, it->second->path, f.sha256, it->second->sha256});
    }
    for (const RecordedFile& f : now)
        if (!matched.count(keyOf(f.path, nowScene)))
            changes.push_back({SceneFileChange::Kind::Added, f.path, "", f.sha256});
    return changes;
}

}  // namespace dw

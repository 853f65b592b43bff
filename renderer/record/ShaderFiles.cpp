#include "renderer/record/ShaderFiles.h"

#include <algorithm>
#include <filesystem>
#include <map>

#include "renderer/record/ExperimentRecord.h"
#include "renderer/record/SceneFiles.h"

namespace dw {

namespace fs = std::filesystem;

RecordedShaders shaderFilesOf(const gl::CompiledShaders& compiled) {
    RecordedShaders r;
    r.present = true;
    std::error_code ec;
    const fs::path root = compiled.root.empty() ? fs::path() : fs::weakly_canonical(compiled.root, ec);
    r.folder = root.string();
    for (const auto& [file, text] : compiled.texts) {
        std::string path = file.string();
        if (!root.empty()) {
            const fs::path rel = file.lexically_normal().lexically_relative(root);
            if (!rel.empty() && *rel.begin() != "..") path = rel.generic_string();
        }
        r.files.push_back({path, sha256Hex(text.data(), text.size())});
    }
    std::sort(r.files.begin(), r.files.end(), [](const RecordedFile& a, const RecordedFile& b) { return a.path < b.path; });
    return r;
}

namespace {

// A recorded path that may be looked up in the shader folder: relative, no "..".
bool insideFolder(const std::string& p) {
    const fs::path path(p);
    if (path.empty() || path.is_absolute()) return false;
    for (const auto& part : path.lexically_normal())
        if (part == "..") return false;
    return true;
}

}  // namespace

std::vector<SceneFileChange> compareShaderFiles(const RecordedShaders& recorded, const RecordedShaders& now) {
    std::map<std::string, std::string> compiledNow;
    for (const auto& f : now.files) compiledNow[f.path] = f.sha256;
    std::vector<SceneFileChange> changes;
    std::map<std::string, bool> seen;
    for (const auto& f : recorded.files) {
        seen[f.path] = true;
        std::string sha;
        bool there = false;
        if (const auto it = compiledNow.find(f.path); it != compiledNow.end()) {
            sha = it->second;
            there = true;
        } else if (insideFolder(f.path) && !now.folder.empty()) {
            const fs::path file = fs::path(now.folder) / f.path;
            std::error_code ec;
            if (fs::is_regular_file(file, ec)) {  // never a pipe or a folder
                sha = sha256OfFile(file.string());
                there = true;
            }
        }
        if (!there)
            changes.push_back({SceneFileChange::Kind::Removed, f.path, f.sha256, ""});
        else if (sha != f.sha256)
            changes.push_back({SceneFileChange::Kind::Changed, f.path, f.sha256, sha});
    }
    for (const auto& f : now.files)
        if (!seen.count(f.path)) changes.push_back({SceneFileChange::Kind::Added, f.path, "", f.sha256});
    return changes;
}

}  // namespace dw

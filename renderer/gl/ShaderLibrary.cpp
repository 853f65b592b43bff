#include "renderer/gl/ShaderLibrary.h"

#include <algorithm>
#include <cstdlib>
#include <unistd.h>

namespace dw::gl {

namespace fs = std::filesystem;

std::string ProgramDesc::key() const {
    std::string k = vertex + "|" + fragment + "|" + geometry + "|" + compute;
    for (const auto& d : defines) k += "|" + d;
    return k;
}

ShaderLibrary::ShaderLibrary(fs::path root) : root_(std::move(root)) { compiled_.root = root_; }

void ShaderLibrary::build(Entry& e) {
    std::vector<ShaderStage> stages;
    auto add = [&](GLenum type, const std::string& file) {
        if (!file.empty()) stages.push_back({type, ShaderSource::load(root_, file, e.desc.defines)});
    };
    add(GL_VERTEX_SHADER, e.desc.vertex);
    add(GL_GEOMETRY_SHADER, e.desc.geometry);
    add(GL_FRAGMENT_SHADER, e.desc.fragment);
    add(GL_COMPUTE_SHADER, e.desc.compute);
    std::vector<fs::path> files;
    for (const auto& s : stages)
        for (const auto& f : s.source.files)
            if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
    Program p = Program::link(stages);
    e.program = std::move(p);
    e.files = files;
    e.stamps.clear();
    for (const auto& f : files) {
        std::error_code ec;
        e.stamps.push_back(fs::last_write_time(f, ec));
    }
    e.error.clear();
    for (const auto& s : stages)
        for (size_t i = 0; i < s.source.files.size() && i < s.source.texts.size(); ++i)
            compiled_.texts[s.source.files[i]] = s.source.texts[i];
}

ShaderLibrary::Handle ShaderLibrary::get(const ProgramDesc& desc) {
    const std::string key = desc.key();
    auto it = entries_.find(key);
    if (it != entries_.end()) return Handle(it->second.get());
    auto e = std::make_unique<Entry>();
    e->desc = desc;
    build(*e);
    const Entry* raw = e.get();
    entries_.emplace(key, std::move(e));
    return Handle(raw);
}

std::vector<std::string> ShaderLibrary::reloadChanged(bool force) {
    std::vector<std::string> errors;
    for (auto& [key, e] : entries_) {
        bool changed = force;
        for (size_t i = 0; i < e->files.size() && !changed; ++i) {
            std::error_code ec;
            if (fs::last_write_time(e->files[i], ec) != e->stamps[i]) changed = true;
        }
        if (!changed) continue;
        try {
            build(*e);
        } catch (const Error& ex) {
            e->error = ex.what();
            // Remember the new stamps so a broken file is not retried every frame.
            for (size_t i = 0; i < e->files.size(); ++i) {
                std::error_code ec;
                e->stamps[i] = fs::last_write_time(e->files[i], ec);
            }
            errors.push_back(e->error);
        }
    }
    return errors;
}

std::vector<std::string> ShaderLibrary::pendingErrors() const {
    std::vector<std::string> out;
    for (const auto& [key, e] : entries_)
        if (!e->error.empty()) out.push_back(e->error);
    return out;
}

fs::path ShaderLibrary::locateRoot() {
    std::vector<fs::path> candidates;
    // A folder named by DW_SHADER_DIR is used or refused, never passed over:
    // falling back to the build's shaders would measure (or replay) other
    // shaders than the ones asked for, and say nothing.
    if (const char* env = std::getenv("DW_SHADER_DIR"); env && *env) {
        std::error_code ec;
        if (!fs::exists(fs::path(env) / "common", ec))
            throw Error(std::string("DW_SHADER_DIR=") + env + " is not a shader folder (" +
                        (!fs::exists(fs::path(env), ec)         ? "it does not exist"
                         : !fs::is_directory(fs::path(env), ec) ? "it is not a folder"
                                                                : "it has no common/ in it") +
                        "); name a copy of the project's shaders/, or unset it for the build's own");
        return fs::weakly_canonical(fs::path(env));
    }
#ifdef DW_SOURCE_SHADER_DIR
    candidates.emplace_back(DW_SOURCE_SHADER_DIR);
#endif
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back(exe.parent_path() / "shaders");
        candidates.push_back(exe.parent_path().parent_path() / "share/deferred-workbench/shaders");
    }
    std::string tried;
    for (const auto& c : candidates) {
        if (fs::exists(c / "common")) return fs::weakly_canonical(c);
        tried += (tried.empty() ? "" : ", ") + c.string();
    }
    throw Error("cannot find the shader directory (looked in: " + tried +
                "); set DW_SHADER_DIR to the project's shaders/ folder");
}

std::vector<const ShaderLibrary::Entry*> ShaderLibrary::programs() const {
    std::vector<const Entry*> out;
    for (const auto& [key, entry] : entries_) out.push_back(entry.get());
    return out;
}

}  // namespace dw::gl

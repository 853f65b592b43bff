#pragma once
// Owns every GLSL program, keyed by its stage files and defines. Programs are
// compiled on first use; reloadChanged() recompiles those whose files changed
// and keeps the last good program when the new source fails (DESIGN.md).
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/gl/CompiledShaders.h"
#include "renderer/gl/Program.h"

namespace dw::gl {

struct ProgramDesc {
    std::string vertex, fragment, geometry, compute;  // paths relative to the shader root
    std::vector<std::string> defines;
    std::string key() const;
};

class ShaderLibrary {
public:
    struct Entry {
        ProgramDesc desc;
        Program program;
        std::vector<std::filesystem::path> files;
        std::vector<std::filesystem::file_time_type> stamps;
        std::string error;  // last failed reload, empty when the program is current
    };
    // A stable reference to a program that survives reloads.
    class Handle {
    public:
        Handle() = default;
        explicit Handle(const Entry* e) : entry_(e) {}
        const Program& operator*() const { return entry_->program; }
        const Program* operator->() const { return &entry_->program; }
        explicit operator bool() const { return entry_ != nullptr; }

    private:
        const Entry* entry_ = nullptr;
    };

    explicit ShaderLibrary(std::filesystem::path root);
    const std::filesystem::path& root() const { return root_; }

    // Compiles on first request; throws ShaderError if that first compile fails.
    Handle get(const ProgramDesc& desc);
    // Recompiles programs whose source files changed (or all, if force).
    // Returns the errors of programs that failed; those keep their old code.
    std::vector<std::string> reloadChanged(bool force = false);
    // Errors from the last reload still unresolved.
    std::vector<std::string> pendingErrors() const;
    size_t programCount() const { return entries_.size(); }
    // Every program compiled so far, in key order (tests inspect their blocks).
    std::vector<const Entry*> programs() const;

    // Every file compiled so far with the text of its last successful compile.
    const CompiledShaders& compiled() const { return compiled_; }

    // Finds the shader directory: $DW_SHADER_DIR, the source tree, or next to
    // the executable. Throws dw::Error listing where it looked.
    static std::filesystem::path locateRoot();

private:
    void build(Entry& e);
    std::filesystem::path root_;
    std::map<std::string, std::unique_ptr<Entry>> entries_;
    CompiledShaders compiled_;
};

}  // namespace dw::gl

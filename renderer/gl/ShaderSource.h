#pragma once
// GLSL source assembly: resolves #include "file" relative to the including file
// or the shader root, inserts #line directives so the compiler's line numbers
// map back to files, and rewrites the driver's info log as "path:line: message".
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/Error.h"

namespace dw::gl {

// A compile or link failure. what() holds one "path:line: message" per line.
class ShaderError : public Error {
public:
    using Error::Error;
};

struct ShaderSource {
    std::string text;                            // assembled source handed to GL
    std::vector<std::filesystem::path> files;    // index = GLSL source-string number
    std::vector<std::string> texts;              // each file's text as read (the same index)
    std::filesystem::path mainFile() const { return files.empty() ? std::filesystem::path{} : files[0]; }

    // Loads `relativePath` under `root`; `defines` are NAME or NAME=VALUE.
    static ShaderSource load(const std::filesystem::path& root, const std::string& relativePath,
                             const std::vector<std::string>& defines);
    // Same, from text already in memory (tests, generated code).
    static ShaderSource fromString(const std::filesystem::path& root, const std::string& virtualName,
                                   const std::string& text, const std::vector<std::string>& defines);

    // Maps a driver info log (Mesa "0:12(3): error" or NVIDIA "0(12) : error")
    // to "path:line: error" lines using `files`.
    std::string mapInfoLog(const std::string& log) const;

    // Where `identifier` first occurs as a whole word (the declaration, in
    // practice): its file and 1-based line, or line 0 when it does not occur.
    // Link logs name variables, not lines (Program::link).
    struct Location {
        std::filesystem::path file;
        int line = 0;
    };
    Location locate(const std::string& identifier) const;
};

}  // namespace dw::gl

#pragma once
// The shader files a ShaderLibrary compiled: its folder and, per file
// (absolute, canonical: each stage's file and every file it #includes,
// params/ headers included), the text it last compiled successfully. They are
// inputs of a measurement: experiment records hash them
// (renderer/record/ShaderFiles). Needs no GL.
#include <filesystem>
#include <map>
#include <string>

namespace dw::gl {

struct CompiledShaders {
    std::filesystem::path root;
    std::map<std::filesystem::path, std::string> texts;

    // Adds `other`'s files (the sessions of one bench run share a folder).
    void add(const CompiledShaders& other) {
        if (root.empty()) root = other.root;
        for (const auto& [file, text] : other.texts) texts[file] = text;
    }
};

}  // namespace dw::gl

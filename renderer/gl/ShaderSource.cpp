#include "renderer/gl/ShaderSource.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "renderer/io/TextFile.h"

namespace dw::gl {

namespace fs = std::filesystem;

namespace {

std::string readFile(const fs::path& path) {
    return readWholeFile(path.string(), "cannot open shader file", "cannot open shader file");
}

struct Assembler {
    fs::path root;
    std::vector<fs::path> files;
    std::vector<std::string> texts;  // parallel to files
    std::ostringstream out;

    int fileIndex(const fs::path& p) {
        for (size_t i = 0; i < files.size(); ++i)
            if (files[i] == p) return static_cast<int>(i);
        files.push_back(p);
        return static_cast<int>(files.size() - 1);
    }

    // Every file is emitted once (include-guard semantics), so diamond and
    // cyclic includes are harmless.
    bool alreadyIncluded(const fs::path& p) const {
        return std::find(files.begin(), files.end(), p) != files.end();
    }

    fs::path resolve(const fs::path& includer, const std::string& name, int line) {
        const fs::path local = includer.parent_path() / name;
        if (fs::exists(local)) return fs::weakly_canonical(local);
        const fs::path fromRoot = root / name;
        if (fs::exists(fromRoot)) return fs::weakly_canonical(fromRoot);
        throw ShaderError(includer.string() + ":" + std::to_string(line) + ": #include \"" + name +
                          "\" not found (looked in " + includer.parent_path().string() + " and " +
                          root.string() + ")");
    }

    // Emits `text` (the contents of `path`); the main file's #version line is
    // handled by the caller.
    void emit(const fs::path& path, const std::string& text, int firstLine) {
        const int index = fileIndex(path);
        if (texts.size() <= static_cast<size_t>(index)) texts.resize(static_cast<size_t>(index) + 1);
        texts[static_cast<size_t>(index)] = text;
        static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
        std::istringstream in(text);
        std::string line;
        int lineNo = 0;
        while (std::getline(in, line)) {
            ++lineNo;
            if (lineNo < firstLine) continue;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            std::smatch m;
            if (std::regex_match(line, m, includeRe)) {
                const fs::path inc = resolve(path, m[1].str(), lineNo);
                if (!alreadyIncluded(inc)) {
                    const std::string incText = readFile(inc);
                    out << "#line 1 " << fileIndex(inc) << "\n";
                    emit(inc, incText, 1);
                }
                out << "#line " << (lineNo + 1) << " " << index << "\n";
                continue;
            }
            out << line << "\n";
        }
    }
};

ShaderSource assemble(const fs::path& root, const fs::path& mainPath, const std::string& text,
                      const std::vector<std::string>& defines) {
    Assembler a;
    a.root = root;
    // The #version line must come first; defines go right after it.
    std::istringstream in(text);
    std::string first;
    std::getline(in, first);
    int bodyStart = 1;
    if (first.rfind("#version", 0) == 0) {
        a.out << first << "\n";
        bodyStart = 2;
    } else {
        a.out << "#version 450 core\n";
    }
    for (const auto& d : defines) {
        const auto eq = d.find('=');
        if (eq == std::string::npos)
            a.out << "#define " << d << " 1\n";
        else
            a.out << "#define " << d.substr(0, eq) << " " << d.substr(eq + 1) << "\n";
    }
    a.fileIndex(mainPath);
    a.out << "#line " << bodyStart << " 0\n";
    a.emit(mainPath, text, bodyStart);
    ShaderSource s;
    s.text = a.out.str();
    s.files = a.files;
    s.texts = a.texts;
    s.texts.resize(s.files.size());
    return s;
}

}  // namespace

ShaderSource ShaderSource::load(const fs::path& root, const std::string& relativePath,
                                const std::vector<std::string>& defines) {
    const fs::path path = fs::weakly_canonical(root / relativePath);
    return assemble(fs::weakly_canonical(root), path, readFile(path), defines);
}

ShaderSource ShaderSource::fromString(const fs::path& root, const std::string& virtualName,
                                      const std::string& text,
                                      const std::vector<std::string>& defines) {
    return assemble(fs::weakly_canonical(root), fs::path(virtualName), text, defines);
}

std::string ShaderSource::mapInfoLog(const std::string& log) const {
    // Mesa: "0:12(3): error: ..."; NVIDIA: "0(12) : error C1008: ..."
    static const std::regex mesaRe(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvRe(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::smatch m;
        if (std::regex_match(line, m, mesaRe) || std::regex_match(line, m, nvRe)) {
            const size_t idx = std::stoul(m[1].str());
            const std::string file = idx < files.size() ? files[idx].string() : "<source " + m[1].str() + ">";
            out << file << ":" << m[2].str() << ": " << m[3].str() << "\n";
        } else {
            out << mainFile().string() << ": " << line << "\n";
        }
    }
    std::string s = out.str();
    if (!s.empty() && s.back() == '\n') s.pop_back();
    return s;
}

ShaderSource::Location ShaderSource::locate(const std::string& identifier) const {
    // Walk the assembled text, following its #line directives back to files.
    static const std::regex lineRe(R"(^#line\s+(\d+)\s+(\d+)\s*$)");
    const std::regex word("(^|[^A-Za-z0-9_])" + identifier + "([^A-Za-z0-9_]|$)");
    std::istringstream in(text);
    std::string line;
    int fileIndex = -1, lineNo = 0;  // before the first #line: the #version and defines
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, lineRe)) {
            lineNo = std::stoi(m[1].str());
            fileIndex = std::stoi(m[2].str());
            continue;
        }
        if (fileIndex >= 0 && fileIndex < static_cast<int>(files.size()) && std::regex_search(line, word))
            return {files[static_cast<size_t>(fileIndex)], lineNo};
        if (fileIndex >= 0) ++lineNo;
    }
    return {};
}

}  // namespace dw::gl

#include "renderer/io/TextFile.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "renderer/Error.h"

namespace dw {

std::string readWholeFile(const std::string& path, const std::string& notFound, const std::string& unreadable) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path, std::filesystem::exists(path) ? unreadable : notFound);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(dir)) throw FileError(path, "cannot save: folder " + dir.string() + " does not exist");
    if (fs::is_directory(target)) throw FileError(path, "cannot save: a folder has that name");
    const fs::path tmp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()));
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw FileError(path, "cannot save: cannot write in " + dir.string());
        out << text;
        out.flush();
        if (!out) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw FileError(path, "cannot save: writing failed (disk full?)");
        }
    }
    if (FILE* f = std::fopen(tmp.c_str(), "rb")) {
        ::fsync(fileno(f));
        std::fclose(f);
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw FileError(path, "cannot save: " + ec.message());
    }
}

std::string textPosition(std::string_view text, std::size_t byte) {
    std::size_t line = 1, col = 1;
    for (std::size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            col = 1;
        } else {
            ++col;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

}  // namespace dw

#include "renderer/io/TextFile.h"

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

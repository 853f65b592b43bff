#pragma once
// Whole-file reads and JSON error positions, shared by the scene, glTF,
// preset and shader loaders so their errors read alike.
#include <cstddef>
#include <string>
#include <string_view>

namespace dw {

// The file's bytes. Throws FileError(path, notFound) when it does not exist,
// FileError(path, unreadable) when it cannot be opened.
std::string readWholeFile(const std::string& path, const std::string& notFound, const std::string& unreadable);

// "line L, column C" (1-based) of the byte a parser reported: nlohmann's
// parse_error::byte counts from 1 and points just past the offending byte.
std::string textPosition(std::string_view text, std::size_t byte);

}  // namespace dw

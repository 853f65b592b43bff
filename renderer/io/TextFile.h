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

// Replaces `path` with `text` without ever leaving it half written: a
// temporary file in the same folder, flushed and synced, then renamed over
// it. On failure the previous file is untouched and FileError(path, "cannot
// save: ...") says why (no folder, a folder of that name, not writable, disk full).
void writeFileAtomically(const std::string& path, const std::string& text);

// "line L, column C" (1-based) of the byte a parser reported: nlohmann's
// parse_error::byte counts from 1 and points just past the offending byte.
std::string textPosition(std::string_view text, std::size_t byte);

}  // namespace dw

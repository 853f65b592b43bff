#pragma once
// Whole-file reads and JSON error positions, shared by the scene, glTF,
// preset and shader loaders so their errors read alike.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace dw {

// The most a text file read whole may hold (scene JSON, presets, records,
// shaders, CSVs, events): 256 MiB. Its parse takes several times as much.
constexpr std::uint64_t kTextFileLimit = 256ull << 20;
// A glTF binary (.glb) declares its length in 32 bits: at most 4 GiB.
constexpr std::uint64_t kBinaryFileLimit = 4ull << 30;

// The file's bytes, at most `limit` of them. Throws FileError(path, notFound)
// when it does not exist, FileError(path, unreadable) when it cannot be
// opened, and FileError(path, "... is a folder" / "... is a device" / "...
// over the limit of N MB") for a folder, a device (/dev/zero, a terminal:
// never ends or never answers), a file larger than `limit` (refused from its
// size before it is read) or a pipe that gives more than `limit`. A pipe
// with no writer reads as empty; nothing blocks on opening.
std::string readWholeFile(const std::string& path, const std::string& notFound, const std::string& unreadable,
                          std::uint64_t limit = kTextFileLimit);

// For a reader that opens the file itself (OpenImageIO's decoders), or one
// that needs the whole of a file that is there (a glTF's buffers and images): throws
// FileError(path, notFound) when it does not exist, and FileError(path,
// unreadable + ": it is a folder" / ": it is a device" / ": it is a pipe")
// when it is not a regular file (symlinks followed). A device such as
// /dev/zero never ends, a pipe's writer may never end it, and decoders seek.
void requireRegularFile(const std::string& path, const std::string& notFound, const std::string& unreadable);

// Replaces `path` with `text` without ever leaving it half written: a
// temporary file in the same folder, flushed and synced, then renamed over
// it. On failure the previous file is untouched and FileError(path, "cannot
// save: ...") says why (no folder, a folder of that name, not writable, disk
// full). A link is written through (the file it names is replaced). A
// device or a pipe (/dev/null, /dev/full, a FIFO) is written in place, its
// write checked, never renamed over; a pipe with no reader is refused.
void writeFileAtomically(const std::string& path, const std::string& text);

// "line L, column C" (1-based) of the byte a parser reported: nlohmann's
// parse_error::byte counts from 1 and points just past the offending byte.
std::string textPosition(std::string_view text, std::size_t byte);

}  // namespace dw

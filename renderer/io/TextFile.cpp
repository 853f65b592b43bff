#include "renderer/io/TextFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "renderer/Error.h"

namespace dw {

namespace {

// "2000 bytes", "300.0 MB".
std::string sizeText(std::uint64_t bytes) {
    if (bytes < (1u << 20)) return std::to_string(bytes) + " bytes";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return buf;
}

// Closes the descriptor on every path out.
struct Descriptor {
    int fd;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

std::string readWholeFile(const std::string& path, const std::string& notFound, const std::string& unreadable,
                          std::uint64_t limit) {
    // O_NONBLOCK: opening a FIFO without a writer would wait for one forever.
    const Descriptor in{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (in.fd < 0) throw FileError(path, errno == ENOENT ? notFound : unreadable + " (" + std::strerror(errno) + ")");
    struct stat st {};
    if (::fstat(in.fd, &st) != 0) throw FileError(path, unreadable + " (" + std::strerror(errno) + ")");
    if (S_ISDIR(st.st_mode)) throw FileError(path, unreadable + ": it is a folder, not a file");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
        throw FileError(path, unreadable + ": it is a device, not a file (a device such as /dev/zero never ends)");
    const std::string limitText = "over the limit of " + sizeText(limit) + " for a file read whole";
    if (S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) > limit)
        throw FileError(path, unreadable + ": it is " + sizeText(static_cast<std::uint64_t>(st.st_size)) + ", " + limitText);
    // Blocking reads from here: a pipe's writer is waited for, but a pipe
    // with none reads as its end.
    ::fcntl(in.fd, F_SETFL, ::fcntl(in.fd, F_GETFL) & ~O_NONBLOCK);
    std::string bytes;
    if (S_ISREG(st.st_mode)) bytes.reserve(static_cast<std::size_t>(st.st_size));
    char buffer[1 << 16];
    for (;;) {
        const ssize_t n = ::read(in.fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw FileError(path, unreadable + " (" + std::strerror(errno) + ")");
        if (n == 0) return bytes;
        if (bytes.size() + static_cast<std::uint64_t>(n) > limit)
            throw FileError(path, unreadable + ": it holds more than " + sizeText(limit) + ", " + limitText);
        bytes.append(buffer, static_cast<std::size_t>(n));
    }
}

void requireRegularFile(const std::string& path, const std::string& notFound, const std::string& unreadable) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw FileError(path, errno == ENOENT ? notFound : unreadable + " (" + std::strerror(errno) + ")");
    if (S_ISREG(st.st_mode)) return;
    if (S_ISDIR(st.st_mode)) throw FileError(path, unreadable + ": it is a folder, not a file");
    if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
        throw FileError(path, unreadable + ": it is a device, not a file (a device such as /dev/zero never ends)");
    throw FileError(path, unreadable + ": it is a pipe or socket, not a file");
}

namespace {

// A device or a pipe (/dev/null, /dev/full, a reader's FIFO): written in
// place, never renamed over (a rename replaced /dev/full with a file). A pipe
// with no reader is refused (opening it would wait for one forever).
void writeInPlace(const std::string& path, const std::string& text) {
    const Descriptor out{::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC)};
    if (out.fd < 0)
        throw FileError(path, errno == ENXIO ? std::string("cannot save: it is a pipe with no reader (start the reader first)")
                                             : "cannot save: " + std::string(std::strerror(errno)));
    ::fcntl(out.fd, F_SETFL, ::fcntl(out.fd, F_GETFL) & ~O_NONBLOCK);
    for (std::size_t done = 0; done < text.size();) {
        const ssize_t n = ::write(out.fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            throw FileError(path, std::string("cannot save: writing failed (") + (n < 0 ? std::strerror(errno) : "no progress") + ")");
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    std::error_code link;
    // Through a link to the file it names: renaming over the link replaced
    // the link with a file and left its target as it was.
    const fs::path target = fs::is_symlink(fs::symlink_status(path, link)) ? fs::weakly_canonical(path, link) : fs::path(path);
    const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    if (!fs::is_directory(dir)) throw FileError(path, "cannot save: folder " + dir.string() + " does not exist");
    if (fs::is_directory(target)) throw FileError(path, "cannot save: a folder has that name");
    std::error_code kind;
    if (fs::exists(target, kind) && !fs::is_regular_file(target, kind)) {
        writeInPlace(path, text);
        return;
    }
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

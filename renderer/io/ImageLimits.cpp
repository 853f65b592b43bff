#include "renderer/io/ImageLimits.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <vector>

#include "renderer/Error.h"

namespace dw {

namespace {

std::string mb(double bytes) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f", bytes / (1024.0 * 1024.0));
    return buf;
}

std::string limitText(std::uint64_t limit) {
    return "the image memory limit of " + std::to_string(limit / (1024 * 1024)) + " MB (set " + kImageLimitVariable +
           "=MB to raise it)";
}

// A name read from a damaged header, fit for a one-line message: bytes
// outside printable ASCII (and the backslash) as \xNN. A damaged EXR's
// attribute "name" is any bytes up to a zero; printed raw it broke the
// terminal's line (and the CLI's one-line promise).
std::string escaped(const std::string& raw) {
    std::string out;
    for (unsigned char c : raw) {
        if (c >= 0x20 && c < 0x7f && c != '\\') {
            out.push_back(static_cast<char>(c));
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    return out;
}

// The header's bytes ran out before its end: in the part of the file read so
// far (read more), or in the whole file (cut short).
struct NeedMore {};

// Bounds-checked little-endian reads over the start of an OpenEXR file.
class Cursor {
public:
    Cursor(const std::uint8_t* bytes, std::size_t size, std::uint64_t fileSize, const std::string& name)
        : p_(bytes), size_(size), fileSize_(fileSize), name_(name) {}

    std::size_t at() const { return at_; }

    void need(std::uint64_t n, const std::string& what) {
        if (at_ + n <= size_) return;
        if (size_ < fileSize_) throw NeedMore{};
        throw FileError(name_, "the OpenEXR header is cut short: " + what + " runs past the end of the file (" +
                                   std::to_string(fileSize_) + " bytes)");
    }
    std::uint8_t u8(const std::string& what) {
        need(1, what);
        return p_[at_++];
    }
    std::int32_t i32(const std::string& what) {
        need(4, what);
        std::uint32_t v = 0;
        for (int i = 3; i >= 0; --i) v = (v << 8) | p_[at_ + static_cast<std::size_t>(i)];
        at_ += 4;
        return static_cast<std::int32_t>(v);
    }
    // A null-terminated string of at most `max` characters.
    std::string text(std::size_t max, const std::string& what) {
        std::string s;
        for (;;) {
            const std::uint8_t c = u8(what);
            if (c == 0) return s;
            if (s.size() >= max)
                throw FileError(name_, "the OpenEXR header is damaged: " + what + " is longer than " + std::to_string(max) +
                                           " characters (at byte " + std::to_string(at_) + ")");
            s.push_back(static_cast<char>(c));
        }
    }
    void skip(std::uint64_t n, const std::string& what) {
        need(n, what);
        at_ += static_cast<std::size_t>(n);
    }

private:
    const std::uint8_t* p_;
    std::size_t size_;
    std::uint64_t fileSize_;
    const std::string& name_;
    std::size_t at_ = 0;
};

struct Box {
    std::int64_t xMin = 0, yMin = 0, xMax = -1, yMax = -1;
    std::int64_t width() const { return xMax - xMin + 1; }
    std::int64_t height() const { return yMax - yMin + 1; }
};

struct Part {
    std::optional<Box> dataWindow, displayWindow;
    int channels = -1;
    std::optional<std::pair<std::uint32_t, std::uint32_t>> tiles;
    int levelMode = 0;  // tiles: 0 one level, 1 mipmaps, 2 ripmaps
    std::string type;
};

// OpenEXR keeps coordinates within +-(INT_MAX / 2) so that widths fit an int.
constexpr std::int64_t kMaxCoordinate = INT_MAX / 2;

void checkBox(const Box& b, const std::string& which, const std::string& name) {
    auto text = [&] {
        return "(" + std::to_string(b.xMin) + ", " + std::to_string(b.yMin) + ") to (" + std::to_string(b.xMax) + ", " +
               std::to_string(b.yMax) + ")";
    };
    if (b.xMax < b.xMin || b.yMax < b.yMin)
        throw FileError(name, "the OpenEXR " + which + " " + text() + " is empty (its maximum is below its minimum)");
    for (std::int64_t v : {b.xMin, b.yMin, b.xMax, b.yMax})
        if (v < -kMaxCoordinate || v > kMaxCoordinate)
            throw FileError(name, "the OpenEXR " + which + " " + text() + " has coordinates beyond +-" +
                                      std::to_string(kMaxCoordinate) + " (a damaged header)");
}

}  // namespace

std::uint64_t imageMemoryLimit() {
    const char* env = std::getenv(kImageLimitVariable);
    if (!env || !*env) return kDefaultImageLimitMB * 1024 * 1024;
    errno = 0;
    char* end = nullptr;
    const unsigned long long v = std::strtoull(env, &end, 10);
    // Up to 2^40 MiB: beyond it the byte count overflows 64 bits.
    if (errno != 0 || end == env || *end != '\0' || v < 1 || v > (1ULL << 40) || *env == '-' || *env == '+')
        throw Error(std::string(kImageLimitVariable) + " is '" + env +
                    "': it takes a whole number of megabytes, at least 1 (the image memory limit; default " +
                    std::to_string(kDefaultImageLimitMB) + ")");
    return static_cast<std::uint64_t>(v) * 1024 * 1024;
}

void checkImageBudget(std::uint64_t width, std::uint64_t height, int channels, std::uint64_t bytesPerPixel,
                      const std::string& name, const std::string& what) {
    const std::uint64_t limit = imageMemoryLimit();
    // In long double: 2^31 x 2^31 x 4 bytes overflows 64 bits.
    const long double bytes = static_cast<long double>(width) * static_cast<long double>(height) *
                              static_cast<long double>(bytesPerPixel);
    if (bytes <= static_cast<long double>(limit)) return;
    throw FileError(name, what + " is " + std::to_string(width) + " x " + std::to_string(height) + " pixels of " +
                              std::to_string(channels) + (channels == 1 ? " channel: " : " channels: ") +
                              mb(static_cast<double>(bytes)) + " MB decoded, over " + limitText(limit));
}

bool isExr(const std::uint8_t* bytes, std::size_t size) {
    return size >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

std::size_t checkExrHeader(const std::uint8_t* bytes, std::size_t size, std::uint64_t fileSize, const std::string& name,
                           std::uint64_t bytesPerChannel) {
    if (!isExr(bytes, size)) return 0;
    try {
        Cursor c(bytes, size, fileSize, name);
        c.skip(4, "the magic number");
        const std::uint32_t version = static_cast<std::uint32_t>(c.i32("the version field"));
        if ((version & 0xff) != 2)
            throw FileError(name, "OpenEXR version " + std::to_string(version & 0xff) + " is not readable (2 is)");
        const bool tiledFlag = version & 0x200, longNames = version & 0x400, deep = version & 0x800,
                   multipart = version & 0x1000;
        if (version & ~0x1effu)
            throw FileError(name, "the OpenEXR header is damaged: unknown flags in the version field (0x" + [&] {
                char b[16];
                std::snprintf(b, sizeof b, "%x", version);
                return std::string(b);
            }() + ")");
        if (deep) throw FileError(name, "deep OpenEXR images (samples per pixel) are not supported");
        const std::size_t maxName = longNames ? 255 : 31;
        std::vector<Part> parts;
        for (;;) {
            Part part;
            bool empty = true;
            for (;;) {
                const std::string attr = c.text(maxName, "an attribute name");
                if (attr.empty()) break;
                empty = false;
                const std::string where = "attribute '" + escaped(attr) + "'";
                const std::string type = c.text(maxName, "the type of " + where);
                const std::string typeShown = escaped(type);
                const std::int32_t length = c.i32("the size of " + where);
                if (length < 0)
                    throw FileError(name, "the OpenEXR header is damaged: " + where + " has a negative size (" +
                                              std::to_string(length) + ")");
                const std::size_t start = c.at();
                c.need(static_cast<std::uint64_t>(length), where);
                auto value = [&](std::size_t want) {
                    if (static_cast<std::size_t>(length) < want)
                        throw FileError(name, "the OpenEXR header is damaged: " + where + " is " + std::to_string(length) +
                                                  " bytes, too short for a " + typeShown);
                };
                if ((attr == "dataWindow" || attr == "displayWindow") && type == "box2i") {
                    value(16);
                    Box b;
                    b.xMin = c.i32(where);
                    b.yMin = c.i32(where);
                    b.xMax = c.i32(where);
                    b.yMax = c.i32(where);
                    (attr == "dataWindow" ? part.dataWindow : part.displayWindow) = b;
                } else if (attr == "channels" && type == "chlist") {
                    int n = 0;
                    for (;;) {
                        if (c.at() >= start + static_cast<std::size_t>(length))
                            throw FileError(name, "the OpenEXR header is damaged: the channel list runs past its attribute");
                        const std::string rawName = c.text(maxName, "a channel name");
                        if (rawName.empty()) break;
                        const std::string ch = escaped(rawName);
                        const std::int32_t pixelType = c.i32("channel '" + ch + "'");
                        c.skip(4, "channel '" + ch + "'");
                        const std::int32_t xs = c.i32("channel '" + ch + "'"), ys = c.i32("channel '" + ch + "'");
                        if (pixelType < 0 || pixelType > 2)
                            throw FileError(name, "the OpenEXR header is damaged: channel '" + ch + "' has pixel type " +
                                                      std::to_string(pixelType) + " (0 to 2 exist)");
                        if (xs < 1 || ys < 1)
                            throw FileError(name, "the OpenEXR header is damaged: channel '" + ch + "' has sampling " +
                                                      std::to_string(xs) + " x " + std::to_string(ys));
                        ++n;
                    }
                    part.channels = n;
                } else if (attr == "tiles" && type == "tiledesc") {
                    value(9);
                    const std::uint32_t tx = static_cast<std::uint32_t>(c.i32(where));
                    const std::uint32_t ty = static_cast<std::uint32_t>(c.i32(where));
                    part.tiles = {tx, ty};
                    part.levelMode = c.u8(where) & 0x0f;
                } else if (attr == "preview" && type == "preview") {
                    // OpenEXR allocates width x height x 4 bytes from these two numbers.
                    value(8);
                    const std::uint64_t w = static_cast<std::uint32_t>(c.i32(where)), h = static_cast<std::uint32_t>(c.i32(where));
                    if (w * h * 4 != static_cast<std::uint64_t>(length) - 8)
                        throw FileError(name, "the OpenEXR header is damaged: its preview image is " + std::to_string(w) + " x " +
                                                  std::to_string(h) + " pixels but the attribute holds " +
                                                  std::to_string(length - 8) + " bytes of them");
                } else if (attr == "type" && type == "string") {
                    std::string s;
                    for (std::int32_t i = 0; i < length; ++i) s.push_back(static_cast<char>(c.u8(where)));
                    part.type = s;
                }
                // The value's full size, whatever of it was read.
                if (c.at() > start + static_cast<std::size_t>(length))
                    throw FileError(name, "the OpenEXR header is damaged: " + where + " is longer than its size (" +
                                              std::to_string(length) + " bytes)");
                c.skip(start + static_cast<std::size_t>(length) - c.at(), where);
            }
            if (empty && multipart && !parts.empty()) break;  // the empty header ending a multi-part file
            if (empty) throw FileError(name, "the OpenEXR header is damaged: it has no attributes");
            parts.push_back(part);
            if (!multipart) break;
            if (parts.size() > 100000) throw FileError(name, "the OpenEXR header is damaged: more than 100000 parts");
        }
        for (std::size_t i = 0; i < parts.size(); ++i) {
            const Part& p = parts[i];
            const std::string part = parts.size() > 1 ? "part " + std::to_string(i) + ": " : "";
            if (p.type == "deepscanline" || p.type == "deeptile")
                throw FileError(name, part + "deep OpenEXR images (samples per pixel) are not supported");
            if (!p.dataWindow) throw FileError(name, part + "the OpenEXR header has no data window (a damaged header)");
            if (!p.displayWindow) throw FileError(name, part + "the OpenEXR header has no display window (a damaged header)");
            if (p.channels < 0) throw FileError(name, part + "the OpenEXR header has no channel list (a damaged header)");
            if (p.channels == 0) throw FileError(name, part + "the OpenEXR image has no channels");
            if (p.channels > 1024)
                throw FileError(name, part + "the OpenEXR image has " + std::to_string(p.channels) +
                                          " channels (at most 1024 are read; a damaged header?)");
            checkBox(*p.dataWindow, "data window", name);
            checkBox(*p.displayWindow, "display window", name);
            const Box& d = *p.dataWindow;
            checkImageBudget(static_cast<std::uint64_t>(d.width()), static_cast<std::uint64_t>(d.height()), p.channels,
                             static_cast<std::uint64_t>(p.channels) * bytesPerChannel, name,
                             part + "the OpenEXR data window " + "(" + std::to_string(d.xMin) + ", " + std::to_string(d.yMin) +
                                 ") to (" + std::to_string(d.xMax) + ", " + std::to_string(d.yMax) + ")");
            const bool tiled = p.type == "tiledimage" || (p.type.empty() && tiledFlag);
            if (tiled) {
                if (!p.tiles) throw FileError(name, part + "the OpenEXR image is tiled but has no tile description");
                const auto [tx, ty] = *p.tiles;
                if (tx < 1 || ty < 1 || tx > static_cast<std::uint32_t>(INT_MAX) || ty > static_cast<std::uint32_t>(INT_MAX))
                    throw FileError(name, part + "the OpenEXR tiles are " + std::to_string(tx) + " x " + std::to_string(ty) +
                                              " pixels (a damaged header)");
                // A decoder holds whole tiles, 4 bytes a channel at most.
                checkImageBudget(tx, ty, p.channels, static_cast<std::uint64_t>(p.channels) * 4, name, part + "one OpenEXR tile");
                if (p.levelMode > 2)
                    throw FileError(name, part + "the OpenEXR tile level mode " + std::to_string(p.levelMode) +
                                              " is unknown (a damaged header)");
                // The table of tile offsets: 8 bytes a tile, every level
                // (mipmaps add at most a third, ripmaps three times).
                const std::uint64_t across = (static_cast<std::uint64_t>(d.width()) + tx - 1) / tx;
                const std::uint64_t down = (static_cast<std::uint64_t>(d.height()) + ty - 1) / ty;
                const std::uint64_t levels = p.levelMode == 0 ? 3 : p.levelMode == 1 ? 4 : 12;  // in thirds
                const long double table = static_cast<long double>(across) * down * 8 * levels / 3;
                if (table > static_cast<long double>(imageMemoryLimit()))
                    throw FileError(name, part + "the OpenEXR data window of " + std::to_string(d.width()) + " x " +
                                              std::to_string(d.height()) + " pixels in tiles of " + std::to_string(tx) +
                                              " x " + std::to_string(ty) + " needs a table of " + std::to_string(across * down) +
                                              " tile offsets, over " + limitText(imageMemoryLimit()));
            }
        }
        return c.at();
    } catch (const NeedMore&) {
        return 0;
    }
}

void checkExrFile(const std::string& path, std::uint64_t bytesPerChannel) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return;  // the decoder says why
    const std::uint64_t fileSize = static_cast<std::uint64_t>(in.tellg());
    std::vector<std::uint8_t> head;
    // The headers are small (previews aside): read 64 KiB, then more as needed.
    for (std::uint64_t want = 64 * 1024;; want *= 4) {
        const std::uint64_t n = std::min(want, fileSize);
        head.resize(static_cast<std::size_t>(n));
        in.seekg(0);
        if (!in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(n))) return;
        if (!isExr(head.data(), head.size())) return;
        if (checkExrHeader(head.data(), head.size(), fileSize, path, bytesPerChannel) > 0 || n == fileSize) return;
    }
}

}  // namespace dw

#include "renderer/io/ImageIO.h"

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <filesystem>

#include "renderer/Error.h"
#include "renderer/io/ImageLimits.h"
#include "renderer/io/TextFile.h"
#include "renderer/io/StderrCapture.h"

namespace dw {

namespace OIIO = OIIO_NAMESPACE;

void FloatImage::flipVertically() {
    const size_t row = static_cast<size_t>(width) * channels;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + y * row, pixels.begin() + (y + 1) * row,
                         pixels.begin() + (height - 1 - y) * row);
}

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

// The budget (ImageLimits.h) for what the decoder's header says, before any
// pixel is read: `bytesPerChannel` in the decoded copy, plus `extraPerPixel`.
void checkSpec(const OIIO::ImageSpec& spec, const std::string& name, std::uint64_t bytesPerChannel,
               std::uint64_t extraPerPixel) {
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw FileError(name, "image has no pixels");
    if (spec.deep) throw FileError(name, "deep images (samples per pixel) are not supported");
    checkImageBudget(static_cast<std::uint64_t>(spec.width), static_cast<std::uint64_t>(spec.height), spec.nchannels,
                     static_cast<std::uint64_t>(spec.nchannels) * bytesPerChannel + extraPerPixel, name);
    if (spec.tile_width > 0)
        checkImageBudget(static_cast<std::uint64_t>(spec.tile_width), static_cast<std::uint64_t>(spec.tile_height),
                         spec.nchannels, static_cast<std::uint64_t>(spec.nchannels) * 4, name, "one tile");
}

// OIIO's own size check (limits:imagesize_MB, set to the same budget) speaks
// of its attribute; the workbench's words say how to raise the workbench's limit.
// OIIO joins the decoder's messages with newlines ("Read error: hit end of
// file\nPNG read error: IDAT: ..."): the CLI's promise is one line per problem.
std::string oneLine(const std::string& text) {
    std::string out, line;
    auto flush = [&] {
        const size_t b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t");
        if (b != std::string::npos) out += (out.empty() ? "" : "; ") + line.substr(b, e - b + 1);
        line.clear();
    };
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            flush();
        } else if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) {
            // A control byte (a damaged file's attribute name, quoted by the decoder) as \xNN.
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
            line += hex;
        } else {
            line += c;
        }
    }
    flush();
    return out;
}

std::string openError(const std::string& raw) {
    const std::string error = oneLine(raw);
    if (error.find("limits:imagesize_MB") != std::string::npos) {
        const std::size_t cut = error.find(". Possible corrupt");
        return (cut == std::string::npos ? error : error.substr(0, cut)) + ": over the image memory limit of " +
               std::to_string(imageMemoryLimit() / (1024 * 1024)) + " MB (set " + kImageLimitVariable + "=MB to raise it)";
    }
    return error;
}

// OIIO's size check at open uses the workbench's budget.
void applyLimits() {
    const int mb = static_cast<int>(std::min<std::uint64_t>(imageMemoryLimit() / (1024 * 1024), INT_MAX));
    OIIO::attribute("limits:imagesize_MB", mb);
}

// A decoder's exception (std::bad_alloc from a damaged file's sizes, or any
// other) becomes an error naming the file.
template <typename F>
auto guarded(const std::string& name, F&& decode) -> decltype(decode()) {
    try {
        return decode();
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw FileError(name, "cannot decode image: out of memory (the file's sizes are damaged, or " +
                                  std::string("the image is larger than this machine can hold)"));
    } catch (const std::exception& e) {
        throw FileError(name, std::string("cannot decode image: ") + e.what());
    }
}

Image toRgba8(std::unique_ptr<OIIO::ImageInput> in, const std::string& name) {
    const OIIO::ImageSpec& spec = in->spec();
    checkSpec(spec, name, 1, 4);  // the decoded bytes, then RGBA
    std::vector<std::uint8_t> raw(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, raw.data()))
        throw FileError(name, "cannot decode image: " + oneLine(in->geterror()));
    Image img;
    img.width = spec.width;
    img.height = spec.height;
    img.source = name;
    img.rgba.resize(static_cast<size_t>(img.width) * img.height * 4);
    const int c = spec.nchannels;
    for (size_t p = 0; p < static_cast<size_t>(img.width) * img.height; ++p) {
        const std::uint8_t* s = &raw[p * c];
        std::uint8_t* d = &img.rgba[p * 4];
        if (c == 1 || c == 2) {
            d[0] = d[1] = d[2] = s[0];
            d[3] = c == 2 ? s[1] : 255;
        } else {
            d[0] = s[0];
            d[1] = s[1];
            d[2] = s[2];
            d[3] = c >= 4 ? s[3] : 255;
        }
    }
    return img;
}

// Textures are colour and coverage side by side (glTF 2.0 "Images": alpha is
// straight, not premultiplied). OIIO's readers premultiply by default (PNG,
// WebP, TIFF), which would darken opaque materials wherever alpha < 1; this
// configuration asks for the values as stored.
OIIO::ImageSpec straightAlphaConfig() {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    return config;
}

}  // namespace

Image loadImage8(const std::string& path) {
    requireRegularFile(path, "image file not found", "cannot read image");
    checkExrFile(path, 1);  // before OpenEXR allocates from the header
    applyLimits();
    StderrCapture quiet;  // libpng/libjpeg's own lines; OIIO's error says the same
    return guarded(path, [&] {
        const OIIO::ImageSpec config = straightAlphaConfig();
        auto in = OIIO::ImageInput::open(path, &config);
        if (!in) throw FileError(path, "cannot read image: " + openError(OIIO::geterror()));
        return toRgba8(std::move(in), path);
    });
}

Image decodeImage8(const std::uint8_t* bytes, size_t size, const std::string& nameHint,
                   const std::string& mimeType) {
    // The bytes' signature decides (a file's URI may not say, and a data URI's
    // MIME type may be wrong); the MIME type only when the signature is unknown.
    std::string ext = ".png";
    if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) ext = ".jpg";
    else if (size >= 12 && std::memcmp(bytes, "RIFF", 4) == 0 && std::memcmp(bytes + 8, "WEBP", 4) == 0) ext = ".webp";
    else if (size >= 8 && std::memcmp(bytes, "\x89PNG", 4) == 0) ext = ".png";
    else if (mimeType == "image/jpeg") ext = ".jpg";
    else if (mimeType == "image/webp") ext = ".webp";
    else if (mimeType == "image/ktx2") ext = ".ktx2";
    if (isExr(bytes, size)) checkExrHeader(bytes, size, size, nameHint, 1);
    applyLimits();
    OIIO::Filesystem::IOMemReader reader(const_cast<std::uint8_t*>(bytes), size);
    StderrCapture quiet;  // libpng/libjpeg's own lines; OIIO's error says the same
    // OIIO 2.4 ignores the proxy argument when a config spec is passed too;
    // the config's "oiio:ioproxy" attribute carries it instead.
    OIIO::ImageSpec config = straightAlphaConfig();
    OIIO::Filesystem::IOProxy* proxy = &reader;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    return guarded(nameHint, [&] {
        auto in = OIIO::ImageInput::open("memory" + ext, &config);
        if (!in) throw FileError(nameHint, "cannot decode embedded image: " + openError(OIIO::geterror()));
        return toRgba8(std::move(in), nameHint);
    });
}

namespace {

// Why a decode failed when the decoder says nothing (OIIO's PFM reader on a
// file cut short): the file's size against what its pixels need.
std::string decodeFailure(OIIO::ImageInput& in, const std::string& path) {
    const std::string said = oneLine(in.geterror());
    if (!said.empty()) return said;
    const OIIO::ImageSpec& spec = in.spec();
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    const std::uint64_t pixelBytes = static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height) *
                                     static_cast<std::uint64_t>(spec.nchannels) * spec.format.size();
    if (!ec && size < pixelBytes)
        return "the file is cut short: it is " + std::to_string(size) + " bytes, and its " + std::to_string(spec.width) +
               " x " + std::to_string(spec.height) + " pixels of " + std::to_string(spec.nchannels) + " channel(s) take " +
               std::to_string(pixelBytes) + " bytes after the header";
    return std::string("the ") + in.format_name() + " decoder failed without saying why (a damaged or cut-short file)";
}

}  // namespace

FloatImage loadImageFloat(const std::string& path) {
    requireRegularFile(path, "image file not found", "cannot read image");
    checkExrFile(path, 4);  // before OpenEXR allocates from the header
    applyLimits();
    StderrCapture quiet;  // libpng/libjpeg's own lines; OIIO's error says the same
    return guarded(path, [&] {
        auto in = OIIO::ImageInput::open(path);
        if (!in) throw FileError(path, "cannot read image: " + openError(OIIO::geterror()));
        const OIIO::ImageSpec& spec = in->spec();
        checkSpec(spec, path, 4, 0);
        FloatImage img;
        img.width = spec.width;
        img.height = spec.height;
        img.channels = spec.nchannels;
        img.pixels.resize(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
            throw FileError(path, "cannot decode image: " + decodeFailure(*in, path));
        return img;
    });
}

ImageShape readImageShape(const std::string& path) {
    requireRegularFile(path, "image file not found", "cannot read image");
    checkExrFile(path, 4);  // a damaged OpenEXR header is refused before OpenEXR allocates from it
    applyLimits();
    StderrCapture quiet;
    return guarded(path, [&] {
        auto in = OIIO::ImageInput::open(path);
        if (!in) throw FileError(path, "cannot read image: " + openError(OIIO::geterror()));
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw FileError(path, "image has no pixels");
        return ImageShape{spec.width, spec.height, spec.nchannels};
    });
}

bool isFloatFormat(const std::string& path) {
    const std::string ext = lower(std::filesystem::path(path).extension().string());
    return ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".pfm";
}

namespace {

// The pixels as the writer takes them: floats, or 8-bit display values
// (clamped; a 2-channel buffer padded with zero blue).
struct EncodedPixels {
    OIIO::ImageSpec spec;
    std::vector<std::uint8_t> bytes;  // 8-bit formats
};

EncodedPixels pixelsToWrite(const FloatImage& image, bool asFloat, const std::vector<std::string>& channelNames) {
    int channels = image.channels;
    const bool pad = !asFloat && channels == 2;
    if (pad) channels = 3;
    EncodedPixels e;
    e.spec = OIIO::ImageSpec(image.width, image.height, channels, asFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!channelNames.empty() && static_cast<int>(channelNames.size()) == image.channels && !pad)
        e.spec.channelnames = channelNames;
    if (asFloat) return e;
    e.bytes.resize(static_cast<size_t>(image.width) * image.height * channels);
    for (size_t p = 0; p < static_cast<size_t>(image.width) * image.height; ++p)
        for (int c = 0; c < channels; ++c) {
            const float v = c < image.channels ? image.pixels[p * image.channels + c] : 0.0f;
            const float clamped = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
            e.bytes[p * channels + c] = static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
        }
    return e;
}

// Encodes with `out` to `target` (a file name or, through `proxy`, memory).
void encode(OIIO::ImageOutput& out, const std::string& target, const EncodedPixels& e, const FloatImage& image,
            const std::string& path) {
    if (!out.open(target, e.spec)) throw FileError(path, "cannot open for writing: " + oneLine(out.geterror()));
    const bool ok = e.bytes.empty() ? out.write_image(OIIO::TypeDesc::FLOAT, image.pixels.data())
                                    : out.write_image(OIIO::TypeDesc::UINT8, e.bytes.data());
    if (!ok || !out.close()) throw FileError(path, "cannot write image: " + oneLine(out.geterror()));
}

}  // namespace

void writeImage(const std::string& path, const FloatImage& image, const std::vector<std::string>& channelNames) {
    namespace fs = std::filesystem;
    const bool asFloat = isFloatFormat(path);
    const std::string ext = lower(fs::path(path).extension().string());
    if (ext.empty()) throw FileError(path, "output needs an extension (.png or .exr)");
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw FileError(path, "no image writer for '" + ext + "' files");
    const EncodedPixels e = pixelsToWrite(image, asFloat, channelNames);
    // A file whole or not at all. The writer's own file writes can fail
    // unseen (libpng's buffered fwrite on a full disk left a 0-byte PNG and
    // "wrote"), so the image is encoded in memory where the writer can and
    // the bytes written by writeFileAtomically, which checks every write
    // (and writes a device or pipe in place); else encoded to a temporary
    // file that must read back.
    if (out->supports("ioproxy")) {
        std::vector<unsigned char> bytes;
        OIIO::Filesystem::IOVecOutput memory(bytes);
        if (!out->set_ioproxy(&memory)) throw FileError(path, "cannot write image: " + oneLine(out->geterror()));
        encode(*out, path, e, image, path);
        writeFileAtomically(path, std::string(bytes.begin(), bytes.end()));  // FileError "cannot save: ..." says why
        return;
    }
    std::error_code ec;
    if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
        encode(*out, path, e, image, path);  // a device or a pipe: written in place, never renamed over
        return;
    }
    const fs::path target(path);
    const fs::path tmp = (target.parent_path().empty() ? fs::path(".") : target.parent_path()) /
                         ("." + target.filename().string() + ".tmp" + std::to_string(::getpid()) + ext);
    try {
        encode(*out, tmp.string(), e, image, path);
        out.reset();
        const ImageShape shape = readImageShape(tmp.string());
        if (shape.width != image.width || shape.height != image.height)
            throw FileError(path, "cannot write image: it did not read back (disk full?)");
    } catch (const FileError&) {
        fs::remove(tmp, ec);
        throw;
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw FileError(path, "cannot write image: " + ec.message());
    }
}

ImageDifference compareImages(const FloatImage& a, const FloatImage& b, float failThreshold) {
    if (a.width != b.width || a.height != b.height)
        throw Error("cannot compare images of different sizes (" + std::to_string(a.width) + "x" +
                    std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                    std::to_string(b.height) + ")");
    const int channels = std::min(a.channels, b.channels);
    auto toBuf = [channels](const FloatImage& img) {
        OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, img.channels, OIIO::TypeDesc::FLOAT),
                           const_cast<float*>(img.pixels.data()));
        return OIIO::ImageBufAlgo::channels(buf, channels, {});
    };
    const OIIO::ImageBuf A = toBuf(a), B = toBuf(b);
    const auto r = OIIO::ImageBufAlgo::compare(A, B, failThreshold, failThreshold);
    ImageDifference d;
    d.meanError = r.meanerror;
    d.rmsError = r.rms_error;
    d.psnr = r.PSNR;
    d.maxError = r.maxerror;
    d.maxX = r.maxx;
    d.maxY = r.maxy;
    d.maxChannel = r.maxc;
    d.failCount = static_cast<long long>(r.nfail);
    d.pixelCount = static_cast<long long>(a.width) * a.height;
    return d;
}

}  // namespace dw

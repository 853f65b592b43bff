// Issue 32's reader faults: every text read is bounded (a device such as
// /dev/zero, a pipe that does not end, a file over the limit: refused by name,
// never read until memory runs out, never blocking on a pipe without a
// writer); a record or a preset given as a scene is named as what it is; a
// damaged EXR's attribute names print escaped on one line; a PFM cut short
// says why it cannot be decoded.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/io/ImageLimits.h"
#include "renderer/io/TextFile.h"
#include "renderer/scene/SceneFileKind.h"
#include "renderer/scene/SceneLoader.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

const fs::path& dir() {
    static const fs::path d = [] {
        fs::path p = fs::temp_directory_path() / ("dw-bounded-read-tests-" + std::to_string(::getpid()));
        fs::create_directories(p);
        return p;
    }();
    return d;
}

fs::path writeBytes(const std::string& name, const std::string& bytes) {
    const fs::path p = dir() / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

// The FileError's text, or "no error".
template <typename F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const FileError& e) {
        return e.what();
    }
    return "no error";
}

#define EXPECT_HAS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

}  // namespace

TEST(BoundedRead, ADeviceIsRefusedByNameNotReadUntilMemoryRunsOut) {
    const auto start = std::chrono::steady_clock::now();
    EXPECT_HAS(errorOf([] { readWholeFile("/dev/zero", "not found", "cannot read scene file"); }),
               "/dev/zero: cannot read scene file: it is a device, not a file");
    // Under a .json name, through the scene loader and the JSON reader.
    const fs::path link = dir() / "zero.json";
    fs::remove(link);
    fs::create_symlink("/dev/zero", link);
    EXPECT_HAS(errorOf([&] { loadScene(link.string()); }), "zero.json: cannot read scene file: it is a device");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(BoundedRead, AFileOverTheLimitIsRefusedFromItsSizeAndAPipeAtTheLimit) {
    const fs::path big = writeBytes("big.json", std::string(2000, ' '));
    EXPECT_HAS(errorOf([&] { readWholeFile(big.string(), "not found", "cannot read", 1024); }),
               "big.json: cannot read: it is 2000 bytes, over the limit of 1024 bytes for a file read whole");
    EXPECT_EQ(readWholeFile(big.string(), "not found", "cannot read", 2000).size(), 2000u);
    EXPECT_HAS(errorOf([&] { readWholeFile((dir() / "none.json").string(), "scene file not found", "cannot read"); }),
               "none.json: scene file not found");
    EXPECT_HAS(errorOf([&] { readWholeFile(dir().string(), "not found", "cannot read"); }), "cannot read: it is a folder");

    // A pipe that gives more than the limit: refused after the limit, not read on.
    const fs::path fifo = dir() / "endless.json";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const int writer = ::open(fifo.c_str(), O_RDWR | O_CLOEXEC);  // a writer that stays: the pipe never ends
    ASSERT_GE(writer, 0);
    const std::string chunk(4096, 'x');
    ASSERT_EQ(::write(writer, chunk.data(), chunk.size()), static_cast<ssize_t>(chunk.size()));
    EXPECT_HAS(errorOf([&] { readWholeFile(fifo.string(), "not found", "cannot read", 1024); }),
               "endless.json: cannot read: it holds more than 1024 bytes");
    ::close(writer);
}

TEST(BoundedRead, APipeWithoutAWriterReadsAsEmptyWithoutBlocking) {
    const fs::path fifo = dir() / "no-writer.json";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(readWholeFile(fifo.string(), "not found", "cannot read"), "");
    // The scene loader then says the file is not JSON, naming it.
    EXPECT_HAS(errorOf([&] { loadScene(fifo.string()); }), "no-writer.json");
}

TEST(BoundedRead, AnImagePathThatIsADevicePipeOrFolderIsRefusedByNameWithoutBlocking) {
    // The image decoders open the path themselves: each reader checks that it
    // is a regular file first (compare /dev/zero spun at 100% CPU).
    const fs::path zero = dir() / "zero.exr";
    fs::remove(zero);
    fs::create_symlink("/dev/zero", zero);
    const fs::path fifo = dir() / "no-writer.png";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const fs::path folder = dir() / "folder.hdr";
    fs::create_directories(folder);
    const auto start = std::chrono::steady_clock::now();
    for (const auto& [path, what] : {std::pair{fs::path("/dev/zero"), std::string("it is a device, not a file")},
                                     std::pair{zero, std::string("it is a device, not a file")},
                                     std::pair{fifo, std::string("it is a pipe or socket, not a file")},
                                     std::pair{folder, std::string("it is a folder, not a file")}}) {
        const std::string p = path.string();
        EXPECT_HAS(errorOf([&] { loadImageFloat(p); }), p + ": cannot read image: " + what);
        EXPECT_HAS(errorOf([&] { loadImage8(p); }), p + ": cannot read image: " + what);
        EXPECT_HAS(errorOf([&] { readImageShape(p); }), p + ": cannot read image: " + what);
    }
    EXPECT_HAS(errorOf([&] { loadImageFloat((dir() / "none.png").string()); }), "none.png: image file not found");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(BoundedRead, ADeviceIsWrittenInPlaceAndItsFailureSaidNeverRenamedOver) {
    // A record written to /dev/full replaced the device with a file (the
    // atomic write renamed its temporary over it), and later writes there
    // "succeeded". A device is written in place and its write checked.
    struct stat before {};
    ASSERT_EQ(::stat("/dev/full", &before), 0);
    ASSERT_TRUE(S_ISCHR(before.st_mode));
    EXPECT_HAS(errorOf([] { writeFileAtomically("/dev/full", "a record"); }), "/dev/full: cannot save: writing failed");
    // An image through a link named .png (the writer goes by the extension).
    const fs::path link = dir() / "full.png";
    fs::remove(link);
    fs::create_symlink("/dev/full", link);
    EXPECT_HAS(errorOf([&] {
                   FloatImage image;
                   image.width = image.height = 64;
                   image.channels = 3;
                   image.pixels.assign(64 * 64 * 3, 0.5f);
                   writeImage(link.string(), image);
               }),
               "full.png: cannot save: writing failed");
    struct stat after {};
    ASSERT_EQ(::stat("/dev/full", &after), 0);
    EXPECT_TRUE(S_ISCHR(after.st_mode)) << "/dev/full is no longer a device";
    EXPECT_TRUE(fs::is_symlink(link));
    writeFileAtomically("/dev/null", "into the void");  // a device that takes it: no error
}

TEST(BoundedRead, AWriteGoesThroughALinkAndAPipeWithNoReaderIsRefused) {
    // A link to a file: the file it names is written, the link stays a link.
    const fs::path real = writeBytes("real.json", "old");
    const fs::path link = dir() / "link.json";
    fs::remove(link);
    fs::create_symlink(real, link);
    writeFileAtomically(link.string(), "new");
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(readWholeFile(real.string(), "not found", "cannot read"), "new");
    // A pipe nobody reads: refused at once (opening it waited forever).
    const fs::path fifo = dir() / "nobody-reads.json";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    EXPECT_HAS(errorOf([&] { writeFileAtomically(fifo.string(), "a record"); }), "it is a pipe with no reader");
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    // With a reader it is written in place.
    const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(reader, 0);
    writeFileAtomically(fifo.string(), "a record");
    char got[16] = {};
    EXPECT_EQ(::read(reader, got, sizeof got), 8);
    EXPECT_EQ(std::string(got, 8), "a record");
    ::close(reader);
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(BoundedRead, RecordsAndPresetsAreToldFromScenes) {
    const fs::path record = writeBytes("rec.json", R"({"format": "deferred-workbench record", "version": 3,
        "command": "render", "scene": {"spec": "spheres"}})");
    const fs::path preset = writeBytes("look.json", R"({"format": "deferred-workbench preset", "name": "look",
        "scene": "fire", "camera": {"pos": [0, 1, 2]}, "knobs": {"ssao.samples": 8}})");
    const fs::path bare = writeBytes("bare-preset.json", R"({"knobs": {"ssao.samples": 8}})");
    const fs::path scene = writeBytes("scene.json", R"({"name": "s", "objects": []})");
    // A scene with a stray "knobs" key is still a scene (its loader warns about the key).
    const fs::path sceneWithKnobs = writeBytes("scene-knobs.json", R"({"lights": [], "knobs": {"ssao.samples": 8}})");
    const fs::path other = writeBytes("other.json", R"({"format": "something else", "knobs": {}})");
    const fs::path broken = writeBytes("broken.json", R"({"format": )");
    EXPECT_EQ(classifySceneFile(record.string()), SceneFileKind::Record);
    EXPECT_EQ(classifySceneFile(preset.string()), SceneFileKind::Preset);
    EXPECT_EQ(classifySceneFile(bare.string()), SceneFileKind::Preset);
    EXPECT_EQ(classifySceneFile(scene.string()), SceneFileKind::Scene);
    EXPECT_EQ(classifySceneFile(sceneWithKnobs.string()), SceneFileKind::Scene);
    EXPECT_EQ(classifySceneFile(other.string()), SceneFileKind::Scene);
    EXPECT_EQ(classifySceneFile(broken.string()), SceneFileKind::Scene);  // the scene loader says what is wrong
    EXPECT_EQ(classifySceneFile((dir() / "missing.json").string()), SceneFileKind::Scene);
    EXPECT_EQ(classifySceneFile("spheres"), SceneFileKind::Scene);

    // The loader refuses the record and the preset, saying what opens them.
    const std::string r = errorOf([&] { loadScene(record.string()); });
    EXPECT_HAS(r, record.string() + ": this is an experiment record (\"format\": \"deferred-workbench record\"), not a scene: "
                                    "`deferred-workbench replay " + record.string() + "` renders it again");
    EXPECT_HAS(r, "here 'spheres'");
    const std::string p = errorOf([&] { loadScene(preset.string()); });
    EXPECT_HAS(p, preset.string() + ": this is a preset (knobs and a camera), not a scene: give it as --preset " +
                      preset.string() + " (preset= in Python); it names its scene, 'fire'");
    EXPECT_HAS(errorOf([&] { loadScene(bare.string()); }), "this is a preset (knobs), not a scene: give it as --preset");
    EXPECT_EQ(errorOf([&] { refuseNonSceneFile(scene.string()); }), "no error");
}

TEST(BoundedRead, ADamagedExrsAttributeNamesPrintEscapedOnOneLine) {
    // An attribute whose "name" holds control bytes (a newline, an escape
    // sequence), then a negative size: the message quotes the name escaped.
    std::string exr("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    exr += std::string("a\x01\x1b[31mb\nc\\", 11) + std::string(1, '\0');
    exr += std::string("int") + std::string(1, '\0');
    exr += std::string("\xff\xff\xff\xff", 4);
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(exr.data());
    const std::string e = errorOf([&] { checkExrHeader(bytes, exr.size(), exr.size(), "named.exr", 4); });
    EXPECT_HAS(e, "named.exr: the OpenEXR header is damaged: attribute 'a\\x01\\x1b[31mb\\x0ac\\x5c' has a negative size (-1)");
    for (char c : e) EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && c != 0x7f) << "a raw control byte in: " << e;
    // Through the file reader too.
    const fs::path file = writeBytes("named.exr", exr);
    const std::string fromFile = errorOf([&] { loadImageFloat(file.string()); });
    EXPECT_HAS(fromFile, "attribute 'a\\x01\\x1b[31mb\\x0ac\\x5c'");
    EXPECT_EQ(fromFile.find('\n'), std::string::npos) << fromFile;
}

TEST(BoundedRead, APfmCutShortSaysWhy) {
    // 8 x 4 pixels of 3 floats need 384 bytes after the header; 100 are there.
    const fs::path pfm = writeBytes("cut.pfm", "PF\n8 4\n-1.0\n" + std::string(100, '\0'));
    const std::string e = errorOf([&] { loadImageFloat(pfm.string()); });
    EXPECT_HAS(e, "cut.pfm: cannot decode image: ");
    EXPECT_NE(e.back(), ' ') << "no reason after the colon: " << e;
    EXPECT_HAS(e, "cut short");
    EXPECT_HAS(e, "8 x 4 pixels of 3 channel(s) take 384 bytes");
}

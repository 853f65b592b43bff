// Issue 32's command faults as a user meets them: a record or a preset given
// as a scene to every command that takes one; compare held to the image
// memory budget before it decodes; a scene path that is a device; the
// window's outputs checked before its first frame.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <OpenImageIO/imageio.h>
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

using Result = test::CommandResult;

fs::path writeText(const std::string& name, const std::string& text) {
    const fs::path p = test::tempDir() / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
}

int lineCount(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

// A grey 8-bit PNG of `w` x `h` written row by row (a 16384 x 16384 one is
// about 260 KB on disk and 256 MB of pixels: never held whole here).
fs::path greyPng(const std::string& name, int w, int h) {
    const fs::path p = test::tempDir() / name;
    auto out = OIIO::ImageOutput::create(p.string());
    const OIIO::ImageSpec spec(w, h, 1, OIIO::TypeDesc::UINT8);
    EXPECT_TRUE(out && out->open(p.string(), spec));
    std::vector<unsigned char> row(static_cast<std::size_t>(w), 128);
    for (int y = 0; y < h; ++y) out->write_scanline(y, 0, OIIO::TypeDesc::UINT8, row.data());
    out->close();
    return p;
}

}  // namespace

TEST(CommandFaultsCli, ARecordOrAPresetGivenAsASceneIsRefusedByEveryCommand) {
    const fs::path record = writeText("as-scene-record.json", R"({"format": "deferred-workbench record", "version": 3,
        "command": "render", "scene": {"spec": "spheres"}})");
    const fs::path preset = writeText("as-scene-preset.json", R"({"format": "deferred-workbench preset", "name": "p",
        "knobs": {"ssao.samples": 8}})");
    const fs::path out = test::tempDir() / "as-scene";
    const std::vector<std::pair<std::string, int>> commands = {
        {"render --size 16x9 --out " + out.string() + ".png --scene ", 1},
        {"reference --size 16x9 --no-cache --out " + out.string() + ".exr --scene ", 1},
        {"tradeoff --size 16x9 --sweep ssao.samples=4,8 --against ssao.samples=16 --metric rms --frames 1 --quiet "
         "--plot none --csv " + out.string() + ".csv --record " + out.string() + ".json --scene ", 1},
        {"bench --size 16x9 --frames 1 --no-lpp --quiet --csv " + out.string() + "-b.csv --record " + out.string() +
             "-b.json --scene ", 1},
        {"compare --size 16x9 --a ssao.samples=4 --b ssao.samples=8 --scene ", 4},
        {"list passes --scene ", 1},
    };
    for (const auto& [command, code] : commands) {
        const Result r = test::runWorkbench(command + record.string());
        SCOPED_TRACE(command + record.string());
        EXPECT_EQ(r.code, code) << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("as-scene-record.json: this is an experiment record"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("`deferred-workbench replay " + record.string() + "`"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("unknown key"), std::string::npos) << r.err;

        const Result p = test::runWorkbench(command + preset.string());
        EXPECT_EQ(p.code, code) << p.err;
        EXPECT_EQ(lineCount(p.err), 1) << p.err;
        EXPECT_NE(p.err.find("as-scene-preset.json: this is a preset (knobs), not a scene: give it as --preset " +
                             preset.string()),
                  std::string::npos)
            << p.err;
    }
    EXPECT_FALSE(fs::exists(out.string() + ".png"));
}

TEST(CommandFaultsCli, CompareRefusesFromTheHeaderWhatWouldExceedTheImageBudget) {
    // A 16384 x 16384 PNG (small on disk) under the default budget: refused
    // before a pixel is decoded, naming the file and its size, in seconds and
    // within a small address space (comparing it took more than 18 GB).
    const fs::path huge = greyPng("huge.png", 16384, 16384);
    EXPECT_LT(fs::file_size(huge), 2u << 20);
    const auto start = std::chrono::steady_clock::now();
    const Result r = test::runCommand("ulimit -v 4000000; DW_IMAGE_LIMIT_MB= " + std::string(DW_WORKBENCH_BINARY) +
                                      " compare " + huge.string() + " " + huge.string());
    EXPECT_EQ(r.code, 4) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("huge.png: the image is 16384 x 16384 pixels of 1 channel: comparing it takes about "), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("over the image memory limit of 1024 MB (set DW_IMAGE_LIMIT_MB=MB to raise it)"), std::string::npos)
        << r.err;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0);

    // A small pair under a smaller budget: the same refusal; a larger budget compares them.
    const fs::path a = greyPng("budget-a.png", 512, 512), b = greyPng("budget-b.png", 512, 512);
    const Result small = test::runCommand("DW_IMAGE_LIMIT_MB=1 " + std::string(DW_WORKBENCH_BINARY) + " compare " +
                                          a.string() + " " + b.string());
    EXPECT_EQ(small.code, 4) << small.err;
    EXPECT_NE(small.err.find("budget-a.png: the image is 512 x 512 pixels of 1 channel"), std::string::npos) << small.err;
    EXPECT_NE(small.err.find("over the image memory limit of 1 MB"), std::string::npos) << small.err;
    const Result fits = test::runCommand("DW_IMAGE_LIMIT_MB=1024 " + std::string(DW_WORKBENCH_BINARY) + " compare " +
                                         a.string() + " " + b.string());
    EXPECT_EQ(fits.code, 0) << fits.err;
    EXPECT_NE(fits.out.find("PASS"), std::string::npos) << fits.out;
}

TEST(CommandFaultsCli, ASceneOrPresetThatIsADeviceIsRefusedNotReadForever) {
    const fs::path link = test::tempDir() / "device.json";
    fs::remove(link);
    fs::create_symlink("/dev/zero", link);
    for (const std::string flag : {"--scene", "--preset"}) {
        const Result r = test::runCommand("ulimit -v 4000000; timeout 60 " + std::string(DW_WORKBENCH_BINARY) +
                                          " render --size 16x9 --out " + (test::tempDir() / "device.png").string() + " " +
                                          flag + " " + link.string());
        EXPECT_EQ(r.code, 1) << flag << ": " << r.err;
        EXPECT_EQ(lineCount(r.err), 1) << r.err;
        EXPECT_NE(r.err.find("device.json"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("it is a device, not a file"), std::string::npos) << r.err;
    }
}

TEST(CommandFaultsCli, CompareRefusesAnImagePathThatIsADeviceOrPipe) {
    // compare /dev/zero x.png spun at 100% CPU: refused by name, exit 4 (a file it cannot read).
    const fs::path link = test::tempDir() / "device.png";
    fs::remove(link);
    fs::create_symlink("/dev/zero", link);
    const fs::path fifo = test::tempDir() / "pipe.exr";
    fs::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const fs::path good = greyPng("device-other.png", 8, 8);
    for (const fs::path& bad : {fs::path("/dev/zero"), link, fifo}) {
        for (const bool first : {true, false}) {
            const std::string args = first ? bad.string() + " " + good.string() : good.string() + " " + bad.string();
            const Result r = test::runCommand("ulimit -v 4000000; timeout 60 " + std::string(DW_WORKBENCH_BINARY) +
                                              " compare " + args);
            EXPECT_EQ(r.code, 4) << args << ": " << r.err;
            EXPECT_EQ(lineCount(r.err), 1) << r.err;
            EXPECT_NE(r.err.find(bad.string() + ": cannot read image: it is a "), std::string::npos) << r.err;
        }
    }
}

TEST(CommandFaultsCli, TheWindowsOutputsAreCheckedBeforeItsFirstFrame) {
    // No display is needed: the refusal comes before a window opens.
    const fs::path missing = test::tempDir() / "no-such-folder" / "run.json";
    const Result r = test::runCommand("DISPLAY= WAYLAND_DISPLAY= " + std::string(DW_WORKBENCH_BINARY) +
                                      " gui --size 64x36 --frames 3 --save-record " + missing.string());
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_EQ(lineCount(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(missing.string() + ": cannot write the --save-record file: no folder"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(missing.parent_path()));
}

// Issue 32: lost transparent fragments (the 4-sample A-buffer on the glass
// scene) were said by render, Python and the window but not by the other
// commands that render: a bench or tradeoff point that drops fragments
// measures neither the method's cost nor its error. Each says so now; the
// exact list (linked_list) loses none and says nothing.
TEST(CommandFaultsCli, EveryCommandThatRendersSaysWhatTransparencyLost) {
    const fs::path dir = test::tempDir() / "lost-fragments";
    fs::create_directories(dir);
    const std::string lossy = " --scene glass --size 32x18 --set oit.method=abuffer --set oit.samples=4";
    const std::string bin = "cd " + dir.string() + " && " + std::string(DW_WORKBENCH_BINARY);
    const std::string lost = "oit: lost ";
    const std::string abuffer = " transparent fragments this frame (abuffer keeps 4 per pixel";

    const Result render = test::runCommand(bin + " render" + lossy + " --out r.png --record r.json");
    ASSERT_EQ(render.code, 0) << render.err;
    EXPECT_NE(render.err.find("warning: " + lost), std::string::npos) << render.err;

    const Result replay = test::runCommand(bin + " replay r.json");
    EXPECT_NE(replay.err.find("warning: " + lost), std::string::npos) << replay.err;
    EXPECT_NE(replay.err.find(abuffer), std::string::npos) << replay.err;

    const Result compare = test::runCommand(bin + " compare --scene glass --size 32x18 --a oit.method=abuffer,oit.samples=4 "
                                                  "--b oit.method=linked_list");
    EXPECT_NE(compare.err.find("compare: warning: side --a: " + lost), std::string::npos) << compare.err;
    EXPECT_EQ(compare.err.find("side --b: " + lost), std::string::npos) << compare.err;

    const Result bench = test::runCommand(bin + " bench" + lossy + " --frames 2 --warmup 0 --csv b.csv --quiet");
    ASSERT_EQ(bench.code, 0) << bench.err;
    EXPECT_NE(bench.err.find("bench: warning: configuration 0 ("), std::string::npos) << bench.err;
    EXPECT_NE(bench.err.find(abuffer), std::string::npos) << bench.err;
    EXPECT_NE(bench.err.find("(in 2 of 2 counted frames; the first such frame's figures)"), std::string::npos) << bench.err;

    const Result tradeoff = test::runCommand(bin + " tradeoff --scene glass --size 32x18 --set oit.method=abuffer "
                                                   "--sweep oit.samples=4,8 --against oit.method=linked_list --metric rms "
                                                   "--frames 1 --warmup 0 --resamples 100 --quiet --plot none");
    ASSERT_EQ(tradeoff.code, 0) << tradeoff.err;
    EXPECT_NE(tradeoff.err.find("tradeoff: warning: point 0, oit.samples=4: " + lost), std::string::npos) << tradeoff.err;

    const Result exact = test::runCommand(bin + " bench --scene glass --size 32x18 --frames 1 --warmup 0 --csv e.csv --quiet");
    ASSERT_EQ(exact.code, 0) << exact.err;
    EXPECT_EQ(exact.err.find(lost), std::string::npos) << exact.err;
}

TEST(CommandFaultsCli, TradeoffPlotNoneDrawsNoPlot) {
    const fs::path dir = test::tempDir() / "plot-none";
    fs::create_directories(dir);
    const Result r = test::runCommand("cd " + dir.string() + " && " + DW_WORKBENCH_BINARY +
                                      " tradeoff --scene default --size 32x18 --sweep ssao.samples=4,8 --against "
                                      "ssao.samples=16 --metric rms --frames 1 --warmup 0 --resamples 100 --quiet --plot none");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "tradeoff.csv"));
    EXPECT_TRUE(fs::exists(dir / "tradeoff.json"));
    for (const auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().extension(), ".png") << e.path();
    EXPECT_EQ(r.out.find(".png"), std::string::npos) << r.out;
}

// A write that fails (a full disk; here the file size limit, ulimit -f, with
// SIGXFSZ ignored so the write returns EFBIG) is an error naming the file,
// with no part of it left: a PNG was reported written and left at 0 bytes.
TEST(CommandFaultsCli, AnImageThatCannotBeWrittenWholeIsAnErrorAndLeavesNoPart) {
    const fs::path dir = test::tempDir() / "full-disk";
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const std::string name : {"a.png", "a.exr"}) {
        const Result r = test::runCommand("cd " + dir.string() + " && bash -c \"trap '' XFSZ; ulimit -f 1; " +
                                          std::string(DW_WORKBENCH_BINARY) + " render --scene spheres --size 160x90 --out " +
                                          name + "\"");
        EXPECT_NE(r.code, 0) << name << ": " << r.out << r.err;
        EXPECT_NE(r.err.find(name + ": cannot "), std::string::npos) << r.err;
        EXPECT_EQ(r.out.find("wrote " + name), std::string::npos) << r.out;
        for (const auto& e : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << e.path();
    }
    // Within the limit the same command writes it.
    const Result ok = test::runCommand("cd " + dir.string() + " && " + std::string(DW_WORKBENCH_BINARY) +
                                       " render --scene spheres --size 16x9 --out b.png");
    EXPECT_EQ(ok.code, 0) << ok.err;
    EXPECT_GT(fs::file_size(dir / "b.png"), 0u);
}

// An output that is a pipe nobody reads is refused when it is written (the
// open waited forever); a plot that cannot be written is one line, not the
// plot script's traceback, and the CSV and record are kept.
TEST(CommandFaultsCli, APipeNobodyReadsAndAPlotThatCannotBeWrittenAreOneLineEach) {
    const fs::path dir = test::tempDir() / "unwritable-outputs";
    fs::remove_all(dir);
    fs::create_directories(dir);
    ASSERT_EQ(::mkfifo((dir / "nobody.json").c_str(), 0600), 0);
    const Result pipe = test::runCommand("cd " + dir.string() + " && timeout 60 " + std::string(DW_WORKBENCH_BINARY) +
                                         " render --scene spheres --size 16x9 --out a.png --record nobody.json");
    EXPECT_EQ(pipe.code, 1) << pipe.err;
    EXPECT_NE(pipe.err.find("nobody.json: cannot save: it is a pipe with no reader"), std::string::npos) << pipe.err;
    const Result plot = test::runCommand(
        "cd " + dir.string() + " && bash -c \"trap '' XFSZ; ulimit -f 30; " + std::string(DW_WORKBENCH_BINARY) +
        " tradeoff --scene default --size 32x18 --sweep ssao.samples=4,8 --against ssao.samples=16 --metric rms "
        "--frames 1 --warmup 0 --resamples 100 --quiet --no-counters --csv t.csv --record t.json --plot p.png "
        "--plot-size 1600x1200\"");  // --no-counters: the record (21 KB) under the 30 KB limit, the plot (44 KB) over it
    EXPECT_NE(plot.err.find("p.png: cannot write the plot"), std::string::npos) << plot.err;
    EXPECT_EQ(plot.err.find("Traceback"), std::string::npos) << plot.err;
    EXPECT_LE(lineCount(plot.err), 3) << plot.err;
    EXPECT_TRUE(fs::exists(dir / "t.csv"));
    EXPECT_TRUE(fs::exists(dir / "t.json"));
}

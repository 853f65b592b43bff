// deferred-workbench compare as a user runs it: the idiff-style exit codes,
// one clear line for bad input, the JSON's keys and numbers, the error maps,
// and the two-render mode.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "renderer/io/ImageIO.h"
#include "renderer/io/JsonGuard.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

using Result = test::CommandResult;
Result run(const std::string& args) { return test::runWorkbench(args); }

int lines(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

FloatImage flat(int w, int h, float v) {
    FloatImage img;
    img.width = w;
    img.height = h;
    img.channels = 3;
    img.pixels.assign(static_cast<size_t>(w) * h * 3, v);
    return img;
}

std::string write(const std::string& name, const FloatImage& img) {
    const fs::path p = test::tempDir() / "compare" / name;
    fs::create_directories(p.parent_path());
    writeImage(p.string(), img);
    return p.string();
}

// 40 x 30 grey 128/255; the test image has 6 pixels 51/255 brighter (0.2) and
// 30 more 5/255 brighter (0.0196), in all three channels: 8-bit exact.
struct Pair {
    std::string reference, test;
};
const Pair& thresholdPair() {
    static const Pair p = [] {
        const FloatImage a = flat(40, 30, 128.0f / 255.0f);
        FloatImage b = a;
        for (int i = 0; i < 36; ++i)
            for (int c = 0; c < 3; ++c) b.at(i, 10, c) = (i < 6 ? 179.0f : 133.0f) / 255.0f;
        return Pair{write("ref.png", a), write("test.png", b)};
    }();
    return p;
}

nlohmann::json readJson(const fs::path& p) { return readJsonFile(p.string(), {kMaxJsonDepth, false}); }

}  // namespace

TEST(CompareCli, IdenticalImagesPass) {
    const Pair& p = thresholdPair();
    const fs::path json = test::tempDir() / "compare" / "same.json";
    const Result r = run("compare " + p.reference + " " + p.reference + " --json " + json.string());
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("\nPASS\n"), std::string::npos) << r.out;
    const nlohmann::json j = readJson(json);
    EXPECT_EQ(j["mean"].get<double>(), 0.0);
    EXPECT_EQ(j["max"].get<double>(), 0.0);
    EXPECT_TRUE(j["psnr"].is_null());  // infinite
    EXPECT_DOUBLE_EQ(j["ssim"].get<double>(), 1.0);
    EXPECT_EQ(j["flip"].get<double>(), 0.0);
    EXPECT_EQ(j["fail_count"].get<long long>(), 0);
    EXPECT_EQ(j["verdict"], "pass");
}

// Each documented exit code from the thresholds, as idiff combines them:
// 1200 pixels, 6 over 0.1, 36 over 0.01.
TEST(CompareCli, ThresholdsGiveTheDocumentedExitCodes) {
    const Pair& p = thresholdPair();
    const std::string files = "compare " + p.reference + " " + p.test;
    // idiff's defaults (1e-6, 0 %): any difference fails.
    EXPECT_EQ(run(files).code, 2);
    // 6 of 1200 = 0.5 % over --fail, allowed 1 %; 36 = 3 % over --warn, allowed 5 %.
    EXPECT_EQ(run(files + " --fail 0.1 --warn 0.01 --failpercent 1 --warnpercent 5").code, 0);
    // The same, no warnings allowed: 36 > 0.
    const Result warn = run(files + " --fail 0.1 --warn 0.01 --failpercent 1");
    EXPECT_EQ(warn.code, 1) << warn.out;
    EXPECT_NE(warn.out.find("\nWARNING\n"), std::string::npos) << warn.out;
    // "More than": 6 is not more than 0.5 % of 1200 = 6.
    EXPECT_EQ(run(files + " --fail 0.1 --warn 0.3 --failpercent 0.5").code, 0);
    // 6 > 0.4 % of 1200 = 4.8: fail.
    const Result fail = run(files + " --fail 0.1 --warn 0.01 --failpercent 0.4 --warnpercent 5");
    EXPECT_EQ(fail.code, 2) << fail.out;
    EXPECT_NE(fail.out.find("6 pixels (0.5%) differ by more than 0.1, allowed 0.4%"), std::string::npos) << fail.out;
    // --hardfail: the largest difference 0.2 exceeds 0.15.
    EXPECT_EQ(run(files + " --fail 0.3 --warn 0.3 --hardfail 0.15").code, 2);
    // --fail-ssim fails below it; --fail-flip above it.
    const std::string loose = files + " --fail 0.3 --warn 0.3";
    EXPECT_EQ(run(loose).code, 0);
    EXPECT_EQ(run(loose + " --fail-ssim 0.99999").code, 2);
    EXPECT_EQ(run(loose + " --fail-ssim 0.5").code, 0);
    EXPECT_EQ(run(loose + " --fail-flip 0.001").code, 2);
    EXPECT_EQ(run(loose + " --fail-flip 0.9").code, 0);
}

TEST(CompareCli, MismatchedSizesExitThree) {
    const Pair& p = thresholdPair();
    const std::string small = write("small.png", flat(20, 30, 0.5f));
    const Result r = run("compare " + p.reference + " " + small);
    EXPECT_EQ(r.code, 3);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("40x30x3"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("20x30x3"), std::string::npos) << r.err;
}

TEST(CompareCli, UnreadableFileExitsFourWithOneLine) {
    const Pair& p = thresholdPair();
    const fs::path missing = test::tempDir() / "compare" / "no-such.png";
    const Result r = run("compare " + p.reference + " " + missing.string());
    EXPECT_EQ(r.code, 4);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(missing.string() + ": image file not found"), std::string::npos) << r.err;
    const fs::path garbage = test::tempDir() / "compare" / "garbage.png";
    std::ofstream(garbage) << "not an image";
    const Result g = run("compare " + garbage.string() + " " + p.reference);
    EXPECT_EQ(g.code, 4);
    EXPECT_EQ(lines(g.err), 1) << g.err;
    EXPECT_NE(g.err.find(garbage.string()), std::string::npos) << g.err;
}

TEST(CompareCli, NonFiniteInputIsAClearError) {
    FloatImage a = flat(16, 16, 0.5f);
    const std::string good = write("finite.exr", a);
    a.at(7, 3, 2) = std::nanf("");
    const std::string bad = write("nan.exr", a);
    const Result r = run("compare " + good + " " + bad);
    EXPECT_EQ(r.code, 5);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(bad + ": pixel (7, 3) channel 2 is NaN"), std::string::npos) << r.err;
}

TEST(CompareCli, JsonHasTheFixedKeysAndNumbers) {
    const Pair& p = thresholdPair();
    const fs::path json = test::tempDir() / "compare" / "diff.json";
    const Result r = run("compare " + p.reference + " " + p.test + " --fail 0.1 --warn 0.01 --json " + json.string());
    ASSERT_EQ(r.code, 2) << r.err;
    const nlohmann::json j = readJson(json);
    for (const char* key : {"mean", "rms", "psnr", "max", "ssim", "flip", "fail_count", "warn_count", "mean_per_channel",
                            "rms_per_channel", "max_per_channel", "ssim_per_channel", "fail_count_per_channel",
                            "ssim_encoding", "flip_variant", "reference", "test", "verdict", "exit_code"})
        EXPECT_TRUE(j.contains(key)) << key;
    // Every channel: (6 x 51 + 30 x 5) / 255 over 1200 pixels.
    const double mean = (6 * 51.0 + 30 * 5.0) / 255.0 / 1200.0;
    EXPECT_NEAR(j["mean"].get<double>(), mean, 1e-7);
    EXPECT_NEAR(j["rms"].get<double>(), std::sqrt((6 * 51.0 * 51.0 + 30 * 25.0) / (255.0 * 255.0) / 1200.0), 1e-7);
    EXPECT_NEAR(j["max"].get<double>(), 51.0 / 255.0, 1e-6);
    EXPECT_NEAR(j["psnr"].get<double>(), 20 * std::log10(1.0 / j["rms"].get<double>()), 1e-3);
    ASSERT_EQ(j["mean_per_channel"].size(), 3u);
    EXPECT_NEAR(j["mean_per_channel"][1].get<double>(), mean, 1e-7);
    EXPECT_EQ(j["fail_count"].get<long long>(), 6);
    EXPECT_EQ(j["warn_count"].get<long long>(), 36);
    EXPECT_EQ(j["fail_count_per_channel"][2].get<long long>(), 6);
    EXPECT_EQ(j["pixel_count"].get<long long>(), 1200);
    EXPECT_EQ(j["ssim_encoding"], "as-stored");
    EXPECT_EQ(j["flip_variant"], "LDR-FLIP");
    EXPECT_GT(j["flip"].get<double>(), 0.0);
    EXPECT_LT(j["ssim"].get<double>(), 1.0);
    EXPECT_EQ(j["reference"]["kind"], "file");
    EXPECT_EQ(j["reference"]["path"], p.reference);
    EXPECT_EQ(j["verdict"], "fail");
    EXPECT_EQ(j["exit_code"].get<int>(), 2);
}

TEST(CompareCli, ExrInputsUseHdrFlipAndWriteErrorMaps) {
    FloatImage a = flat(24, 16, 1.0f), b = flat(24, 16, 2.0f);
    const std::string ra = write("one.exr", a), rb = write("two.exr", b);
    const fs::path dir = test::tempDir() / "compare";
    const Result r = run("compare " + ra + " " + rb + " --fail 2 --warn 2 --error-map " + (dir / "map.exr").string() +
                         " --json " + (dir / "hdr.json").string());
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    const nlohmann::json j = readJson(dir / "hdr.json");
    EXPECT_EQ(j["flip_variant"], "HDR-FLIP");
    EXPECT_EQ(j["ssim_encoding"], "reinhard");
    EXPECT_TRUE(j["hdr"].get<bool>());
    // The flat radiance pair worked by hand in tests/metrics/MetricsTest.cpp.
    EXPECT_NEAR(j["flip"].get<double>(), 0.144751, 1e-5);
    EXPECT_EQ(j["flip_exposures"]["count"].get<int>(), 2);
    // EXR keeps channels by name (OpenEXR sorts them): look each up.
    auto in = OIIO::ImageInput::open((dir / "map.exr").string());
    ASSERT_TRUE(in);
    const std::vector<std::string> names = in->spec().channelnames;
    ASSERT_EQ(names.size(), 5u);
    const FloatImage map = loadImageFloat((dir / "map.exr").string());
    auto channel = [&](const std::string& name) {
        const auto it = std::find(names.begin(), names.end(), name);
        EXPECT_NE(it, names.end()) << name;
        return static_cast<int>(it - names.begin());
    };
    EXPECT_FLOAT_EQ(map.at(3, 4, channel("absdiff.R")), 1.0f);
    EXPECT_FLOAT_EQ(map.at(3, 4, channel("absdiff.B")), 1.0f);
    EXPECT_NEAR(map.at(3, 4, channel("flip")), 0.144751, 1e-5);
    // Flat images: no variance, SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1) on
    // the Reinhard values mx = 1/2, my = 2/3, C1 = 1e-4: 0.666767 / 0.694544 = 0.960006.
    EXPECT_NEAR(map.at(3, 4, channel("ssim")), 0.960006, 1e-5);
    EXPECT_NEAR(j["ssim"].get<double>(), 0.960006, 1e-5);

    const FloatImage heat = loadImageFloat((dir / "map.png").string());  // beside the EXR
    EXPECT_EQ(heat.width, 24);
    EXPECT_EQ(heat.channels, 3);
}

// Two renders of one scene: equal knob sets are identical; SSAO off differs.
TEST(CompareCli, TwoRendersOfOneScene) {
    const fs::path dir = test::tempDir() / "compare";
    // An output in a folder that does not exist: refused before anything renders.
    const Result noFolder = run("compare --scene spheres --a ao.enabled=true --b ao.enabled=false --json " +
                                (dir / "missing-folder" / "r.json").string());
    EXPECT_EQ(noFolder.code, 5);
    EXPECT_NE(noFolder.err.find("cannot write the --json file: no folder"), std::string::npos) << noFolder.err;
    fs::create_directories(dir);
    const std::string scene = " --scene spheres --size 96x54";
    const Result same = run("compare" + scene + " --a ao.enabled=true --b ao.enabled=true --json " +
                            (dir / "same-render.json").string());
    ASSERT_EQ(same.code, 0) << same.out << same.err;
    EXPECT_EQ(readJson(dir / "same-render.json")["flip"].get<double>(), 0.0);
    const Result differ = run("compare" + scene + " --buffer lbuffer --a ao.enabled=true --b ao.enabled=false,shadows.enabled=false" +
                              " --json " + (dir / "render.json").string());
    EXPECT_EQ(differ.code, 2) << differ.out << differ.err;
    const nlohmann::json j = readJson(dir / "render.json");
    EXPECT_GT(j["mean"].get<double>(), 0.0);
    EXPECT_EQ(j["flip_variant"], "HDR-FLIP");
    EXPECT_EQ(j["test"]["kind"], "render");
    EXPECT_EQ(j["test"]["buffer"], "lbuffer");
    EXPECT_EQ(j["test"]["set"].size(), 2u);
    // A bad knob is a usage error (5), named before anything renders.
    const Result bad = run("compare" + scene + " --a ao.enabled=maybe --b ao.enabled=true");
    EXPECT_EQ(bad.code, 5);
    EXPECT_NE(bad.err.find("ao.enabled"), std::string::npos) << bad.err;
    // A scene or preset that cannot be read: 4 and one line, as for an image.
    const Result noScene = run("compare --scene " + (dir / "no-scene.json").string() + " --a ao.enabled=true --b ao.enabled=false");
    EXPECT_EQ(noScene.code, 4);
    EXPECT_EQ(lines(noScene.err), 1) << noScene.err;
    EXPECT_NE(noScene.err.find("no-scene.json: scene file not found"), std::string::npos) << noScene.err;
    // Files and knob sets together: a usage error.
    EXPECT_EQ(run("compare a.png b.png --a x=1 --b x=2").code, 5);
}

namespace {

// The sub-pixel-moving edge of TemporalError's closed-form test
// (tests/metrics/TemporalErrorTest.cpp): 17 frames 16 x 4, an edge moving a
// quarter pixel a frame; box-filtered truth and pixel centres, as EXR files
// ref%02d.exr and test%02d.exr in `dir`.
std::string edgeSequences(const std::string& dir) {
    const fs::path d = test::tempDir() / "compare" / dir;
    fs::remove_all(d);
    fs::create_directories(d);
    for (int t = 0; t < 17; ++t) {
        FloatImage truth = flat(16, 4, 0.0f), centres = flat(16, 4, 0.0f);
        const double edge = 2.125 + 0.25 * t;
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 16; ++x)
                for (int c = 0; c < 3; ++c) {
                    truth.at(x, y, c) = static_cast<float>(std::clamp(edge - x, 0.0, 1.0));
                    centres.at(x, y, c) = x + 0.5 < edge ? 1.0f : 0.0f;
                }
        char name[32];
        std::snprintf(name, sizeof name, "ref%02d.exr", t);
        writeImage((d / name).string(), truth);
        std::snprintf(name, sizeof name, "test%02d.exr", t);
        writeImage((d / name).string(), centres);
    }
    return d.string();
}

}  // namespace

// compare --sequence: each frame's FLIP and RMS and the temporal error with
// its interval; the pixel centres of the moving edge flicker by the closed
// form 0.375 / 16, the truth against itself by 0.
TEST(CompareCli, SequencesGiveEachFramesErrorAndTheTemporalError) {
    const std::string d = edgeSequences("sequence");
    const Result r = run("compare --sequence " + d + "/ref%02d.exr " + d + "/test%02d.exr");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("frames 0..16 (17), 16x4x3, HDR"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("mean FLIP"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("  temporal error 0.0234375 ["), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("   1->2     0.046875"), std::string::npos) << r.out;  // the jump: 0.75 / 16
    const Result same = run("compare --sequence " + d + "/ref%02d.exr " + d + "/ref%02d.exr");
    ASSERT_EQ(same.code, 0) << same.err;
    EXPECT_NE(same.out.find("  temporal error 0 [0, 0]"), std::string::npos) << same.out;
}

// Bad sequences: one line naming the file; a missing or extra frame or another
// size exits 3 (as two images of other sizes do), a bad pattern 5.
TEST(CompareCli, SequencesThatDoNotMatchAreRefusedNamingTheFile) {
    const std::string d = edgeSequences("sequence-bad");
    const std::string ref = d + "/ref%02d.exr", tst = d + "/test%02d.exr";
    fs::remove(d + "/test05.exr");
    const Result missing = run("compare --sequence " + ref + " " + tst);
    EXPECT_EQ(missing.code, 3);
    EXPECT_EQ(lines(missing.err), 1) << missing.err;
    EXPECT_NE(missing.err.find("test frame 5 is missing: " + d + "/test05.exr does not exist"), std::string::npos)
        << missing.err;
    writeImage(d + "/test05.exr", flat(8, 4, 0.5f));
    const Result size = run("compare --sequence " + ref + " " + tst);
    EXPECT_EQ(size.code, 3);
    EXPECT_EQ(lines(size.err), 1) << size.err;
    EXPECT_NE(size.err.find(d + "/test05.exr is 8x4x3, " + d + "/ref00.exr is 16x4x3"), std::string::npos) << size.err;
    writeImage(d + "/test05.exr", flat(16, 4, 0.5f));
    writeImage(d + "/test17.exr", flat(16, 4, 0.5f));
    const Result extra = run("compare --sequence " + ref + " " + tst);
    EXPECT_EQ(extra.code, 3);
    EXPECT_NE(extra.err.find("the test has more frames than the reference: " + d + "/test17.exr exists"),
              std::string::npos) << extra.err;
    const Result pattern = run("compare --sequence " + d + "/ref.exr " + tst);
    EXPECT_EQ(pattern.code, 5);
    EXPECT_NE(pattern.err.find("one integer conversion"), std::string::npos) << pattern.err;
    const Result option = run("compare --sequence " + ref + " " + tst + " --fail 0.1");
    EXPECT_EQ(option.code, 5);
    EXPECT_NE(option.err.find("--sequence compares two sequences of image files"), std::string::npos) << option.err;
}

// render --out-sequence: a camera path's frames in order, as compare
// --sequence reads them. An orbit of 16 degrees over 5 cameras of the pixel
// centres, of TAA (its history carried, after 16 frames at the first camera)
// and of the reference at 4 samples a pixel; the frames move; compare
// --sequence measures each method's temporal error against the reference's.
// A path without --out-sequence, or the reverse, is one line, exit 2.
TEST(CompareCli, RenderWritesACameraPathsFramesThatCompareSequenceReads) {
    const fs::path d = test::tempDir() / "compare" / "render-sequence";
    fs::remove_all(d);
    fs::create_directories(d);
    const std::string path = "render --scene default --size 48x27 --set bloom.enabled=false --orbit 5 --orbit-degrees 16 ";
    const Result none = run(path + "--set aa.method=none --out-sequence " + (d / "none%02d.png").string());
    ASSERT_EQ(none.code, 0) << none.err;
    EXPECT_NE(none.out.find("frames 0..4"), std::string::npos) << none.out;
    const Result taa = run(path + "--set aa.method=taa --warmup 16 --out-sequence " + (d / "taa%02d.png").string());
    ASSERT_EQ(taa.code, 0) << taa.err;
    const Result ref =
        run(path + "--buffer reference.final --spp 4 --out-sequence " + (d / "ref%02d.png").string());
    ASSERT_EQ(ref.code, 0) << ref.err;
    for (const char* name : {"none", "taa", "ref"}) {
        for (int t = 0; t < 5; ++t) EXPECT_TRUE(fs::exists(d / (name + std::string(t < 10 ? "0" : "") + std::to_string(t) + ".png")));
        EXPECT_FALSE(fs::exists(d / (name + std::string("05.png"))));
    }
    EXPECT_NE(loadImageFloat((d / "none00.png").string()).pixels, loadImageFloat((d / "none04.png").string()).pixels);
    for (const char* name : {"none", "taa"}) {
        const Result c = run("compare --sequence " + (d / "ref%02d.png").string() + " " + (d / name).string() + "%02d.png");
        ASSERT_EQ(c.code, 0) << c.err;
        EXPECT_NE(c.out.find("frames 0..4 (5), 48x27x4, LDR"), std::string::npos) << c.out;
        EXPECT_NE(c.out.find("  temporal error "), std::string::npos) << c.out;
    }
    const Result noSequence = run(path + "--out " + (d / "x.png").string());
    EXPECT_EQ(noSequence.code, 2);
    EXPECT_NE(noSequence.err.find("a camera path (--orbit, --walkthrough) or --time-steps renders a sequence: give --out-sequence"),
              std::string::npos) << noSequence.err;
    const Result noPath = run("render --scene default --size 48x27 --out-sequence " + (d / "y%02d.png").string());
    EXPECT_EQ(noPath.code, 2);
    EXPECT_NE(noPath.err.find("--out-sequence writes a sequence's frames"), std::string::npos) << noPath.err;
}

// The anti-aliasing methods from the command line (issue 35 part 2), as
// docs/antialiasing.md shows them: an unbuilt method is one line naming those
// that exist, before anything renders; the old name fxaa.enabled works with
// its warnings; the methods' own buffers and their pass lines.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {
test::CommandResult run(const std::string& args) { return test::runWorkbench(args); }
fs::path dir() {
    const fs::path d = test::tempDir() / "aa-cli";
    fs::create_directories(d);
    return d;
}
}  // namespace

TEST(AntialiasingCli, AnUnbuiltMethodIsOneLineNamingThoseThatExist) {
    const fs::path out = dir() / "smaa.png";
    const auto r = run("render --scene default --size 32x18 --set aa.method=smaa --out " + out.string());
    EXPECT_NE(r.code, 0);
    EXPECT_EQ(r.err, "deferred-workbench: error: knob 'aa.method' takes one of: none, msaa, fxaa, ssaa, taa; got 'smaa'\n");
    EXPECT_FALSE(fs::exists(out));
    const auto f = run("render --scene default --size 32x18 --set aa.ssaa_factor=3 --out " + out.string());
    EXPECT_NE(f.code, 0);
    EXPECT_NE(f.err.find("knob 'aa.ssaa_factor' takes one of: 2, 4; got '3'"), std::string::npos) << f.err;
    EXPECT_EQ(std::count(f.err.begin(), f.err.end(), '\n'), 1) << f.err;
}

TEST(AntialiasingCli, TheOldNameFxaaEnabledSetsTheMethodWithItsWarnings) {
    const auto r = run("render --scene spheres --size 32x18 --set fxaa.enabled=false --timings --out " +
                       (dir() / "old.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("warning: knob 'fxaa.enabled' is now 'aa.method' (anti-aliasing has several methods now, "
                         "chosen by aa.method); the old name still works"),
              std::string::npos) << r.err;
    EXPECT_NE(r.err.find("warning: knob 'aa.method': value 'false' is now 'none'"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("skipped: switched off (aa.method = none)"), std::string::npos) << r.out;
}

TEST(AntialiasingCli, EachMethodsBuffersAndPassLine) {
    const auto s = run("render --scene spheres --size 32x18 --set aa.method=ssaa --set aa.ssaa_factor=4 --timings "
                       "--buffer ssaa.lbuffer --out " + (dir() / "s.exr").string());
    ASSERT_EQ(s.code, 0) << s.err;
    EXPECT_NE(s.out.find("(4x4 samples a pixel, rendered at 128x72)"), std::string::npos) << s.out;
    EXPECT_EQ(loadImageFloat((dir() / "s.exr").string()).width, 32);
    const auto t = run("render --scene spheres --size 32x18 --set aa.method=taa --timings --buffer taa.rejected --out " +
                       (dir() / "t.png").string());
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_NE(t.out.find("Halton(2,3) point"), std::string::npos) << t.out;
    EXPECT_TRUE(fs::exists(dir() / "t.png"));
    const auto m = run("render --scene spheres --size 32x18 --set aa.method=msaa --timings --buffer aa.edges --out " +
                       (dir() / "edges.png").string());
    ASSERT_EQ(m.code, 0) << m.err;
    EXPECT_NE(m.out.find("(4 samples)"), std::string::npos) << m.out;
    EXPECT_EQ(loadImageFloat((dir() / "edges.png").string()).width, 32);
    // The final image: the lighting pass's line counts the samples shaded.
    const auto l = run("render --scene spheres --size 32x18 --set aa.method=msaa --timings --out " +
                       (dir() / "msaa.png").string());
    ASSERT_EQ(l.code, 0) << l.err;
    EXPECT_NE(l.out.find(" edge pixels of 576 shaded again per sample; shaded samples 576 + "), std::string::npos)
        << l.out;
    // docs/antialiasing.md's cap line (a device that offers 16 samples has none).
    const auto c = run("render --scene spheres --size 32x18 --set aa.method=msaa --set aa.samples=16 --out " +
                       (dir() / "capped.png").string());
    ASSERT_EQ(c.code, 0) << c.err;
    if (c.err.find("capped") != std::string::npos) {
        EXPECT_EQ(c.err.rfind("warning: msaa: aa.samples 16 is capped to ", 0), 0u) << c.err;
        EXPECT_NE(c.err.find(" samples for the G-buffer's formats (GL_MAX_SAMPLES, "), std::string::npos) << c.err;
        EXPECT_EQ(std::count(c.err.begin(), c.err.end(), '\n'), 1) << c.err;
    }
    const auto f = run("render --scene spheres --size 32x18 --set aa.method=msaa --set aa.samples=3 --out " +
                       (dir() / "bad.png").string());
    EXPECT_NE(f.code, 0);
    EXPECT_NE(f.err.find("knob 'aa.samples' takes one of: 2, 4, 8, 16; got '3'"), std::string::npos) << f.err;
}

// What a method cannot do is said, not left to a silent image (found by a new
// user): MSAA under a forward strategy (which draws the scene itself at the
// pixel centres) warns that the image is none's; a CPU reference buffer
// under SSAA (the frame at factor x the output size) is refused before
// anything is traced, naming both sizes; compare --sequence refuses a
// sequence of one frame (no frame-to-frame change).
TEST(AntialiasingCli, WhatAMethodCannotDoIsSaid) {
    const auto f = run("render --scene default --size 32x18 --set lighting.strategy=forward --set aa.method=msaa --out " +
                       (dir() / "fwd.png").string());
    ASSERT_EQ(f.code, 0) << f.err;
    EXPECT_NE(f.err.find("msaa: lighting.strategy=forward shades per pixel only"), std::string::npos) << f.err;
    EXPECT_NE(f.err.find("the image is aa.method=none's"), std::string::npos) << f.err;
    const auto d = run("render --scene default --size 32x18 --set aa.method=msaa --out " + (dir() / "def.png").string());
    EXPECT_EQ(d.err.find("shades per pixel only"), std::string::npos) << d.err;

    const fs::path ref = dir() / "ref-ssaa.png";
    const auto r = run("render --scene default --size 32x18 --set aa.method=ssaa --buffer reference.final --spp 4 --out " +
                       ref.string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--buffer reference.final is the CPU reference at the output size (32x18) and "
                         "aa.method=ssaa renders the frame at 2x2 that size"),
              std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("CPU reference"), std::string::npos) << "refused before the trace: " << r.out;
    EXPECT_FALSE(fs::exists(ref));

    const fs::path one = dir() / "one";
    fs::create_directories(one);
    fs::copy_file(dir() / "def.png", one / "a0.png", fs::copy_options::overwrite_existing);
    fs::copy_file(dir() / "def.png", one / "b0.png", fs::copy_options::overwrite_existing);
    const auto c = run("compare --sequence " + (one / "a%d.png").string() + " " + (one / "b%d.png").string());
    EXPECT_EQ(c.code, 3);
    EXPECT_NE(c.err.find("a sequence of 1 frame has no frame-to-frame change"), std::string::npos) << c.err;
}

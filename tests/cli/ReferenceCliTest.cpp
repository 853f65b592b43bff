// `deferred-workbench reference` as a user runs it: the buffers it writes,
// the knobs it reports, the cache, and one clear line for bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "renderer/io/ImageIO.h"
#include "tests/support/TestSupport.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

test::CommandResult run(const std::string& args) { return test::runWorkbench(args); }

TEST(ReferenceCli, WritesEachBufferAndCachesTheRender) {
    const fs::path dir = test::tempDir() / "reference-cli";
    fs::create_directories(dir);
    const std::string cache = " --cache-dir " + (dir / "cache").string();
    const std::string common = "reference --scene spheres --size 48x27 --ao-rays 4 --quiet" + cache;
    const auto first = run(common + " --set lighting.strategy=tiled --stats-out " + (dir / "s.json").string() +
                           " --out " + (dir / "l.exr").string());
    ASSERT_EQ(first.code, 0) << first.err;
    EXPECT_NE(first.out.find("of them set here: lighting.strategy=tiled"), std::string::npos) << first.out;
    // Bloom and FXAA are on, but they matter only to the final image.
    EXPECT_EQ(first.out.find("not modelled"), std::string::npos) << first.out;
    const FloatImage l = loadImageFloat((dir / "l.exr").string());
    EXPECT_EQ(l.width, 48);
    EXPECT_EQ(l.height, 27);
    std::ifstream sf(dir / "s.json");
    const auto stats = nlohmann::json::parse(sf);
    EXPECT_EQ(stats["cached"], false);
    EXPECT_EQ(stats["primary_rays"], 48 * 27);
    EXPECT_GT(stats["ao_rays"].get<long long>(), 0);

    // The same model (the strategy is ignored): from the cache, the same values.
    const auto again = run(common + " --buffer ao --out " + (dir / "ao.exr").string());
    ASSERT_EQ(again.code, 0) << again.err;
    EXPECT_NE(again.out.find("from the cache"), std::string::npos) << again.out;
    const FloatImage ao = loadImageFloat((dir / "ao.exr").string());
    EXPECT_EQ(ao.channels, 1);
    // A honoured knob makes a new reference.
    const auto other = run(common + " --set ssao.intensity=2 --buffer final --out " + (dir / "f.png").string());
    ASSERT_EQ(other.code, 0) << other.err;
    EXPECT_EQ(other.out.find("from the cache"), std::string::npos) << other.out;
    EXPECT_NE(other.out.find("not modelled"), std::string::npos) << other.out;

    // A cache that cannot be written costs the next run a render, not this run's image.
    const fs::path notADir = dir / "a-file";
    std::ofstream(notADir) << "x";
    const auto uncached = run("reference --scene spheres --size 16x9 --ao-rays 2 --quiet --cache-dir " + notADir.string() +
                              " --out " + (dir / "u.exr").string());
    EXPECT_EQ(uncached.code, 0) << uncached.err;
    EXPECT_NE(uncached.err.find("warning: the reference is not cached"), std::string::npos) << uncached.err;
    EXPECT_TRUE(fs::exists(dir / "u.exr"));
}

TEST(ReferenceCli, BadInputGetsOneClearLine) {
    const fs::path dir = test::tempDir() / "reference-cli-bad";
    fs::create_directories(dir);
    auto r = run("reference --scene spheres --size 8x8 --buffer depth --out " + (dir / "x.exr").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("unknown reference buffer 'depth'"), std::string::npos) << r.err;
    r = run("reference --scene spheres --size 8x8 --out " + (dir / "x.hdr").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("float images are written as .exr"), std::string::npos) << r.err;
    r = run("reference --scene spheres --size 8x8 --out " + (dir / "x.png").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("the L-buffer is HDR; write it as .exr"), std::string::npos) << r.err;
    const fs::path broken = dir / "broken.json";
    std::ofstream(broken) << "{ \"objects\": [ }";
    r = run("reference --scene " + broken.string() + " --size 8x8 --out " + (dir / "x.exr").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(broken.string()), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
    // An output that cannot be written fails before the render, not after it.
    r = run("reference --scene spheres --size 8x8 --out " + (dir / "no-such-folder" / "x.exr").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("cannot write the --out file: no folder"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("rendered in"), std::string::npos) << r.out;
    r = run("reference --scene spheres --size 8x8 --set ssao.intensity=9 --out " + (dir / "x.exr").string());
    EXPECT_EQ(r.code, 1) << r.err;
    EXPECT_NE(r.err.find("'ssao.intensity' = 9 is out of range"), std::string::npos) << r.err;
}

// Issue 35: --spp N samples each pixel's area; spp_error is each pixel's
// standard error; the run says whether N is enough; N enters the cache key;
// bad counts and filters are one line before anything renders.
TEST(ReferenceCli, SamplesPerPixelAndTheirStandardError) {
    const fs::path dir = test::tempDir() / "reference-cli-spp";
    fs::create_directories(dir);
    const std::string common = "reference --scene default --size 40x24 --ao-rays 2 --cache-dir " + (dir / "cache").string();
    auto r = run(common + " --spp 4 --filter tent --buffer spp_error --stats-out " + (dir / "s.json").string() +
                 " --out " + (dir / "e.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("pixel samples: 4 (tent), relative standard error of the pixels' luminance: mean"),
              std::string::npos) << r.out;
    const FloatImage e = loadImageFloat((dir / "e.exr").string());
    EXPECT_EQ(e.channels, 1);
    float largest = 0.0f;
    for (float v : e.pixels) largest = std::max(largest, v);
    EXPECT_GT(largest, 0.0f);  // the edges and the floor's texture vary inside a pixel
    std::ifstream sf(dir / "s.json");
    const auto stats = nlohmann::json::parse(sf);
    EXPECT_EQ(stats["primary_rays"], 40 * 24 * 4);
    EXPECT_EQ(stats["pixel_samples"], 4);
    // One sample: another cache entry, and no spread to report.
    r = run(common + " --buffer spp_error --out " + (dir / "e1.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.find("from the cache"), std::string::npos) << r.out;
    for (float v : loadImageFloat((dir / "e1.exr").string()).pixels) ASSERT_EQ(v, 0.0f);
    for (const std::string bad : {"--spp 0", "--spp 1e9", "--spp 70000"}) {
        r = run(common + " " + bad + " --out " + (dir / "x.exr").string());
        EXPECT_EQ(r.code, 2) << bad;
        EXPECT_NE(r.err.find("--spp"), std::string::npos) << bad << ": " << r.err;
    }
    r = run(common + " --spp 4 --filter gauss --out " + (dir / "x.exr").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--filter: expected box or tent, got 'gauss'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

TEST(ReferenceCli, CompareAgainstTheReference) {
    const fs::path dir = test::tempDir() / "reference-compare";
    fs::create_directories(dir);
    const std::string env = "DW_REFERENCE_CACHE=" + (dir / "cache").string() + " ";
    const std::string accurate =
        " --b lighting.strategy=fullscreen,lighting.threshold=1e-5,ao.enabled=false,gbuffer.texture_filter=base_level,"
        "shadows.enabled=false";
    auto r = test::runCommand(env + DW_WORKBENCH_BINARY + std::string(" compare --against reference --scene spheres --size 64x36 "
                                                                       "--buffer lbuffer --fail 0.01 --warn 0.01 --json ") +
                              (dir / "c.json").string() + accurate);
    ASSERT_EQ(r.code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("CPU reference of spheres, lbuffer"), std::string::npos) << r.out;
    std::ifstream jf(dir / "c.json");
    const auto j = nlohmann::json::parse(jf);
    EXPECT_LT(j["mean"].get<double>(), 1e-3);
    EXPECT_LT(j["flip"].get<double>(), 0.02);
    // The entry is in the cache the variable names.
    int entries = 0;
    for (const auto& e : fs::directory_iterator(dir / "cache")) entries += e.path().extension() == ".json";
    EXPECT_EQ(entries, 1);
    // An animated scene: the reference is of the render's last frame (fire's flames move with it). The
    // flames pass's sprites are emission the reference does not trace, so the render leaves them out.
    for (const char* frames : {"1", "12"}) {
        r = test::runCommand(env + DW_WORKBENCH_BINARY +
                             std::string(" compare --against reference --scene fire --size 48x27 --buffer lbuffer "
                                         "--warn 1 --fail 1 --frames ") +
                             frames + " --json " + (dir / "fire.json").string() + accurate +
                             ",flames.enabled=false");  // the sprites are not in the reference; their lights are
        ASSERT_EQ(r.code, 0) << r.out << r.err;
        std::ifstream ff(dir / "fire.json");
        EXPECT_LT(nlohmann::json::parse(ff)["flip"].get<double>(), 0.03) << "after " << frames << " frames";
    }
    // ao.raw is at the AO resolution: said before anything renders.
    r = run("compare --against reference --scene spheres --size 8x8 --buffer ao.raw");
    EXPECT_EQ(r.code, 5);
    EXPECT_NE(r.err.find("add --b ssao.resolution=full"), std::string::npos) << r.err;
    // A buffer with no counterpart: one line, before anything renders.
    r = run("compare --against reference --scene spheres --size 8x8 --buffer gbuffer.normal");
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("no counterpart of buffer 'gbuffer.normal'"), std::string::npos) << r.err;
    r = run("compare --against reference --a ao.enabled=false --scene spheres --size 8x8");
    EXPECT_NE(r.err.find("give the render's knobs with --b"), std::string::npos) << r.err;
}

// render --buffer reference.* traces the view's reference as `reference` does and hands it to the
// reference pass: the same images bit for bit; compare.error is the pass's per-pixel
// |L - L_ref| / (L_ref + 0.001) of the frame's lbuffer against it (L the luminance).
bool sameBits(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(ReferenceCli, RenderBufferOfTheReferenceIsReferencesImage) {
    const fs::path dir = test::tempDir() / "reference-render-buffer";
    fs::remove_all(dir / "cache");  // the seed-4 trace below must miss it
    fs::create_directories(dir);
    const std::string view = " --scene default --size 32x18 --ao-rays 4 --seed 3";
    const std::string cache = " --cache-dir " + (dir / "cache").string();
    for (const std::string name : {"lbuffer", "final", "ao"}) {
        const fs::path ref = dir / ("ref-" + name + ".exr"), ren = dir / ("render-" + name + ".exr");
        auto r = run("reference" + view + " --no-cache --quiet --buffer " + name + " --out " + ref.string());
        ASSERT_EQ(r.code, 0) << r.err;
        r = run("render" + view + cache + " --buffer reference." + name + " --out " + ren.string());
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.out.find("CPU reference of the view: 4 AO rays per pixel, seed 3"), std::string::npos) << r.out;
        const FloatImage a = loadImageFloat(ref.string()), b = loadImageFloat(ren.string());
        EXPECT_EQ(b.width, 32);
        EXPECT_EQ(b.channels, name == "ao" ? 1 : 4) << name;
        EXPECT_TRUE(sameBits(a, b)) << name;
    }
    // The first trace was cached in --cache-dir; a seed of its own is traced again and differs.
    auto r = run("render" + view + cache + " --buffer reference.ao --out " + (dir / "again.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("from the cache"), std::string::npos) << r.out;
    r = run("render --scene default --size 32x18 --ao-rays 4 --seed 4" + cache + " --buffer reference.ao --out " +
            (dir / "seed4.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out.find("from the cache"), std::string::npos) << r.out;
    EXPECT_FALSE(sameBits(loadImageFloat((dir / "seed4.exr").string()), loadImageFloat((dir / "ref-ao.exr").string())));

    // compare.error against the formula on the frame's lbuffer and the reference's.
    r = run("render" + view + cache + " --buffer compare.error --out " + (dir / "error.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    r = run("render --scene default --size 32x18 --buffer lbuffer --out " + (dir / "frame.exr").string());
    ASSERT_EQ(r.code, 0) << r.err;
    const FloatImage error = loadImageFloat((dir / "error.exr").string());
    const FloatImage frame = loadImageFloat((dir / "frame.exr").string());
    const FloatImage ref = loadImageFloat((dir / "ref-lbuffer.exr").string());
    ASSERT_EQ(error.channels, 1);
    ASSERT_EQ(error.width * error.height, frame.width * frame.height);
    const auto luminance = [](const FloatImage& i, size_t p) {
        const float* c = &i.pixels[p * static_cast<size_t>(i.channels)];
        return static_cast<double>(static_cast<float>(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]));
    };
    double largest = 0.0;
    for (size_t p = 0; p < error.pixels.size(); ++p) {
        const double l = luminance(frame, p), lr = luminance(ref, p);
        const float expected = static_cast<float>(std::abs(l - lr) / (lr + 1e-3));
        ASSERT_EQ(error.pixels[p], expected) << "pixel " << p;
        largest = std::max(largest, static_cast<double>(error.pixels[p]));
    }
    EXPECT_GT(largest, 0.0);
}

TEST(ReferenceCli, RenderBufferOfTheReferenceBadInput) {
    const fs::path dir = test::tempDir() / "reference-render-bad";
    fs::create_directories(dir);
    // (--record of a reference buffer is allowed since records hold its rays and
    // seed: tests/python/test_records.py.) The reference's options with a GPU buffer: said, not ignored.
    auto r = run("render --scene default --size 8x8 --buffer final --ao-rays 8 --out " + (dir / "x.png").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--buffer final has no reference"), std::string::npos) << r.err;
    r = run("render --scene default --size 8x8 --buffer reference.ao --ao-rays 0 --out " + (dir / "x.exr").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("--ao-rays"), std::string::npos) << r.err;
    // An output that cannot be written fails before the trace.
    r = run("render --scene default --size 8x8 --buffer reference.ao --no-cache --out " +
            (dir / "no-such-folder" / "x.exr").string());
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("cannot write the --out file"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("CPU reference of the view"), std::string::npos) << r.out;
}

}  // namespace

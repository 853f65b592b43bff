// The binary as a user runs it: exit codes, one-line errors naming the file,
// and the files it writes.
#include <gtest/gtest.h>
#include <dlfcn.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "renderer/io/ImageIO.h"
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

fs::path writeText(const std::string& name, const std::string& text) {
    const fs::path p = test::tempDir() / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p;
}

}  // namespace

TEST(Cli, ListsScenesBuffersKnobsAndPasses) {
    const Result scenes = run("list scenes");
    EXPECT_EQ(scenes.code, 0);
    for (const char* s : {"default", "street", "spheres", "fire"}) EXPECT_NE(scenes.out.find(s), std::string::npos);
    const Result buffers = run("list buffers");
    for (const char* b : {"gbuffer.albedo", "gbuffer.normal", "gbuffer.specular", "gbuffer.depth", "lbuffer",
                          "luminance.stats", "final"})
        EXPECT_NE(buffers.out.find(b), std::string::npos) << b;
    const Result knobs = run("list knobs");
    EXPECT_NE(knobs.out.find("lighting.threshold"), std::string::npos);
    EXPECT_NE(knobs.out.find("tonemap.key"), std::string::npos);
    const Result passes = run("list passes");
    EXPECT_EQ(passes.code, 0);
    EXPECT_NE(passes.out.find("reads    ao.filtered (when produced)"), std::string::npos) << passes.out;
    EXPECT_NE(passes.out.find("shadows  [lights]\n  modifies lights.table"), std::string::npos) << passes.out;
    const Result presets = run("list presets");
    EXPECT_EQ(presets.code, 0);
    for (const char* p : {"Low", "Medium", "High", "SSAO1", "SSAO5"}) EXPECT_NE(presets.out.find(p), std::string::npos) << p;
    EXPECT_EQ(run("list widgets").code, 2);
}

// list passes --scene: which passes that scene (its knobs and camera) skips,
// and why, as --timings and the inspector say it (a new user found it never could).
TEST(Cli, ListPassesWithASceneShowsItsSkips) {
    const Result plain = run("list passes --scene default --set dof.enabled=true");
    ASSERT_EQ(plain.code, 0) << plain.err;
    EXPECT_NE(plain.out.find("oit  [lighting]  (skipped: no blended material in the scene)"), std::string::npos) << plain.out;
    EXPECT_EQ(plain.out.find("dof  [post]  (skipped"), std::string::npos) << plain.out;
    EXPECT_NE(plain.out.find("flames  [lighting]  (skipped: the scene has no flame particles)"), std::string::npos)
        << plain.out;
    const Result glass = run("list passes --scene glass");
    ASSERT_EQ(glass.code, 0) << glass.err;
    EXPECT_NE(glass.out.find("oit  [lighting]\n"), std::string::npos) << glass.out;
    EXPECT_NE(glass.out.find("dof  [post]  (skipped: switched off (dof.enabled = false))"), std::string::npos) << glass.out;
    const Result misplaced = run("list knobs --scene glass");
    EXPECT_EQ(misplaced.code, 2);
    EXPECT_NE(misplaced.err.find("apply to 'list passes' and 'list scenes --stats' only"), std::string::npos)
        << misplaced.err;
}

TEST(Cli, RendersPngOfTheRequestedSize) {
    const fs::path out = test::tempDir() / "frame.png";
    const Result r = run("render --scene spheres --size 96x54 --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote"), std::string::npos);
    const FloatImage img = loadImageFloat(out.string());
    EXPECT_EQ(img.width, 96);
    EXPECT_EQ(img.height, 54);
}

// render --memory (README, issue 36): the inspector's GPU memory table after
// the frame, the owners of what passes allocate themselves among the frame
// graph's resources, and the total.
TEST(Cli, RenderMemoryPrintsEveryOwnerAndTheTotal) {
    const fs::path out = test::tempDir() / "memory.png";
    const Result r = run("render --scene glass --size 64x36 --set oit.method=linked_list --set aa.method=taa --memory --out " +
                         out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* row : {"GPU memory (logical bytes", "frame graph: oit.list_nodes", "frame graph: gbuffer.", "shadow maps",
                            "light table", "taa history", "scene geometry", "  total "})
        EXPECT_NE(r.out.find(row), std::string::npos) << row << "\n" << r.out;
    EXPECT_EQ(r.out.find("unowned"), std::string::npos) << r.out;
}

// Every output render writes is checked before the frames: a --record in a
// missing folder failed after --out was written.
TEST(Cli, RenderRefusesAnUnwritableOutputBeforeItRenders) {
    const fs::path out = test::tempDir() / "unwritable-record.png";
    fs::remove(out);
    const fs::path missing = test::tempDir() / "no-such-folder" / "r.json";
    const Result r = run("render --scene spheres --size 16x9 --out " + out.string() + " --record " + missing.string());
    EXPECT_NE(r.code, 0);
    EXPECT_NE(r.err.find("cannot write the --record file: no folder"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

// render --check-finite (issue 10): every buffer the frame produced is read
// back; a clean frame says how many and exits 0. (The non-zero exit naming
// the first bad buffer is FiniteCheck's, tested in extremes_tests.)
TEST(Cli, CheckFiniteReadsEveryProducedBuffer) {
    const fs::path out = test::tempDir() / "finite.png";
    const Result r = run("render --scene spheres --size 96x54 --check-finite --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("check-finite: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("no NaN or infinity"), std::string::npos) << r.out;
    // At least the G-buffer's five targets, the L-buffer and the final image.
    const auto at = r.out.find("check-finite: ");
    EXPECT_GE(std::stoi(r.out.substr(at + 14)), 7) << r.out;
}

TEST(Cli, WritesRawBuffersToExr) {
    const fs::path out = test::tempDir() / "depth.exr";
    ASSERT_EQ(run("render --scene default --size 64x36 --buffer gbuffer.depth --out " + out.string()).code, 0);
    const FloatImage depth = loadImageFloat(out.string());
    EXPECT_EQ(depth.channels, 1);
    const auto s = test::stats(depth, 0);
    // Reversed Z (depth.mode default): 1 at the near plane, 0 at the far
    // plane and on the background.
    EXPECT_GE(s.min, 0.0);
    EXPECT_GT(s.max, 0.0);
    EXPECT_LE(s.max, 1.0);
    const fs::path normal = test::tempDir() / "normal.exr";
    ASSERT_EQ(run("render --scene default --size 64x36 --buffer gbuffer.normal --out " + normal.string()).code, 0);
    EXPECT_EQ(loadImageFloat(normal.string()).channels, 2);
    const fs::path hdr = test::tempDir() / "l.exr";
    ASSERT_EQ(run("render --scene default --size 64x36 --buffer lbuffer --set lighting.threshold=0.02 --out " + hdr.string()).code, 0);
    EXPECT_GT(test::stats(loadImageFloat(hdr.string()), 0).max, 0.0);
}

TEST(Cli, TimingsListEveryPassThatRan) {
    const Result r = run("render --scene default --size 64x36 --frames 3 --timings --out " +
                         (test::tempDir() / "t.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* p : {"geometry", "lighting", "luminance", "tonemap", "frame (total)"})
        EXPECT_NE(r.out.find(p), std::string::npos) << p;
    EXPECT_NE(r.out.find("skipped: nothing this frame consumes"), std::string::npos);
    // The effect passes, each with its own line, and the shadow maps as a
    // span inside lighting.
    for (const char* p : {"\nao ", "\nao_filter ", "\nskybox ", "\nbloom ", "\nfxaa ", "\n  shadow maps "})
        EXPECT_NE(r.out.find(p), std::string::npos) << p << r.out;
    EXPECT_NE(r.out.find("skipped: switched off (dof.enabled = false)"), std::string::npos) << r.out;
    // Then the cost counters, the same in the three counted frames: the tone
    // mapper's full-screen triangle passes a sample per pixel, 1 primitive, 3 vertices.
    EXPECT_NE(r.out.find("cost counters per frame (exact; the same in all 3 counted frame(s))\n"
                         "pass                  fragments        samples     primitives       vertices        compute"
                         "          bytes\n"),
              std::string::npos)
        << r.out;
    const size_t tonemap = r.out.find("\ntonemap ", r.out.find("cost counters per frame"));
    ASSERT_NE(tonemap, std::string::npos) << r.out;
    std::istringstream line(r.out.substr(tonemap + 1, r.out.find('\n', tonemap + 1) - tonemap - 1));
    std::string name;
    long long fragments = 0, samples = 0, primitives = 0, vertices = 0;
    line >> name >> fragments >> samples >> primitives >> vertices;
    EXPECT_EQ(samples, 64 * 36);
    EXPECT_GE(fragments, 64 * 36);
    EXPECT_EQ(primitives, 1);
    EXPECT_EQ(vertices, 3);
    const Result dof = run("render --scene default --size 64x36 --set dof.enabled=true --set ao.enabled=false --timings --out " +
                           (test::tempDir() / "t.png").string());
    ASSERT_EQ(dof.code, 0) << dof.err;
    EXPECT_NE(dof.out.find("\ndof "), std::string::npos) << dof.out;
    EXPECT_NE(dof.out.find("skipped: switched off (ao.enabled = false)"), std::string::npos) << dof.out;
}

TEST(Cli, WritesEffectBuffers) {
    const fs::path ao = test::tempDir() / "ao.exr";
    ASSERT_EQ(run("render --scene default --size 64x36 --buffer ao.filtered --out " + ao.string()).code, 0);
    const FloatImage aoImg = loadImageFloat(ao.string());
    EXPECT_EQ(aoImg.width, 64);
    const auto aoStats = test::stats(aoImg, 0);
    EXPECT_GE(aoStats.min, 0.0);
    EXPECT_LT(aoStats.min, 0.9);  // the courtyard has creases
    EXPECT_LE(aoStats.max, 1.0 + 1e-3);

    // Every shadow-casting light's map (the sun and two spots of the default
    // scene), kept although maps are reused by default, as a 2x2 grid of layers.
    const fs::path shadow = test::tempDir() / "shadow.exr";
    ASSERT_EQ(run("render --scene default --size 64x36 --set shadows.map_size=128 --buffer shadow.maps --out " +
                  shadow.string()).code, 0);
    const FloatImage maps = loadImageFloat(shadow.string());
    ASSERT_EQ(maps.width, 256);
    ASSERT_EQ(maps.height, 256);
    for (int layer = 0; layer < 3; ++layer) {
        double lo = 1.0, hi = 0.0;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                const float d = maps.at(128 * (layer % 2) + x, 128 * (layer / 2) + y, 0);
                lo = std::min(lo, static_cast<double>(d));
                hi = std::max(hi, static_cast<double>(d));
            }
        EXPECT_GE(lo, 0.0) << layer;
        EXPECT_LE(hi, 1.0) << layer;
        EXPECT_GT(hi - lo, 1e-3) << layer;  // geometry in every map (perspective depth crowds near 1), not a cleared layer
    }

    const fs::path mip = test::tempDir() / "mip.exr";
    ASSERT_EQ(run("render --scene street --size 128x72 --buffer bloom.mip2 --out " + mip.string()).code, 0);
    const FloatImage mipImg = loadImageFloat(mip.string());
    EXPECT_LT(mipImg.width, 64);
    EXPECT_GT(test::stats(mipImg, 0).max, 0.0);  // street lamps are above the threshold

    const fs::path png = test::tempDir() / "bloom.png";
    ASSERT_EQ(run("render --scene street --size 128x72 --buffer bloom.result --out " + png.string()).code, 0);
    const FloatImage bloomPng = loadImageFloat(png.string());
    EXPECT_EQ(bloomPng.width, 64);  // half size
    EXPECT_GT(test::stats(bloomPng, 0).max, 0.2);  // the lamps' glow, tone-mapped for display
}

TEST(Cli, PresetsApplyBeforeSetAndBadOnesAreOneLineErrors) {
    const Result builtin = run("render --scene spheres --size 64x36 --preset SSAO1 --timings --out " +
                               (test::tempDir() / "p.png").string());
    ASSERT_EQ(builtin.code, 0) << builtin.err;
    EXPECT_NE(builtin.out.find("8 samples at 16x9"), std::string::npos) << builtin.out;  // quarter resolution
    // --set wins over the preset.
    const Result over = run("render --scene spheres --size 64x36 --preset SSAO1 --set ssao.resolution=full --timings --out " +
                            (test::tempDir() / "p.png").string());
    ASSERT_EQ(over.code, 0) << over.err;
    EXPECT_NE(over.out.find("8 samples at 64x36"), std::string::npos) << over.out;
    // A preset file names its scene; without --scene that scene is rendered.
    const fs::path file = writeText("street-preset.json", R"({"name": "dim street", "scene": "street",
        "knobs": {"bloom.enabled": "false", "tonemap.exposure": "-1"}})");
    const Result fromFile = run("render --size 64x36 --preset " + file.string() + " --timings --out " +
                                (test::tempDir() / "p.png").string());
    ASSERT_EQ(fromFile.code, 0) << fromFile.err;
    EXPECT_NE(fromFile.out.find("scene street"), std::string::npos) << fromFile.out;
    EXPECT_NE(fromFile.out.find("skipped: switched off (bloom.enabled = false)"), std::string::npos) << fromFile.out;

    const fs::path bad = writeText("bad-preset.json", R"({"name": "typo", "knobs": {"ssao.sampels": "8"}})");
    const Result r = run("render --size 32x32 --preset " + bad.string() + " --out x.png");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(bad.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("ssao.sampels"), std::string::npos) << r.err;
    const fs::path broken = writeText("broken-preset.json", "{\"knobs\": [1, 2");
    const Result b = run("render --size 32x32 --preset " + broken.string() + " --out x.png");
    EXPECT_EQ(b.code, 1);
    EXPECT_EQ(lines(b.err), 1) << b.err;
    EXPECT_NE(b.err.find(broken.string()), std::string::npos) << b.err;
    EXPECT_EQ(run("render --size 32x32 --preset NoSuchPreset --out x.png").code, 1);
}

TEST(Cli, MalformedSceneJsonIsOneLineNamingTheFile) {
    const fs::path bad = writeText("bad.json", "{\n  \"lights\": [ {\"pos\": [0, 1, 0],, } ]\n}\n");
    const Result r = run("render --scene " + bad.string() + " --out x.png");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(bad.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
}

TEST(Cli, BrokenGltfAndMissingTextureAreOneLineErrors) {
    const fs::path gltf = writeText("broken.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 12, "uri": "gone.bin"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": 1, "type": "VEC3"}],
        "bufferViews": [{"buffer": 0, "byteLength": 12}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})");
    const Result r = run("render --scene " + gltf.string() + " --out x.png");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(gltf.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("gone.bin"), std::string::npos) << r.err;

    const fs::path tex = writeText("textured.json", R"({"materials": {"m": {"diffuse-map": "textures/brick.png"}},
        "objects": [{"shape": "box", "material": "m"}]})");
    const Result t = run("render --scene " + tex.string() + " --out x.png");
    EXPECT_EQ(t.code, 1);
    EXPECT_EQ(lines(t.err), 1) << t.err;
    EXPECT_NE(t.err.find(tex.string()), std::string::npos) << t.err;
    EXPECT_NE(t.err.find("missing texture 'textures/brick.png'"), std::string::npos) << t.err;
}

TEST(Cli, BadArgumentsExitWithUsageOrError) {
    EXPECT_EQ(run("render --scene default --size big --out x.png").code, 2);
    EXPECT_EQ(run("render --scene default").code, 2);
    EXPECT_EQ(run("frobnicate").code, 2);
    const Result knob = run("render --scene default --set lighting.treshold=0.1 --out x.png");
    EXPECT_EQ(knob.code, 1);
    EXPECT_NE(knob.err.find("did you mean 'lighting.threshold'"), std::string::npos) << knob.err;
    const Result range = run("render --scene default --set tonemap.key=7 --out x.png");
    EXPECT_EQ(range.code, 1);
    EXPECT_NE(range.err.find("out of range"), std::string::npos) << range.err;
    const Result buffer = run("render --scene default --size 32x32 --buffer gbuffer.nope --out x.png");
    EXPECT_EQ(buffer.code, 1);
    EXPECT_NE(buffer.err.find("unknown buffer 'gbuffer.nope'"), std::string::npos) << buffer.err;
    const Result scene = run("render --scene nowhere.glb --out x.png");
    EXPECT_EQ(scene.code, 1);
    EXPECT_NE(scene.err.find("nowhere.glb"), std::string::npos) << scene.err;
    const Result out = run("render --scene default --size 32x32 --out " + (test::tempDir() / "x.unknownext").string());
    EXPECT_EQ(out.code, 1);
}

// No command writes over the files it reads or another output of its own:
// a scene, a preset or an events file named as an output is refused before
// anything runs, and stays as it was (found by a new user: bench --json and
// render --timings-out replaced the scene they rendered).
TEST(Cli, OutputsNeverReplaceTheirInputs) {
    const fs::path scene = writeText("own-scene.json", R"({"objects": [{"shape": "plane", "size": [10, 0, 10]}]})");
    const fs::path preset = writeText("own-preset.json", R"({"name": "p", "knobs": {"bloom.enabled": "false"}})");
    auto contents = [](const fs::path& p) {
        std::ifstream in(p);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const std::string sceneText = contents(scene), presetText = contents(preset);
    const std::string png = (test::tempDir() / "own.png").string();
    for (const std::string& args :
         {"render --scene " + scene.string() + " --size 32x18 --timings-out " + scene.string() + " --out " + png,
          "render --scene " + scene.string() + " --size 32x18 --dump-knobs " + scene.string() + " --out " + png,
          "render --scene " + scene.string() + " --size 32x18 --out " + scene.string(),
          "render --scene " + scene.string() + " --preset " + preset.string() + " --size 32x18 --timings-out " +
              preset.string() + " --out " + png,
          "render --scene " + scene.string() + " --size 32x18 --timings-out " + png + " --out " + png,
          "bench --scene " + scene.string() + " --size 32x18 --frames 1 --json " + scene.string(),
          "bench --scene " + scene.string() + " --preset " + preset.string() + " --size 32x18 --frames 1 --csv " +
              preset.string(),
          "gui --scene " + scene.string() + " --frames 2 --dump-knobs " + scene.string()}) {
        const Result r = run(args);
        EXPECT_EQ(r.code, 2) << args << ": " << r.err;
        EXPECT_NE(r.err.find("are the same file"), std::string::npos) << args << ": " << r.err;
    }
    EXPECT_EQ(contents(scene), sceneText);
    EXPECT_EQ(contents(preset), presetText);
}

TEST(Cli, UsageComesFromTheCommandTable) {
    const Result help = run("help");
    ASSERT_EQ(help.code, 0);
    for (const char* c : {"deferred-workbench gui ", "deferred-workbench render ", "deferred-workbench list "})
        EXPECT_NE(help.out.find(c), std::string::npos) << c << help.out;
    EXPECT_EQ(run("--help").out, help.out);
    // "help COMMAND" is "COMMAND --help".
    const Result renderHelp = run("help render");
    EXPECT_EQ(renderHelp.code, 0);
    EXPECT_EQ(renderHelp.out, run("render --help").out);
    EXPECT_NE(renderHelp.out.find("--warmup"), std::string::npos) << renderHelp.out;
    EXPECT_EQ(run("list --help").code, 0);
    // An unknown command: one line naming it, then the usage, on stderr; exit 2.
    const Result unknown = run("frobnicate");
    EXPECT_EQ(unknown.code, 2);
    EXPECT_TRUE(unknown.out.empty()) << unknown.out;
    EXPECT_EQ(unknown.err.rfind("deferred-workbench: unknown command 'frobnicate'\n", 0), 0u) << unknown.err;
    EXPECT_NE(unknown.err.find("deferred-workbench render "), std::string::npos) << unknown.err;
    EXPECT_EQ(run("help frobnicate").code, 2);
}

// The run configuration's order, as render applies it: defaults, the scene's
// settings, the preset, --set; --scene wins over the preset's scene.
TEST(Cli, DumpKnobsShowsSceneSettingsThenPresetThenSet) {
    const fs::path scene = writeText("with-settings.json", R"({"name": "with settings",
        "settings": {"tonemap.key": 0.1, "bloom.intensity": 0.3}, "objects": [{"shape": "box"}]})");
    const fs::path preset = writeText("street-look.json", R"({"name": "street look", "scene": "street",
        "knobs": {"bloom.intensity": 0.9, "ssao.samples": 8}})");
    const fs::path dump = test::tempDir() / "render-knobs.txt";
    const Result r = run("render --scene " + scene.string() + " --preset " + preset.string() +
                         " --set ssao.samples=4 --size 32x18 --out " + (test::tempDir() / "k.png").string() +
                         " --dump-knobs " + dump.string());
    ASSERT_EQ(r.code, 0) << r.err;
    auto k = test::readKnobDump(dump);
    EXPECT_EQ(k["#scene"], scene.string());        // --scene, not the preset's street
    EXPECT_EQ(k["tonemap.key"], "0.1");            // the scene's setting
    EXPECT_EQ(k["bloom.intensity"], "0.9");        // the preset over the scene
    EXPECT_EQ(k["ssao.samples"], "4");             // --set over the preset
    EXPECT_EQ(k["ssao.resolution"], "half");       // untouched: the default
    EXPECT_GT(k.size(), 40u);                      // every knob

    // Without --scene the preset's scene opens, with its own settings.
    const Result p = run("render --preset " + preset.string() + " --size 32x18 --out " +
                         (test::tempDir() / "k.png").string() + " --dump-knobs " + dump.string());
    ASSERT_EQ(p.code, 0) << p.err;
    k = test::readKnobDump(dump);
    EXPECT_EQ(k["#scene"], "builtin:street");
    EXPECT_EQ(k["tonemap.key"], "0.05");  // the street at night is seen with a low key
    EXPECT_EQ(k["bloom.intensity"], "0.9");
    EXPECT_EQ(k["ssao.samples"], "8");
}

// Warm-up frames are rendered but left out: every pass that ran and the total
// report exactly the counted frames, in the table and in the JSON.
TEST(Cli, TimingsCountOnlyTheFramesAfterWarmup) {
    const fs::path json = test::tempDir() / "timings.json";
    const fs::path csv = test::tempDir() / "timings.csv";
    const Result r = run("render --scene default --size 64x36 --frames 3 --warmup 2 --timings --timings-out " + json.string() +
                         " --out " + (test::tempDir() / "t.png").string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("timings over 3 frame(s) after 2 warm-up frame(s)\n"), std::string::npos) << r.out;
    // The last column of every timed line (passes, spans, total) is the frame count.
    std::istringstream lines(r.out.substr(r.out.find("\npass ") + 1));
    std::string line;
    std::getline(lines, line);  // the header
    int timed = 0;
    while (std::getline(lines, line)) {
        if (line.rfind("cost counters per frame", 0) == 0) break;  // the counters' table follows the timings
        if (line.find("(skipped: ") != std::string::npos || line.rfind("  (", 0) == 0) continue;
        EXPECT_EQ(line.substr(line.size() - 3), "  3") << line;
        ++timed;
    }
    EXPECT_GE(timed, 10) << r.out;  // passes, the shadow-map span and the total
    EXPECT_NE(r.out.find("\nframe (total) "), std::string::npos);

    std::ifstream in(json);
    const auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["frames"], 3);
    EXPECT_EQ(j["warmup"], 2);
    EXPECT_EQ(j["total"]["frames"], 3);
    for (const auto& p : j["passes"]) {
        if (p["ran"] == true) {
            EXPECT_EQ(p["frames"], 3) << p["name"];
        }
    }

    // The default warm-up with timings is one frame; CSV rows by extension.
    const Result d = run("render --scene default --size 64x36 --frames 2 --timings-out " + csv.string() + " --out " +
                         (test::tempDir() / "t.png").string());
    ASSERT_EQ(d.code, 0) << d.err;
    EXPECT_EQ(d.out.find("timings over"), std::string::npos) << "no table without --timings";
    std::ifstream c(csv);
    std::string header;
    std::getline(c, header);
    EXPECT_EQ(header.rfind("series,kind,ran,frames,gpu_median_ms,", 0), 0u) << header;
    std::string total;
    while (std::getline(c, line)) total = line;
    EXPECT_EQ(total.rfind("frame,total,1,2,", 0), 0u) << total;
    EXPECT_EQ(run("render --scene default --frames 3 --warmup -1 --timings --out x.png").code, 2);
}

// render --renderdoc-capture: one RenderDoc capture of the last frame, when
// Debian's librenderdoc is installed (scripts/test.sh installs it); a clear
// error otherwise.
TEST(Cli, RenderdocCaptureWritesANonEmptyCaptureFile) {
    const fs::path dir = test::tempDir() / "renderdoc-cli";
    fs::remove_all(dir);
    fs::create_directories(dir);
    void* lib = dlopen("librenderdoc.so", RTLD_LAZY | RTLD_LOCAL);
    if (lib && !test::renderDocCaptureUnavailable().empty()) {
        dlclose(lib);
        GTEST_SKIP() << test::renderDocCaptureUnavailable();
    }
    const Result r = run("render --scene spheres --size 64x36 --out " + (dir / "f.png").string() + " --renderdoc-capture " +
                         (dir / "frame.rdc").string());
    if (!lib) {
        EXPECT_EQ(r.code, 1);
        EXPECT_NE(r.err.find("librenderdoc"), std::string::npos) << r.err;
        GTEST_SKIP() << "librenderdoc.so is not installed (Debian package librenderdoc)";
    }
    dlclose(lib);
    ASSERT_EQ(r.code, 0) << r.err;
    const fs::path capture = dir / "frame_capture.rdc";
    ASSERT_TRUE(fs::exists(capture)) << r.out;
    EXPECT_GT(fs::file_size(capture), 10000u);
    EXPECT_NE(r.out.find(capture.string()), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir / "f.png"));
}

// Transparency (issue 21): `render --buffer oit.sample_count` writes every
// pixel's transparent fragment count (the glass scene is deeper than 8
// somewhere, and the 4- or 8-sample A-buffer's overflow is the rest);
// the default scene has no blended material, and --timings says the oit
// pass was skipped and why.
TEST(Cli, WritesTransparencySampleCounts) {
    const fs::path counts = test::tempDir() / "oit_counts.exr";
    const Result r = run("render --scene glass --size 160x90 --set oit.method=abuffer --set oit.samples=4 --buffer "
                         "oit.sample_count --out " + counts.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const FloatImage c = loadImageFloat(counts.string());
    EXPECT_EQ(c.channels, 1);
    const auto s = test::stats(c, 0);
    EXPECT_EQ(s.min, 0.0);
    EXPECT_GT(s.max, 8.0);
    EXPECT_EQ(s.max, std::floor(s.max));  // counts, not a display mapping
    const fs::path overflow = test::tempDir() / "oit_overflow.exr";
    ASSERT_EQ(run("render --scene glass --size 160x90 --set oit.method=abuffer --set oit.samples=4 --buffer "
                  "oit.overflow --out " + overflow.string()).code, 0);
    const FloatImage o = loadImageFloat(overflow.string());
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x)
            ASSERT_EQ(o.at(x, y, 0), std::max(0.0f, c.at(x, y, 0) - 4.0f)) << x << ", " << y;
    const Result skipped = run("render --scene default --size 64x36 --timings --out " + (test::tempDir() / "t.png").string());
    ASSERT_EQ(skipped.code, 0) << skipped.err;
    EXPECT_NE(skipped.out.find("(skipped: no blended material in the scene)"), std::string::npos) << skipped.out;
    const Result wrong = run("render --scene glass --size 64x36 --set oit.method=weighted --buffer oit.abuffer --out " +
                             (test::tempDir() / "x.png").string());
    EXPECT_NE(wrong.code, 0);
    EXPECT_NE(wrong.err.find("oit.abuffer is written only with oit.method=abuffer"), std::string::npos) << wrong.err;
}

// Issue 32: a plain render says in one line when the oit pass lost
// fragments (the 4-sample A-buffer on the glass scene), with the count that
// oit.overflow sums to; the exact list loses none there and says nothing.
// A blended pane of emission 1e30 is clamped (65000, the G-buffer's bound,
// as for opaque surfaces and the reference) with a warning naming the file
// and the material: the L-buffer stays finite.
TEST(Cli, RenderSaysWhenTransparencyLosesFragments) {
    const fs::path overflow = test::tempDir() / "oit_lost.exr";
    const Result r = run("render --scene glass --size 160x90 --set oit.method=abuffer --set oit.samples=4 --buffer "
                         "oit.overflow --out " + overflow.string());
    ASSERT_EQ(r.code, 0) << r.err;
    const FloatImage o = loadImageFloat(overflow.string());
    double lost = 0;
    for (float v : o.pixels) lost += v;
    ASSERT_GT(lost, 0.0);
    const std::string line = "warning: oit: lost " + std::to_string(static_cast<long long>(lost)) + " of ";
    const size_t at = r.err.find(line);
    ASSERT_NE(at, std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("warning: oit:", at + 1), std::string::npos) << "one line: " << r.err;
    const std::string rest = r.err.substr(at, r.err.find('\n', at) - at);
    EXPECT_NE(rest.find(" transparent fragments this frame (abuffer keeps 4 per pixel (oit.samples = 4), the first to "
                        "arrive); oit.overflow shows where"),
              std::string::npos)
        << rest;
    const Result exact = run("render --scene glass --size 160x90 --out " + (test::tempDir() / "oit_exact.png").string());
    ASSERT_EQ(exact.code, 0) << exact.err;
    EXPECT_EQ(exact.err.find("oit:"), std::string::npos) << exact.err;

    const fs::path hot = test::tempDir() / "oit_hot.json";
    std::ofstream(hot) << R"({"camera": {"pos": [0, 0, 10], "look-at": [0, 0, 0]},
        "objects": [{"shape": "plane", "size": [40, 0, 40], "rotate": [90, 0, 0], "name": "hot",
                     "material": {"diffuse": [0.5, 0.5, 0.5], "emissive": [1e30, 1e30, 1e30], "opacity": 0.5}}]})";
    const Result clamped = run("render --scene " + hot.string() + " --size 32x18 --check-finite --buffer lbuffer --out " +
                               (test::tempDir() / "oit_hot.exr").string());
    ASSERT_EQ(clamped.code, 0) << clamped.err;
    EXPECT_NE(clamped.err.find(hot.string() + ": material 'objects[0]': emissive 1e+30 is beyond 65000"), std::string::npos)
        << clamped.err;
    EXPECT_NE(clamped.out.find("no NaN or infinity"), std::string::npos) << clamped.out;
}

// Issue 36 part 4: the documented `render --scene fire --buffer flames.result`
// writes the flames alone: not empty, finite, and `--timings` times the
// flames pass; with flames.enabled=false the pass says why it did not run.
TEST(Cli, FireSceneWritesItsFlamesAndTimesTheFlamesPass) {
    const fs::path out = test::tempDir() / "flames.exr";
    const Result r = run("render --scene fire --size 96x54 --buffer flames.result --timings --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("flames"), std::string::npos) << r.out;
    const FloatImage flames = loadImageFloat(out.string());
    ASSERT_GE(flames.channels, 3);
    int lit = 0;
    for (int y = 0; y < flames.height; ++y)
        for (int x = 0; x < flames.width; ++x) lit += flames.at(x, y, 0) > 0.01f;
    EXPECT_GT(lit, 20);
    EXPECT_EQ(test::stats(flames, 0).nonFinite, 0);
    const Result off = run("render --scene fire --size 32x18 --set flames.enabled=false --buffer flames.result --out " +
                           (test::tempDir() / "no-flames.exr").string());
    EXPECT_NE(off.code, 0);
    EXPECT_NE((off.out + off.err).find("flames.enabled = false"), std::string::npos) << off.out << off.err;
}

// Issue 36 part 3: `list scenes --stats` (seed 000 table 6.1). The spheres
// scene's counts derived here from how it is built: a floor plane (2
// triangles) and 36 spheres of 48 slices x 24 stacks (2 x 48 x 24 triangles
// each); a key, two point lights and a spot. Its directional light reaches
// every surface pixel, so LPP lit is at least 1 and LPP at most the 4 lights.
TEST(Cli, SceneStatisticsCountObjectsTrianglesAndLights) {
    const fs::path duck = test::dataDir() / "gltf" / "Duck" / "Duck.gltf";
    const bool gltf = fs::exists(duck);
    const Result r = run("list scenes --stats --size 48x27 --poses 2" + (gltf ? " --scene " + duck.string() : std::string()));
    ASSERT_EQ(r.code, 0) << r.err;
    const auto at = r.out.find("| spheres | ");
    ASSERT_NE(at, std::string::npos) << r.out;
    std::istringstream row(r.out.substr(at + 12));
    long long objects = 0, triangles = 0, lights = 0;
    char bar = 0;
    row >> objects >> bar >> triangles >> bar >> lights;
    EXPECT_EQ(objects, 1 + 36);
    EXPECT_EQ(triangles, 2 + 36 * 2 * 48 * 24);
    EXPECT_EQ(lights, 4);
    EXPECT_NE(r.out.find("| spheres | 37 | 82946 | 4 | 1 / 2 / 1 | "), std::string::npos) << r.out;
    std::string rest;
    std::getline(row, rest);
    double lpp = 0, lo = 0, hi = 0, lit = 0;
    ASSERT_EQ(std::sscanf(rest.c_str(), " | 1 / 2 / 1 | %lf | [%lf, %lf] | %lf |", &lpp, &lo, &hi, &lit), 4) << rest;
    EXPECT_GE(lit, 1.0);
    EXPECT_LE(lpp, 4.0);
    EXPECT_LE(lo, lpp);
    EXPECT_GE(hi, lpp);
    for (const char* s : {"| default |", "| street |", "| glass |", "| fire |", "| atrium |"})
        EXPECT_NE(r.out.find(s), std::string::npos) << s;
    // README's command: a glTF's row after the built-in ones (the Duck: one mesh of 4212 triangles).
    if (gltf) {
        EXPECT_NE(r.out.find("| " + duck.string() + " | 1 | 4212 | "), std::string::npos) << r.out;
    }
    EXPECT_EQ(run("list knobs --stats").code, 2);
}

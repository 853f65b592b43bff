// --animation NAME|INDEX|none (issue 36) as a user runs it: the test's
// animated glTF (tests/support/AnimatedGltf.h, one clip "move") rendered
// with no clip is the same image at 0 s and 0.5 s, with "move" (by name or
// index) at 0.5 s another; an unknown clip is one line naming the clips,
// exit 1, nothing written; a record keeps the choice.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/support/AnimatedGltf.h"
#include "tests/support/GltfBuilder.h"
#include "tests/support/TestSupport.h"

namespace fs = std::filesystem;

namespace dw {
namespace {

std::string bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Renders the animated glTF with `args`; returns the PNG's bytes.
std::string render(const std::string& scene, const std::string& args, const std::string& name) {
    const fs::path out = test::tempDir() / name;
    const auto r = test::runWorkbench("render --scene " + scene + " --size 160x90 " + args + " --out " + out.string());
    EXPECT_EQ(r.code, 0) << args << ": " << r.err;
    return bytes(out);
}

TEST(AnimationCli, TheClipChosenByNameIndexOrNonePlays) {
    const std::string scene = test::writeJson("animation-cli.gltf", test::animatedGltf()).string();
    const std::string none0 = render(scene, "--animation none --scene-time 0", "none-0.png");
    const std::string none05 = render(scene, "--animation none --scene-time 0.5", "none-05.png");
    const std::string move05 = render(scene, "--animation move --scene-time 0.5", "move-05.png");
    const std::string index05 = render(scene, "--animation 0 --scene-time 0.5", "index-05.png");
    const std::string default05 = render(scene, "--scene-time 0.5", "default-05.png");
    ASSERT_FALSE(none0.empty());
    EXPECT_EQ(none0, none05);      // no clip: the time moves nothing
    EXPECT_NE(move05, none05);     // the clip does
    EXPECT_EQ(move05, index05);    // by name or by index
    EXPECT_EQ(move05, default05);  // the file's first is the default
}

TEST(AnimationCli, AnUnknownClipIsOneLineNamingTheClips) {
    const std::string scene = test::writeJson("animation-cli-bad.gltf", test::animatedGltf()).string();
    const fs::path out = test::tempDir() / "unknown-clip.png";
    const auto r = test::runWorkbench("render --scene " + scene + " --size 160x90 --animation jump --out " + out.string());
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("--animation 'jump': the scene has no such clip; its clips: 0 'move' (or none)"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(AnimationCli, ARecordKeepsTheClipChoice) {
    const std::string scene = test::writeJson("animation-cli-record.gltf", test::animatedGltf()).string();
    const fs::path record = test::tempDir() / "animation-record.json";
    render(scene, "--animation none --scene-time 0.5 --record " + record.string(), "record.png");
    const nlohmann::json j = nlohmann::json::parse(bytes(record));
    EXPECT_EQ(j.value("animation", ""), "none");
}

// render --time-steps N --frame-rate F --out-sequence: an animated scene's
// frames over scene time at one camera (issue 35 part 4: the temporal
// error of an animated scene), frame k at --scene-time + k / F: frame 1 at
// 2 frames a second from 0 is the 0.5 s render, and the clip moves it; the
// frames are what compare --sequence reads (against themselves: temporal
// error 0). --frame-rate without --time-steps is one line, exit 2.
TEST(AnimationCli, TimeStepsRenderTheSceneTimesAsASequence) {
    const std::string scene = test::writeJson("animation-steps.gltf", test::animatedGltf()).string();
    const fs::path dir = test::tempDir() / "animation-steps";
    fs::create_directories(dir);
    const std::string pattern = (dir / "f%d.png").string();
    const auto r = test::runWorkbench("render --scene " + scene + " --size 160x90 --time-steps 3 --frame-rate 2 "
                                      "--out-sequence " + pattern);
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string at05 = render(scene, "--scene-time 0.5", "steps-05.png");
    const std::string at0 = render(scene, "--scene-time 0", "steps-0.png");
    EXPECT_EQ(bytes(dir / "f1.png"), at05);
    EXPECT_EQ(bytes(dir / "f0.png"), at0);
    EXPECT_NE(bytes(dir / "f1.png"), bytes(dir / "f0.png"));
    const auto same = test::runWorkbench("compare --sequence " + pattern + " " + pattern);
    EXPECT_EQ(same.code, 0) << same.err << same.out;
    EXPECT_NE(same.out.find("temporal"), std::string::npos) << same.out;
    const auto bad = test::runWorkbench("render --scene " + scene + " --size 160x90 --frame-rate 2 --out " +
                                        (dir / "x.png").string());
    EXPECT_EQ(bad.code, 2) << bad.err;
    EXPECT_NE(bad.err.find("--frame-rate is --time-steps N's frames per second"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace dw

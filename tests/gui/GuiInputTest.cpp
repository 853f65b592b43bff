// The workbench's text fields, shortcuts and scene opening driven by input
// events under Xvfb: scripted events (gui --events, which go through the same
// input queue as the window's), and real X events from xdotool.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "renderer/inspect/PixelProbe.h"
#include "tests/gui/HeadlessImGui.h"
#include "ui/UiState.h"
#include "tests/support/TestSupport.h"
#include "ui/ProbePanel.h"

using namespace dw;
namespace fs = std::filesystem;

namespace {

fs::path writeFile(const std::string& name, const std::string& text) {
    const fs::path p = test::tempDir() / name;
    std::ofstream(p) << text;
    return p;
}

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

// The window under Xvfb at 1024x640 for `frames` frames replaying `events`;
// its --layout-out report (null when it failed).
nlohmann::json runEvents(const std::string& name, int frames, const std::string& events, const std::string& extra = "") {
    const fs::path ev = writeFile(name + "-events.txt", events), out = test::tempDir() / (name + "-layout.json");
    const test::CommandResult r =
        test::runCommand("xvfb-run -a -s '-screen 0 1100x700x24' " + std::string(DW_WORKBENCH_BINARY) +
                         " --scene spheres --set ao.enabled=false --size 1024x640 --frames " + std::to_string(frames) +
                         " --events " + ev.string() + " --layout-out " + out.string() + " " + extra);
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    return r.code == 0 ? readJson(out) : nlohmann::json();
}

std::string validScene() { return (test::scenesDir() / "spotlights.json").string(); }

fs::path brokenGltf() {
    // Cut short in the middle of its JSON, as a failed download leaves it.
    return writeFile("cut-short.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"scenes\": [{\"nodes\": [0");
}

}  // namespace

TEST(GuiInput, CtrlOThenTypingAPathOverOldTextAndEnterOpensTheScene) {
    ASSERT_EQ(test::runCommand("command -v xvfb-run").code, 0) << "xvfb-run is missing (scripts/setup-deps.sh installs it)";
    ASSERT_TRUE(fs::exists(validScene()));
    // Ctrl+O focuses the path field; old text typed there (its 'a's are no
    // shortcut: the axes stay off), Ctrl+A selects it, the path replaces it,
    // Enter opens. Each key is pressed and released within one frame.
    const nlohmann::json r = runEvents("open-typed", 16,
                                       "1 key ctrl+o\n3 type a wrong start\n5 key ctrl+a\n6 type " + validScene() +
                                           "\n8 key Enter\n");
    ASSERT_FALSE(r.is_null());
    EXPECT_EQ(r["scene"]["source"].get<std::string>(), validScene());
    EXPECT_EQ(r["errors"].size(), 0u) << r["errors"].dump();
    EXPECT_FALSE(r["axes"].get<bool>()) << "a key typed into the path field toggled the axes";
    ASSERT_GE(r["recent_scenes"].size(), 1u);
    EXPECT_EQ(r["recent_scenes"][0].get<std::string>(), fs::absolute(validScene()).lexically_normal().string());
}

TEST(GuiInput, HomeAndEndEditThePathAndTheOpenButtonOpensIt) {
    const fs::path dir = fs::path(validScene()).parent_path();
    // The field gets "spotlights.json", Home, the folder in front, End, then a click on *open*.
    const nlohmann::json first = runEvents("open-button-where", 2, "");
    ASSERT_FALSE(first.is_null());
    ASSERT_TRUE(first["items"].contains("scene.open")) << first["items"].dump();
    const auto open = first["items"]["scene.open"];
    const float x = open["x"].get<float>() + open["w"].get<float>() * 0.5f, y = open["y"].get<float>() + open["h"].get<float>() * 0.5f;
    const nlohmann::json r = runEvents("open-home-end", 16,
                                       "1 key ctrl+o\n3 type spotlights\n4 key Home\n5 type " + dir.string() +
                                           "/\n7 key End\n8 type .json\n10 click " + std::to_string(x) + " " +
                                           std::to_string(y) + "\n");
    ASSERT_FALSE(r.is_null());
    EXPECT_EQ(r["scene"]["source"].get<std::string>(), validScene());
}

TEST(GuiInput, ABrokenSceneFileShowsWhyInTheBannerAndKeepsTheScene) {
    const fs::path broken = brokenGltf();
    const nlohmann::json r = runEvents("open-broken", 12, "1 key ctrl+o\n3 type " + broken.string() + "\n5 key Enter\n");
    ASSERT_FALSE(r.is_null());
    EXPECT_EQ(r["scene"]["name"].get<std::string>(), "spheres") << "the scene that failed replaced the one shown";
    const std::string banner = r["banner"].get<std::string>();
    EXPECT_NE(banner.find(broken.string()), std::string::npos) << banner;
    EXPECT_NE(banner.find("cannot open scene"), std::string::npos) << banner;
    // A reason, not only the name: the JSON parser's words (where it ended).
    EXPECT_GT(banner.size(), broken.string().size() + 30) << banner;
    // An empty field says what to do instead of doing nothing.
    const nlohmann::json empty = runEvents("open-empty", 8, "1 key ctrl+o\n3 key Enter\n");
    ASSERT_FALSE(empty.is_null());
    EXPECT_NE(empty["banner"].get<std::string>().find("type a file's path"), std::string::npos) << empty["banner"];
}

TEST(GuiInput, AFileDroppedOnTheWindowOpensAsTheSceneAndTheProbeDropsTheOldScenesValues) {
    // The probe read a pixel of the old scene, then the mouse left the viewport.
    const nlohmann::json hovered = runEvents("drop-hover", 6, "2 move 500 250\n4 move 60 600\n");
    ASSERT_FALSE(hovered.is_null());
    EXPECT_TRUE(hovered["probe"]["shows_values"].get<bool>()) << "the probe read nothing to begin with";
    const nlohmann::json r = runEvents("drop", 10, "2 move 500 250\n4 move 60 600\n6 drop " + validScene() + "\n");
    ASSERT_FALSE(r.is_null());
    EXPECT_EQ(r["scene"]["source"].get<std::string>(), validScene());
    EXPECT_FALSE(r["probe"]["shows_values"].get<bool>()) << "the probe still shows the previous scene's pixel";
}

TEST(GuiInput, EnterInThePresetNameFieldSavesAndOneClickLoadsABuiltInPreset) {
    const fs::path presets = test::tempDir() / "typed-presets";
    fs::remove_all(presets);
    const nlohmann::json where = runEvents("preset-where", 2, "", "--presets " + presets.string());
    ASSERT_FALSE(where.is_null());
    const auto name = where["items"]["presets.name"];
    const auto low = where["items"]["presets.builtin.Low"];
    ASSERT_TRUE(where["items"].contains("presets.name")) << where["items"].dump();
    ASSERT_TRUE(where["items"].contains("presets.builtin.Low")) << where["items"].dump();
    auto centre = [](const nlohmann::json& r) {
        return std::to_string(r["x"].get<float>() + r["w"].get<float>() * 0.5f) + " " +
               std::to_string(r["y"].get<float>() + r["h"].get<float>() * 0.5f);
    };
    const nlohmann::json r = runEvents("preset-typed", 14,
                                       "1 click " + centre(low) + "\n4 click " + centre(name) + "\n6 key ctrl+a\n7 type my-ssao\n9 key Enter\n",
                                       "--presets " + presets.string());
    ASSERT_FALSE(r.is_null());
    EXPECT_TRUE(fs::exists(presets / "my-ssao.json")) << "Enter in the name field did not save";
    EXPECT_EQ(r["active_preset"].get<std::string>(), "my-ssao");
    EXPECT_EQ(r["errors"].size(), 0u) << r["errors"].dump();
    // The click on "Low" loaded it (the save after it named the active preset anew).
    std::ifstream saved(presets / "my-ssao.json");
    const nlohmann::json preset = nlohmann::json::parse(saved);
    EXPECT_EQ(preset["knobs"]["ssao.resolution"].get<std::string>(), "quarter") << preset.dump();
}

// Real key events from the X server (xdotool through XTEST), the way a
// person's keyboard reaches the window: Ctrl+O, a path typed over old text
// after Ctrl+A, Return; then a broken file; then Ctrl+Q. The window writes
// its report at exit.
TEST(GuiInput, RealKeyEventsFromXdotoolOpenATypedPathAndReportABrokenOne) {
    ASSERT_EQ(test::runCommand("command -v xdotool && command -v Xvfb").code, 0)
        << "xdotool or Xvfb is missing (scripts/setup-deps.sh --tests installs them)";
    const fs::path dir = test::tempDir() / "xdotool";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path report = dir / "report.json", broken = brokenGltf();
    const std::string script = R"(
set -u
dir=)" + dir.string() + R"(
Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3>"$dir/display" 2>/dev/null &
xvfb=$!
for i in $(seq 100); do [ -s "$dir/display" ] && break; sleep 0.1; done
export DISPLAY=:$(cat "$dir/display")
export XDG_CONFIG_HOME="$dir/config" XDG_DATA_HOME="$dir/data"
)" + std::string(DW_WORKBENCH_BINARY) + R"( --scene spheres --set ao.enabled=false --size 1024x640 --layout-out )" +
                               report.string() + R"( >"$dir/out.txt" 2>&1 &
app=$!
win=$(timeout 60 xdotool search --sync --onlyvisible --name 'Deferred Workbench' | head -1)
xdotool windowfocus --sync "$win"
sleep 2
xdotool key ctrl+o; sleep 0.5
xdotool type --delay 20 'a wrong start'
xdotool key ctrl+a
xdotool type --delay 20 ')" + validScene() + R"('
xdotool key Return; sleep 3
xdotool key ctrl+o; sleep 0.5
xdotool type --delay 20 ')" + broken.string() + R"('
xdotool key Return; sleep 2
# Ctrl+Q, again until the window has gone (a loaded machine may be mid-frame).
for i in $(seq 40); do kill -0 $app 2>/dev/null || break; xdotool key ctrl+q 2>/dev/null; sleep 1.5; done
kill $app 2>/dev/null && echo "the window did not close on Ctrl+Q" >&2
wait $app; code=$?
kill $xvfb; wait $xvfb 2>/dev/null
exit $code
)";
    const test::CommandResult r = test::runCommand("bash -c '" + [&] {
        std::string q;
        for (char c : script) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return q;
    }() + "'");
    std::ifstream log(dir / "out.txt");
    const std::string out((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
    ASSERT_EQ(r.code, 0) << r.out << r.err << out;
    ASSERT_TRUE(fs::exists(report)) << out;
    const nlohmann::json j = readJson(report);
    // The valid path opened (recent list), then the broken one failed and kept it.
    ASSERT_GE(j["recent_scenes"].size(), 1u) << j.dump();
    EXPECT_EQ(j["recent_scenes"][0].get<std::string>(), fs::absolute(validScene()).lexically_normal().string());
    EXPECT_EQ(j["scene"]["source"].get<std::string>(), validScene());
    const std::string banner = j["banner"].get<std::string>();
    EXPECT_NE(banner.find(broken.string()), std::string::npos) << banner;
    EXPECT_FALSE(j["axes"].get<bool>()) << "typed 'a's toggled the axes";
    // Without a GPU the window started at a reduced, automatic scale and said so.
    if (j["resolution"]["software_start"].get<std::string>().find("llvmpipe") != std::string::npos) {
        EXPECT_TRUE(j["resolution"]["auto"].get<bool>());
        EXPECT_LT(j["resolution"]["scale"].get<float>(), 0.5f);
    }
}

TEST(GuiInput, OneQuickClickOnAnOutputInThePassInspectorShowsIt) {
    const nlohmann::json where = runEvents("inspector-where", 2, "");
    ASSERT_FALSE(where.is_null());
    ASSERT_TRUE(where["items"].contains("inspector.gbuffer.normal")) << where["items"].dump();
    const auto& r = where["items"]["inspector.gbuffer.normal"];
    // Straight from elsewhere to the output and a press and release at once, as xdotool clicks.
    const nlohmann::json shown = runEvents("inspector-click", 8,
                                           "2 click " + std::to_string(r["x"].get<float>() + 20.0f) + " " +
                                               std::to_string(r["y"].get<float>() + r["h"].get<float>() * 0.5f) + "\n");
    ASSERT_FALSE(shown.is_null());
    EXPECT_EQ(shown["viewport"]["output"].get<std::string>(), "gbuffer.normal");
}

TEST(GuiInput, TheViewerSavesTheShownBufferAtItsOwnResolutionAsExrAndPng) {
    const fs::path exports = test::tempDir() / "viewer-exports";
    fs::remove_all(exports);
    const std::string extra = "--view gbuffer.normal --export-dir " + exports.string();
    const nlohmann::json where = runEvents("save-where", 2, "", extra);
    ASSERT_FALSE(where.is_null());
    auto centre = [](const nlohmann::json& r) {
        return std::to_string(r["x"].get<float>() + r["w"].get<float>() * 0.5f) + " " +
               std::to_string(r["y"].get<float>() + r["h"].get<float>() * 0.5f);
    };
    ASSERT_TRUE(where["items"].contains("viewport.save_exr")) << where["items"].dump();
    const nlohmann::json r = runEvents("save", 10,
                                       "2 click " + centre(where["items"]["viewport.save_exr"]) + "\n5 click " +
                                           centre(where["items"]["viewport.save_png"]) + "\n",
                                       extra);
    ASSERT_FALSE(r.is_null());
    EXPECT_EQ(r["errors"].size(), 0u) << r["errors"].dump();
    fs::path exr, png;
    for (const auto& e : fs::directory_iterator(exports)) {
        if (e.path().extension() == ".exr") exr = e.path();
        if (e.path().extension() == ".png") png = e.path();
    }
    ASSERT_FALSE(exr.empty()) << "save EXR wrote nothing";
    ASSERT_FALSE(png.empty()) << "save PNG wrote nothing";
    EXPECT_EQ(exr.filename().string().rfind("gbuffer_normal-frame", 0), 0u) << exr;
    const int w = r["render_size"][0].get<int>(), h = r["render_size"][1].get<int>();
    const FloatImage raw = loadImageFloat(exr.string()), shown = loadImageFloat(png.string());
    EXPECT_EQ(raw.width, w);
    EXPECT_EQ(raw.height, h);
    EXPECT_EQ(shown.width, w);
    EXPECT_EQ(shown.height, h);
    // The EXR holds the raw encoded normals (two signed channels), not the colours shown.
    EXPECT_EQ(raw.channels, 2) << "gbuffer.normal is two Kircher-Lawrance channels";
    double lo = 0.0;
    for (float v : raw.pixels) lo = std::min(lo, static_cast<double>(v));
    EXPECT_LT(lo, -0.01) << "signed values: raw, not a display mapping";
}

TEST(GuiInput, TheProbesCopyHoldsEveryValueItShowsAsLabelTabValueLines) {
    auto session = test::makeSession(64, 36);
    session->loadScene("default");
    ui::UiState state;
    state.report = session->render();
    state.probe.result = probePixel(session->pipeline(), 32, 20);
    state.probe.pinned = true;
    ui::ProbePanel panel;
    {
        test::HeadlessImGui imgui(ImVec2(800, 900));
        bool open = true;
        for (int i = 0; i < 2; ++i)
            imgui.frame([&] {
                ImGui::SetNextWindowSize(ImVec2(600, 880));
                panel.draw("Pixel probe", &open, state);
            });
    }
    const std::string& t = panel.copyText;
    EXPECT_EQ(t.rfind("pixel\t32 20\n", 0), 0u) << t;
    char lbuffer[128];
    const glm::vec3 L = state.probe.result.surface.radiance;
    std::snprintf(lbuffer, sizeof(lbuffer), "L-buffer\t%.5g %.5g %.5g", L.r, L.g, L.b);
    EXPECT_NE(t.find(lbuffer), std::string::npos) << t;
    EXPECT_NE(t.find("\ndepth\t"), std::string::npos) << t;
    // Every output's raw value at the pixel, by name.
    EXPECT_NE(t.find("\ngbuffer.normal\t"), std::string::npos) << t;
    EXPECT_NE(t.find("\nlbuffer\t"), std::string::npos) << t;
}

TEST(GuiInput, ThePresetsGivenAtStartUpAreTheActiveOnes) {
    // gui --preset: the Presets panel names it (it said "no preset loaded").
    const nlohmann::json one = runEvents("startup-preset", 2, "", "--preset AOV1");
    ASSERT_FALSE(one.is_null());
    EXPECT_EQ(one["active_preset"].get<std::string>(), "AOV1");
    // Several, in the order given.
    const nlohmann::json two = runEvents("startup-presets", 2, "", "--preset AOV1 --preset Low");
    ASSERT_FALSE(two.is_null());
    EXPECT_EQ(two["active_preset"].get<std::string>(), "AOV1 + Low");
    const nlohmann::json none = runEvents("startup-no-preset", 2, "");
    ASSERT_FALSE(none.is_null());
    EXPECT_EQ(none["active_preset"].get<std::string>(), "");
}

// A knob value of 20 000 characters (an events `set` line, or a record's
// knob) was echoed whole in its error, which took ImGui past its 65 536
// vertices a draw list: the window aborted. The message is cut on screen and
// the window keeps the start-up scene.
TEST(GuiInput, AnEnormousKnobValueIsAShortMessageNotACrash) {
    ASSERT_EQ(test::runCommand("command -v xvfb-run").code, 0) << "xvfb-run is missing (scripts/setup-deps.sh installs it)";
    const nlohmann::json r = runEvents("long-knob", 6, "1 set ssao.samples=" + std::string(20000, '1') + "\n");
    ASSERT_FALSE(r.is_null());
    ASSERT_EQ(r["errors"].size(), 1u) << r["errors"].dump().substr(0, 300);
    const std::string e = r["errors"][0].get<std::string>();
    EXPECT_LE(e.size(), ui::MessageLog::kMaxMessageBytes + 40) << e.substr(0, 300);
    EXPECT_NE(e.find("more bytes)"), std::string::npos) << e.substr(0, 300);
    EXPECT_EQ(r["scene"]["name"], "spheres");
}

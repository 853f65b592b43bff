// Faults found by trying the window as researchers do (issue 32), each
// driven with real input under Xvfb: the scripted mode's events (the same
// input queue as the window's own) or xdotool's X events.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/support/TestSupport.h"

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

// The window under Xvfb for `frames` frames replaying `events`, with a
// reference cache of its own; its --layout-out report (null when it failed).
nlohmann::json runWindow(const std::string& name, const std::string& args, int frames, const std::string& events) {
    const fs::path ev = writeFile(name + "-events.txt", events), out = test::tempDir() / (name + "-layout.json");
    const test::CommandResult r = test::runCommand(
        "DW_REFERENCE_CACHE=" + (test::tempDir() / (name + "-cache")).string() + " xvfb-run -a -s '-screen 0 1700x1000x24' " +
        std::string(DW_WORKBENCH_BINARY) + " " + args + " --frames " + std::to_string(frames) + " --events " + ev.string() +
        " --layout-out " + out.string());
    EXPECT_EQ(r.code, 0) << r.out << r.err;
    return r.code == 0 ? readJson(out) : nlohmann::json();
}

}  // namespace

// ../shared/cases/inputs/ab_split_after_reference.events: F9 traces the
// reference with the split off, then `b` turns the split on. The split's
// numbers once took their rows from the render, so the frame shrank by a few
// rows, the reference just traced was withdrawn and the frame that asked for
// it failed ("buffer 'reference.final' has not been allocated"). Now the
// render size stays, the reference survives and B shows it; a window resized
// after the trace withdraws it without failing a frame.
TEST(WindowJourney, TheAbSplitAfterAReferenceKeepsTheRenderSizeAndTheReference) {
    ASSERT_EQ(test::runCommand("command -v xvfb-run").code, 0) << "xvfb-run is missing (scripts/setup-deps.sh installs it)";
    const std::string args = "--scene spheres --size 1600x900 --resolution 1/4 --ab reference";
    const nlohmann::json off = runWindow("ab-off", args, 4, "2 key b\n");
    ASSERT_FALSE(off.is_null());
    EXPECT_FALSE(off["ab"]["enabled"].get<bool>());

    const nlohmann::json on = runWindow("ab-after-reference", args, 80, "2 move 700 300\n3 key b\n6 key F9\n60 key b\n");
    ASSERT_FALSE(on.is_null());
    EXPECT_EQ(on["errors"], nlohmann::json::array()) << on["errors"].dump();
    EXPECT_TRUE(on["ab"]["enabled"].get<bool>());
    EXPECT_EQ(on["render_size"], off["render_size"]) << "turning the split on changed the render size";
    EXPECT_TRUE(on["reference"]["shown"].get<bool>()) << on["reference"].dump();
    EXPECT_TRUE(on["ab"]["ready"].get<bool>()) << on["ab"].dump();
    EXPECT_EQ(on["ab"]["unavailable"].get<std::string>(), "");
    EXPECT_EQ(on["ab"]["size"], on["render_size"]);
    // B is the reference, not A again: the two differ by the approximations.
    EXPECT_GT(on["ab"]["rms"].get<double>(), 1e-4);

    const nlohmann::json resized = runWindow("ab-reference-resize", args, 60, "3 key F9\n45 resize 1400 820\n");
    ASSERT_FALSE(resized.is_null());
    EXPECT_EQ(resized["errors"], nlohmann::json::array()) << resized["errors"].dump();
    EXPECT_NE(resized["render_size"], off["render_size"]) << "the resize did not reach the render";
    EXPECT_FALSE(resized["reference"]["shown"].get<bool>());
    EXPECT_NE(resized["ab"]["unavailable"].get<std::string>().find("F9"), std::string::npos) << resized["ab"].dump();
}

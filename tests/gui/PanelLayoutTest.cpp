// The workbench layout's arithmetic (PanelLayout) and the scripted input's
// parser, without a window.
#include <gtest/gtest.h>

#include <set>

#include "app/ScriptedInput.h"
#include "headless/CommandLine.h"
#include "ui/PanelLayout.h"

using namespace dw;
using namespace dw::ui;

namespace {

bool overlaps(const PanelRect& a, const PanelRect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

// Every panel inside the window below the menu bar, none overlapping, all open ones placed.
void expectTiles(const PanelLayout::Arrangement& a, float w, float h, float top, const std::set<std::string>& open) {
    std::set<std::string> placed;
    for (const auto& p : a.panels) {
        placed.insert(p.panel);
        EXPECT_GE(p.rect.x, 0.0f) << p.panel;
        EXPECT_GE(p.rect.y, top) << p.panel;
        EXPECT_LE(p.rect.x + p.rect.w, w) << p.panel << " at " << w << "x" << h;
        EXPECT_LE(p.rect.y + p.rect.h, h) << p.panel << " at " << w << "x" << h;
        EXPECT_GT(p.rect.w, 0.0f) << p.panel;
        EXPECT_GT(p.rect.h, 0.0f) << p.panel;
    }
    EXPECT_EQ(placed, open);
    for (size_t i = 0; i < a.panels.size(); ++i)
        for (size_t j = i + 1; j < a.panels.size(); ++j)
            EXPECT_FALSE(overlaps(a.panels[i].rect, a.panels[j].rect)) << a.panels[i].panel << " / " << a.panels[j].panel;
}

}  // namespace

TEST(PanelLayout, TilesTheWindowAtEverySizeWithAnyPanelsOpen) {
    PanelLayout layout;
    const std::vector<std::string> all = layout.panels();
    // Every subset of a few panels closed, at sizes from tiny to large.
    const std::vector<std::set<std::string>> closed = {
        {}, {"Presets", "Messages", "Keys", "Side view"}, {"Scene", "Lights", "Presets"}, {"Viewport"},
        {"Pass inspector", "Parameters", "Messages", "Keys"}, {"GPU timings", "Pixel probe"}};
    for (const auto& c : closed)
        for (auto [w, h] : {std::pair{1024.f, 640.f}, {1100.f, 650.f}, {1600.f, 900.f}, {3840.f, 2160.f}, {300.f, 200.f}}) {
            std::set<std::string> open;
            for (const auto& p : all)
                if (!c.count(p)) open.insert(p);
            const auto a = layout.arrange(w, h, 19.0f, [&](const std::string& n) { return open.count(n) > 0; });
            expectTiles(a, w, h, 19.0f, open);
        }
}

TEST(PanelLayout, ScalesWithTheWindowAndComesBackAfterAResize) {
    PanelLayout layout;
    auto open = [](const std::string& n) { return n != "Keys" && n != "Side view"; };
    const auto big = layout.arrange(1600, 900, 19, open);
    const auto small = layout.arrange(1024, 640, 19, open);
    const auto again = layout.arrange(1600, 900, 19, open);
    ASSERT_EQ(big.panels.size(), again.panels.size());
    for (size_t i = 0; i < big.panels.size(); ++i) {
        EXPECT_EQ(big.panels[i].rect.w, again.panels[i].rect.w) << big.panels[i].panel;
        EXPECT_EQ(big.panels[i].rect.h, again.panels[i].rect.h) << big.panels[i].panel;
    }
    // The viewport follows the window (it is the same share of both).
    const PanelRect* vb = big.find("Viewport");
    const PanelRect* vs = small.find("Viewport");
    ASSERT_TRUE(vb && vs);
    EXPECT_NEAR(vb->w / 1600.0f, vs->w / 1024.0f, 0.04f);
    EXPECT_GE(vs->w, PanelLayout::kMinWidth);
    // At 1024x640 every open panel keeps a usable size.
    for (const auto& p : small.panels) {
        EXPECT_GE(p.rect.w, PanelLayout::kMinWidth) << p.panel;
        EXPECT_GE(p.rect.h, PanelLayout::kMinHeight) << p.panel;
    }
}

TEST(PanelLayout, DraggingASplitterMovesRoomBetweenNeighboursAndStopsAtTheMinimum) {
    PanelLayout layout;
    auto open = [](const std::string& n) { return n != "Keys"; };
    auto a = layout.arrange(1600, 900, 19, open);
    // The bar between the left column and the middle one.
    const PanelLayout::Splitter* bar = nullptr;
    for (const auto& s : a.splitters)
        if (s.vertical && s.row < 0 && s.column == 0) bar = &s;
    ASSERT_NE(bar, nullptr);
    const float sceneW = a.find("Scene")->w, viewW = a.find("Viewport")->w + a.find("Side view")->w + PanelLayout::kGap;
    layout.drag(*bar, 80.0f);
    auto b = layout.arrange(1600, 900, 19, open);
    EXPECT_NEAR(b.find("Scene")->w, sceneW + 80.0f, 1.0f);
    EXPECT_NEAR(b.find("Viewport")->w + b.find("Side view")->w + PanelLayout::kGap, viewW - 80.0f, 2.0f);
    EXPECT_EQ(b.find("Pass inspector")->w, a.find("Pass inspector")->w);
    expectTiles(b, 1600, 900, 19, [&] {
        std::set<std::string> s;
        for (const auto& p : layout.panels())
            if (open(p)) s.insert(p);
        return s;
    }());
    // Far past the end: the neighbour keeps its minimum.
    for (const auto& s : b.splitters)
        if (s.vertical && s.row < 0 && s.column == 0) layout.drag(s, 5000.0f);
    auto c = layout.arrange(1600, 900, 19, open);
    EXPECT_GE(c.find("Viewport")->w, PanelLayout::kMinWidth - 1.0f);
    // Saved and read back, the same arrangement.
    PanelLayout restored;
    restored.fromJson(layout.toJson());
    auto d = restored.arrange(1600, 900, 19, open);
    for (size_t i = 0; i < c.panels.size(); ++i) EXPECT_EQ(c.panels[i].rect.w, d.panels[i].rect.w) << c.panels[i].panel;
}

// A layout saved by an older version (before the Pareto panel joined the
// timings and the probe) loads what it has: its weights where this version
// has the same place, the new panel at its default width, nothing said.
TEST(PanelLayout, AnOlderLayoutLoadsWhatItHasAndDefaultsTheRest) {
    PanelLayout layout;
    nlohmann::json j = layout.toJson();
    j["columns"][0]["width"] = 0.3;
    j["columns"][1]["rows"][1] =
        nlohmann::json::parse(R"({"panels": ["GPU timings", "Pixel probe"], "widths": [0.4, 0.6], "height": 0.5})");
    EXPECT_TRUE(layout.fromJson(j).empty());
    const nlohmann::json got = layout.toJson();
    EXPECT_FLOAT_EQ(got["columns"][0]["width"].get<float>(), 0.3f);
    const nlohmann::json& row = got["columns"][1]["rows"][1];
    EXPECT_EQ(row["panels"], nlohmann::json({"GPU timings", "Pixel probe", "Pareto"}));
    EXPECT_EQ(row["widths"], nlohmann::json({0.4f, 0.6f, 0.5f}));
    EXPECT_FLOAT_EQ(row["height"].get<float>(), 0.5f);
    // Arranged, the saved proportions of the two old panels hold.
    auto open = [](const std::string&) { return true; };
    const auto a = layout.arrange(1600, 900, 19, open);
    EXPECT_NEAR(a.find("Pixel probe")->w / a.find("GPU timings")->w, 1.5f, 0.02f);
    // Only weights (no "panels"): taken in this version's order when the count matches.
    PanelLayout bare;
    const nlohmann::json w = nlohmann::json::parse(R"({"columns": [{"width": 0.25}, {"rows": [{"widths": [0.5, 0.5]}]}]})");
    EXPECT_TRUE(bare.fromJson(w).empty());
    EXPECT_FLOAT_EQ(bare.toJson()["columns"][0]["width"].get<float>(), 0.25f);
    EXPECT_EQ(bare.toJson()["columns"][1]["rows"][0]["widths"], nlohmann::json({0.5f, 0.5f}));
    EXPECT_EQ(bare.toJson()["columns"][2], PanelLayout().toJson()["columns"][2]);
}

// What cannot be placed is dropped and named, the rest is still taken; only a
// file that is no layout at all is refused, and then nothing changes.
TEST(PanelLayout, WhatALayoutCannotPlaceIsDroppedAndNamed) {
    PanelLayout layout;
    nlohmann::json j = layout.toJson();
    j["columns"][0]["width"] = -1;
    j["columns"][1]["rows"][0]["panels"] = nlohmann::json::parse(R"(["Viewport", "Something else"])");
    j["columns"][1]["rows"][0]["widths"] = nlohmann::json::parse("[0.9, 0.1]");
    j["columns"][2]["width"] = 0.4;
    j["columns"].push_back(nlohmann::json::parse(R"({"width": 1})"));
    const std::vector<std::string> dropped = layout.fromJson(j);
    EXPECT_EQ(dropped, (std::vector<std::string>{"columns past the 3 this version has",
                                                 "columns[0].width is not a positive weight",
                                                 "columns[1].rows[0]: the panel 'Something else' this version does not place there"}));
    const nlohmann::json got = layout.toJson();
    const nlohmann::json def = PanelLayout().toJson();
    EXPECT_EQ(got["columns"][0]["width"], def["columns"][0]["width"]);
    EXPECT_EQ(got["columns"][1]["rows"][0]["widths"], nlohmann::json({0.9f, 0.4f}));
    EXPECT_FLOAT_EQ(got["columns"][2]["width"].get<float>(), 0.4f);
    PanelLayout untouched;
    EXPECT_THROW(untouched.fromJson(nlohmann::json::array()), std::runtime_error);
    EXPECT_THROW(untouched.fromJson(nlohmann::json{{"columns", 3}}), std::runtime_error);
    EXPECT_EQ(untouched.toJson(), PanelLayout().toJson());
}

TEST(ScriptedInput, ParsesActionsIntoFramesAndNamesTheLineOfABadOne) {
    const ScriptedInput s = ScriptedInput::parse(
        "# a drag then a click\n2 drag 100 100 200 150 2\n9 click 50 60\n12 key F12\n13 resize 1024 640\n", "events.txt");
    EXPECT_FLOAT_EQ(*s.at(2).mouseX, 100.0f);
    EXPECT_FALSE(s.at(2).leftDown.has_value());
    EXPECT_TRUE(*s.at(3).leftDown);
    EXPECT_FLOAT_EQ(*s.at(4).mouseX, 150.0f);
    EXPECT_FLOAT_EQ(*s.at(5).mouseY, 150.0f);
    EXPECT_FALSE(*s.at(6).leftDown);
    EXPECT_FLOAT_EQ(*s.at(9).mouseX, 50.0f);
    EXPECT_FALSE(s.at(9).leftDown.has_value()) << "a click is over its point a frame before the press";
    EXPECT_TRUE(*s.at(10).leftDown);
    EXPECT_FALSE(*s.at(11).leftDown);
    ASSERT_EQ(s.at(12).keys.size(), 1u);
    EXPECT_EQ(s.at(13).resize->first, 1024);
    EXPECT_EQ(s.lastFrame(), 13);
    try {
        ScriptedInput::parse("1 move 3 4\n2 jump 1\n", "events.txt");
        FAIL() << "an unknown action was accepted";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("events.txt: line 2: unknown action 'jump'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(ScriptedInput::parse("1 key Hyper\n", "e"), UsageError);
    EXPECT_THROW(ScriptedInput::parse("1 resize 10 10\n", "e"), UsageError);
    // A line a person could type, not megabytes of queued keys.
    EXPECT_EQ(ScriptedInput::parse("1 type " + std::string(kMaxTypedBytes, 'x') + "\n", "e").at(1).text.size(),
              kMaxTypedBytes);
    try {
        ScriptedInput::parse("1 type " + std::string(10 << 20, 'x') + "\n", "e");
        FAIL() << "a 10 MB type line was accepted";
    } catch (const UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("type takes at most 4096 bytes on a line, got 10485760"), std::string::npos)
            << std::string(e.what()).substr(0, 200);
    }
}

// The timing report's numbers from a synthetic timer history (no GL): which
// frames count, the statistics per pass, span and total, and the three forms.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "renderer/graph/TimingReport.h"

using namespace dw;

namespace {

// Frames 0..5: 0 and 1 are warm-up (slow, as the first frame's shader compile
// makes them), 2..4 are counted, 5 comes after the report's last frame.
PassTimer syntheticTimer() {
    PassTimer t;
    const float geometry[] = {100.0f, 90.0f, 3.0f, 1.0f, 2.0f, 50.0f};
    const float lighting[] = {200.0f, 150.0f, 10.0f, 14.0f, 12.0f, 70.0f};
    const float shadows[] = {80.0f, 60.0f, 4.0f, 5.0f, 6.0f, 30.0f};
    for (std::uint64_t f = 0; f < 6; ++f) {
        t.addSample("geometry", {f, geometry[f], geometry[f] * 0.5f});
        t.addSample("lighting", {f, lighting[f], 1.0f});
        t.addSample("lighting/shadow maps", {f, shadows[f], 0.25f});
        t.addSample(PassTimer::kFrameSeries, {f, geometry[f] + lighting[f], geometry[f] + lighting[f] + 1.0f});
    }
    // Ran in a warm-up frame only: no samples in the counted frames.
    t.addSample("ssao", {0, 7.0f, 7.0f});
    return t;
}

FrameReport lastFrame() {
    FrameReport r;
    r.frameIndex = 4;
    r.passes = {{"geometry", true, "", "3 draws"},
                {"ssao", false, "switched off (ssao.enabled = false)", ""},
                {"lighting", true, "", "2 lights"}};
    return r;
}

}  // namespace

TEST(TimingReport, StatisticsOverTheCountedFramesOnly) {
    PassTimer timer = syntheticTimer();
    const TimingReport r = TimingReport::build(timer, lastFrame(), 2, 2);
    EXPECT_EQ(r.countedFrames(), 3);
    EXPECT_EQ(r.warmupFrames(), 2);

    ASSERT_EQ(r.rows().size(), 5u);
    EXPECT_EQ(r.rows()[0].series, "geometry");
    EXPECT_EQ(r.rows()[1].series, "ssao");
    EXPECT_EQ(r.rows()[2].series, "lighting");
    EXPECT_EQ(r.rows()[3].series, "lighting/shadow maps");
    EXPECT_EQ(r.rows()[3].kind, TimingRow::Kind::Span);
    EXPECT_EQ(r.rows()[3].pass, "lighting");
    EXPECT_EQ(r.rows()[4].kind, TimingRow::Kind::Total);

    const TimingRow* g = r.find("geometry");
    ASSERT_NE(g, nullptr);
    EXPECT_EQ(g->gpu.count, 3);
    EXPECT_FLOAT_EQ(g->gpu.median, 2.0f);  // of 3, 1, 2: frames 0, 1 and 5 left out
    EXPECT_FLOAT_EQ(g->gpu.min, 1.0f);
    EXPECT_FLOAT_EQ(g->gpu.max, 3.0f);
    EXPECT_FLOAT_EQ(g->gpu.mean, 2.0f);
    EXPECT_FLOAT_EQ(g->cpu.median, 1.0f);
    EXPECT_FLOAT_EQ(g->cpu.max, 1.5f);
    EXPECT_EQ(g->stats, "3 draws");

    const TimingRow* s = r.find("lighting/shadow maps");
    EXPECT_FLOAT_EQ(s->gpu.median, 5.0f);
    EXPECT_FLOAT_EQ(s->gpu.min, 4.0f);
    EXPECT_FLOAT_EQ(s->gpu.max, 6.0f);
    EXPECT_FLOAT_EQ(s->cpu.median, 0.25f);

    const TimingRow* skipped = r.find("ssao");
    EXPECT_FALSE(skipped->ran);
    EXPECT_EQ(skipped->gpu.count, 0);

    EXPECT_FLOAT_EQ(r.total().gpu.median, 14.0f);  // 13, 15, 14
    EXPECT_FLOAT_EQ(r.total().gpu.min, 13.0f);
    EXPECT_FLOAT_EQ(r.total().gpu.max, 15.0f);
    EXPECT_FLOAT_EQ(r.total().cpu.median, 15.0f);

    // Without warm-up every frame up to the last counts; an even count takes
    // the mean of the middle two.
    const TimingReport all = TimingReport::build(timer, lastFrame(), 0, 0);
    EXPECT_EQ(all.countedFrames(), 5);
    EXPECT_FLOAT_EQ(all.find("geometry")->gpu.median, 3.0f);  // 1 2 3 90 100
    FrameReport upTo3 = lastFrame();
    upTo3.frameIndex = 3;
    const TimingReport even = TimingReport::build(timer, upTo3, 0, 0);
    EXPECT_FLOAT_EQ(even.find("lighting")->gpu.median, 82.0f);  // 10 14 150 200: (14 + 150) / 2
}

TEST(TimingReport, TableJsonAndCsvCarryTheSameNumbers) {
    PassTimer timer = syntheticTimer();
    const TimingReport r = TimingReport::build(timer, lastFrame(), 2, 2);

    const std::string table = r.table();
    EXPECT_EQ(table.rfind("timings over 3 frame(s) after 2 warm-up frame(s)\n", 0), 0u) << table;
    EXPECT_NE(table.find("\ngeometry                  2.000          1.000          3.000          1.000  3\n"),
              std::string::npos) << table;
    EXPECT_NE(table.find("\n  (3 draws)\n"), std::string::npos) << table;
    EXPECT_NE(table.find("\nssao                          -  (skipped: switched off (ssao.enabled = false))\n"),
              std::string::npos) << table;
    // The span under its pass, before the pass's own line.
    const size_t span = table.find("\n  shadow maps             5.000");
    ASSERT_NE(span, std::string::npos) << table;
    EXPECT_LT(table.find("\nlighting "), span);
    EXPECT_LT(span, table.find("\n  (2 lights)"));
    EXPECT_NE(table.find("\nframe (total)            14.000         13.000         15.000         15.000  3\n"),
              std::string::npos) << table;

    const auto j = nlohmann::json::parse(r.json());
    EXPECT_EQ(j["frames"], 3);
    EXPECT_EQ(j["warmup"], 2);
    ASSERT_EQ(j["passes"].size(), 3u);
    EXPECT_EQ(j["passes"][0]["name"], "geometry");
    EXPECT_EQ(j["passes"][0]["frames"], 3);
    EXPECT_DOUBLE_EQ(j["passes"][0]["gpu_ms"]["median"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(j["passes"][0]["cpu_ms"]["max"].get<double>(), 1.5);
    EXPECT_EQ(j["passes"][1]["ran"], false);
    EXPECT_EQ(j["passes"][1]["reason"], "switched off (ssao.enabled = false)");
    EXPECT_EQ(j["passes"][2]["spans"][0]["name"], "shadow maps");
    EXPECT_DOUBLE_EQ(j["passes"][2]["spans"][0]["gpu_ms"]["max"].get<double>(), 6.0);
    EXPECT_DOUBLE_EQ(j["total"]["gpu_ms"]["median"].get<double>(), 14.0);

    const std::vector<std::string> rows = r.csvRows();
    ASSERT_EQ(rows.size(), r.rows().size());
    auto columns = [](const std::string& line) { return std::count(line.begin(), line.end(), ',') + 1; };
    for (const auto& line : rows) EXPECT_EQ(columns(line), columns(TimingReport::csvHeader())) << line;
    EXPECT_EQ(rows[0], "geometry,pass,1,3,2.0000,1.0000,3.0000,2.0000,1.0000,0.5000,1.5000,1.0000");
    EXPECT_EQ(rows[1].rfind("ssao,pass,0,0,", 0), 0u) << rows[1];
    EXPECT_EQ(rows[3].rfind("lighting/shadow maps,span,1,3,5.0000,", 0), 0u) << rows[3];
    EXPECT_EQ(rows[4].rfind("frame,total,1,3,14.0000,13.0000,15.0000,", 0), 0u) << rows[4];
    EXPECT_EQ(r.csv(), TimingReport::csvHeader() + "\n" + rows[0] + "\n" + rows[1] + "\n" + rows[2] + "\n" + rows[3] + "\n" +
                           rows[4] + "\n");
}

TEST(TimingReport, HistoryLengthKeepsEnoughFrames) {
    PassTimer t;
    t.setHistoryLength(3);
    for (std::uint64_t f = 0; f < 5; ++f) t.addSample("geometry", {f, static_cast<float>(f), 0.0f});
    ASSERT_EQ(t.find("geometry")->samples.size(), 3u);
    EXPECT_EQ(t.find("geometry")->samples.front().frame, 2u);
    t.setHistoryLength(2);
    EXPECT_EQ(t.find("geometry")->samples.size(), 2u);
    // Paused: nothing recorded.
    t.setPaused(true);
    t.addSample("geometry", {9, 1.0f, 1.0f});
    EXPECT_EQ(t.find("geometry")->samples.back().frame, 4u);
}

TEST(TimingReport, CountersAreTheLastFramesAndADifferingFrameIsNamed) {
    PassTimer timer = syntheticTimer();
    EXPECT_FALSE(TimingReport::build(timer, lastFrame(), 2, 2).counted());
    EXPECT_EQ(TimingReport::build(timer, lastFrame(), 2, 2).countersTable(), "");
    PassTimer counted;
    for (std::uint64_t f = 0; f < 5; ++f) {
        PassCounts g, l, total;
        g.v = {100, 90, 2, 6, 0, 4096};
        l.v = {f == 3 ? 51 : 50, 40, 1, 3, 0, 1024};  // frame 3 shades one fragment more
        total = g;
        total.add(l);
        counted.addSample("geometry", {f, 1.0f, 1.0f, g});
        counted.addSample("lighting", {f, 1.0f, 1.0f, l});
        counted.addSample(PassTimer::kFrameSeries, {f, 2.0f, 2.0f, total});
    }
    const TimingReport r = TimingReport::build(counted, lastFrame(), 2, 2);
    ASSERT_TRUE(r.counted());
    EXPECT_EQ(r.find("lighting")->counts[PassCounts::Fragments], 50);  // the last frame's (4)
    EXPECT_TRUE(r.find("lighting")->countsDiffer);
    EXPECT_EQ(r.find("lighting")->differingFrame, 3u);
    EXPECT_FALSE(r.find("geometry")->countsDiffer);
    EXPECT_EQ(r.total().counts[PassCounts::Bytes], 5120);
    const std::string table = r.table();
    EXPECT_NE(table.find("cost counters per frame (exact; they differ between frames: frame 3's lighting differ from "
                         "the last frame's, shown)"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("\ngeometry                    100             90              2              6              0"
                         "           4096\n"),
              std::string::npos)
        << table;
    const auto j = nlohmann::json::parse(r.json());
    EXPECT_EQ(j["passes"][0]["counters"]["fragments"], 100);
    EXPECT_EQ(j["total"]["counters"]["samples"], 130);
    EXPECT_EQ(j["counters_same_every_frame"], false);
}

// The parts of `bench` that need no GL: the grid and its shards, the samples
// CSV and merging, the bootstrap interval, the baseline and the tables.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <set>

#include "renderer/Error.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/BenchMerge.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/record/ExperimentRecord.h"

using namespace dw;

namespace {

BenchGrid smallGrid() {
    BenchGrid g;
    g.sizes = {{64, 36}, {96, 54}};
    g.lights = {1, 10};
    g.knobAxes = {BenchGrid::parseSweep("lighting.strategy=stencil_volumes,fullscreen")};
    return g;
}

// Synthetic results: every configuration's frame takes `scale(config)` ms
// times noise, with two passes under it.
BenchResults synthetic(const BenchGrid& grid, int frames, double (*scale)(const BenchConfig&)) {
    BenchResults r;
    for (const auto& a : grid.knobAxes) r.knobAxes.push_back(a.knob);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(1.0, 0.03);
    long long seq = 0;
    for (const auto& c : grid.configs()) {
        r.configs.push_back({c, 0.5 * c.lights, 1.5});
        for (int k = 0; k < frames; ++k) {
            const double ms = scale(c) * noise(rng);
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "geometry", ms * 0.25, 0.1});
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "lighting", ms * 0.7, 0.2});
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "frame", ms, 0.4});
            ++seq;
        }
    }
    return r;
}

}  // namespace

TEST(BenchGrid, OrdersSizeThenLightsThenKnobsAndShardsByIndex) {
    const BenchGrid g = smallGrid();
    const auto configs = g.configs();
    ASSERT_EQ(configs.size(), 8u);
    EXPECT_EQ(g.count(), 8u);
    EXPECT_EQ(configs[0].size(), "64x36");
    EXPECT_EQ(configs[0].lights, 1);
    EXPECT_EQ(configs[0].knobValues[0], "stencil_volumes");
    EXPECT_EQ(configs[1].knobValues[0], "fullscreen");
    EXPECT_EQ(configs[2].lights, 10);
    EXPECT_EQ(configs[4].size(), "96x54");
    for (size_t i = 0; i < configs.size(); ++i) EXPECT_EQ(configs[i].index, static_cast<int>(i));

    // Comparison groups: the strategies at one size and light count go together.
    EXPECT_EQ(g.groupsAlong(configs, "lighting.strategy"), (std::vector<int>{0, 0, 1, 1, 2, 2, 3, 3}));
    EXPECT_EQ(g.groupsAlong(configs, "lights"), (std::vector<int>{0, 1, 0, 1, 2, 3, 2, 3}));
    EXPECT_EQ(g.groupsAlong(configs, "size"), (std::vector<int>{0, 1, 2, 3, 0, 1, 2, 3}));
    EXPECT_EQ(g.groupsAlong(configs, ""), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));

    const BenchShard s = BenchShard::parse("1/3");
    EXPECT_TRUE(s.takes(1));
    EXPECT_TRUE(s.takes(4));
    EXPECT_FALSE(s.takes(3));
    for (const char* bad : {"3/3", "1", "-1/2", "a/b", "1/0", "0/"}) EXPECT_THROW(BenchShard::parse(bad), Error) << bad;
    EXPECT_THROW(BenchGrid::parseSweep("lighting.strategy"), Error);
    EXPECT_THROW(BenchGrid::parseSweep("k=a,,b"), Error);
    EXPECT_THROW(BenchGrid::parseSweep("k=a,a"), Error);
    // No light counts: one column with the scene's own count.
    BenchGrid plain;
    plain.sizes = {{8, 8}};
    EXPECT_EQ(plain.configs(17).at(0).lights, 17);
}

// An axis made without text (the Python module's sweep dicts) is held to what --sweep's text is.
TEST(BenchGrid, CheckAxisHoldsAnAxisToWhatTheSweepTextChecks) {
    EXPECT_NO_THROW(BenchGrid::checkAxis({"ssao.radius", {"0.25", "0.5"}}));
    EXPECT_THROW(BenchGrid::checkAxis({"", {"1"}}), Error);
    EXPECT_THROW(BenchGrid::checkAxis({"ssao.radius", {}}), Error);
    EXPECT_THROW(BenchGrid::checkAxis({"ssao.radius", {"0.5", ""}}), Error);
    try {
        BenchGrid::checkAxis({"ssao.samples", {"8", "16", "8"}});
        FAIL() << "a value given twice";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "--sweep ssao.samples: '8' is given twice");
    }
}

TEST(Bootstrap, IdenticalDistributionsContainOneTwiceAsSlowGivesTwo) {
    std::mt19937 rng(11);
    std::lognormal_distribution<double> ms(std::log(5.0), 0.05);
    std::vector<double> a(40), b(40), slow(40);
    for (auto& v : a) v = ms(rng);
    for (auto& v : b) v = ms(rng);
    for (auto& v : slow) v = 2.0 * ms(rng);
    const RatioInterval same = bootstrapRatioOfMedians(a, b, 2000, 1);
    ASSERT_TRUE(same.valid());
    EXPECT_LE(same.low, 1.0);
    EXPECT_GE(same.high, 1.0);
    EXPECT_LT(same.high - same.low, 0.2);
    const RatioInterval twice = bootstrapRatioOfMedians(slow, b, 2000, 1);
    EXPECT_NEAR(twice.ratio, 2.0, 0.1);
    EXPECT_LE(twice.low, twice.ratio);
    EXPECT_GE(twice.high, twice.ratio);
    EXPECT_GT(twice.low, 1.8);
    EXPECT_LT(twice.high, 2.2);
    // Seeded: the same call gives the same interval.
    const RatioInterval again = bootstrapRatioOfMedians(slow, b, 2000, 1);
    EXPECT_EQ(again.low, twice.low);
    EXPECT_EQ(again.high, twice.high);
    EXPECT_FALSE(bootstrapRatioOfMedians({}, b).valid());
    EXPECT_FALSE(bootstrapRatioOfMedians(a, {0.0, 0.0}).valid());
    EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0, 10.0}), 2.5);
}

TEST(BenchResults, CsvRoundTripsAndShardsMergeIntoTheGrid) {
    const BenchGrid g = smallGrid();
    const BenchResults all = synthetic(g, 3, [](const BenchConfig& c) { return 1.0 + c.lights; });
    const std::string csv = all.csv();
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "config,size,lights,lighting.strategy,lpp,lpp_lit,sample,seq,frame,pass,gpu_ms,cpu_ms,gpu_mem_peak_mib");
    const BenchResults back = BenchResults::parseCsv(csv, "all.csv");
    ASSERT_EQ(back.configs.size(), 8u);
    ASSERT_EQ(back.samples.size(), all.samples.size());
    EXPECT_EQ(back.csv(), csv);
    EXPECT_DOUBLE_EQ(back.configs[2].lpp, 5.0);

    // Shards 0/2 and 1/2 of the same grid merge back to it.
    BenchResults parts[2];
    for (int i = 0; i < 2; ++i) {
        parts[i].knobAxes = all.knobAxes;
        for (const auto& c : all.configs)
            if (c.config.index % 2 == i) parts[i].configs.push_back(c);
        for (const auto& s : all.samples)
            if (s.config % 2 == i) parts[i].samples.push_back(s);
    }
    const BenchResults merged = BenchResults::merge(
        {BenchResults::parseCsv(parts[1].csv(), "b.csv"), BenchResults::parseCsv(parts[0].csv(), "a.csv")}, {"b.csv", "a.csv"});
    EXPECT_EQ(merged.csv(), csv);
    // The same shard twice is a clash, and so are other knob columns.
    EXPECT_THROW(BenchResults::merge({parts[0], parts[0]}, {"a.csv", "a2.csv"}), Error);
    BenchResults other = parts[1];
    other.knobAxes = {"ssao.samples"};
    EXPECT_THROW(BenchResults::merge({parts[0], other}, {}), Error);

    EXPECT_THROW(BenchResults::parseCsv("a,b\n", "x.csv"), FileError);
    const std::string broken = csv.substr(0, csv.find('\n') + 1) + "0,64x36,1,volumes,,,zero,0,0,frame,1,1,\n";
    try {
        BenchResults::parseCsv(broken, "x.csv");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("x.csv: line 2: sample"), std::string::npos) << e.what();
    }
}

// --ratio-of: the ratio compares one pass's medians, not the frame's. Here
// fullscreen's lighting pass takes 3x stencil_volumes' while the frames are
// alike; a configuration without samples of that pass gets no ratio.
TEST(BenchSummary, RatioOfAPassComparesThatPass) {
    BenchGrid g;
    g.sizes = {{64, 36}};
    g.lights = {10};
    g.knobAxes = {BenchGrid::parseSweep("lighting.strategy=stencil_volumes,fullscreen,tiled")};
    BenchResults r;
    r.knobAxes = {"lighting.strategy"};
    std::mt19937 rng(5);
    std::normal_distribution<double> noise(1.0, 0.02);
    long long seq = 0;
    for (const auto& c : g.configs()) {
        r.configs.push_back({c, 1.0, 1.0});
        const std::string strategy = c.knobValues[0];
        for (int k = 0; k < 30; ++k, ++seq) {
            const double lighting = (strategy == "fullscreen" ? 3.0 : 1.0) * noise(rng);
            if (strategy != "tiled")
                r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "lighting", lighting, 0.1});
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "frame", 10.0 * noise(rng), 0.2});
        }
    }
    BenchBaseline b = chooseBaseline(r, "");
    EXPECT_EQ(b.series, "frame");
    EXPECT_NEAR(summarize(r, b, 500).find(1)->ratio.ratio, 1.0, 0.05);
    b.series = "lighting";
    const BenchSummary s = summarize(r, b, 500);
    ASSERT_TRUE(s.find(1)->ratio.valid());
    EXPECT_NEAR(s.find(1)->ratio.ratio, 3.0, 0.15);
    EXPECT_LT(s.find(1)->ratio.low, 3.0);
    EXPECT_GT(s.find(1)->ratio.high, 3.0);
    EXPECT_FALSE(s.find(2)->ratio.valid());  // tiled recorded no lighting samples here
    EXPECT_TRUE(hasSeries(r, "lighting"));
    EXPECT_FALSE(hasSeries(r, "ssao"));
    const std::string table = markdownTable(r, s);
    EXPECT_NE(table.find("| lighting ratio to lighting.strategy=stencil_volumes | 95% CI |"), std::string::npos) << table;
    EXPECT_NE(benchJson(r, s).find("\"series\": \"lighting\""), std::string::npos);
}

TEST(BenchSummary, RatiosAgainstTheFirstValueOfTheFirstSweptKnob) {
    const BenchGrid g = smallGrid();
    // fullscreen twice as slow as stencil_volumes, in every size and light count.
    const BenchResults r = synthetic(g, 25, [](const BenchConfig& c) {
        return (c.knobValues[0] == "fullscreen" ? 2.0 : 1.0) * (1.0 + c.lights) * (c.width / 64.0);
    });
    const BenchBaseline b = chooseBaseline(r, "");
    EXPECT_EQ(b.axis, "lighting.strategy");
    EXPECT_EQ(b.value, "stencil_volumes");
    const BenchBaseline fromGrid = chooseBaseline(g, 0, "");
    EXPECT_EQ(fromGrid.axis, b.axis);
    EXPECT_EQ(fromGrid.value, b.value);
    const BenchSummary s = summarize(r, b, 1000);
    ASSERT_EQ(s.rows.size(), 8u);
    for (const auto& row : s.rows) {
        const bool full = r.find(row.config)->config.knobValues[0] == "fullscreen";
        EXPECT_EQ(row.baseline, full ? row.config - 1 : row.config);
        ASSERT_TRUE(row.ratio.valid());
        EXPECT_NEAR(row.ratio.ratio, full ? 2.0 : 1.0, 0.1);
        EXPECT_LE(row.ratio.low, row.ratio.ratio);
        EXPECT_GE(row.ratio.high, row.ratio.ratio);
        ASSERT_NE(row.frame(), nullptr);
        EXPECT_EQ(row.frame()->gpu.count, 25);
        EXPECT_EQ(row.series.back().series, "frame");
    }
    EXPECT_EQ(s.passes, (std::vector<std::string>{"geometry", "lighting"}));

    const std::string table = markdownTable(r, s);
    EXPECT_NE(table.find("| config | size | lights | lighting.strategy | LPP |"), std::string::npos) << table;
    EXPECT_NE(table.find("95% CI"), std::string::npos);
    EXPECT_NE(table.find("1 (baseline)"), std::string::npos);
    int rows = 0;  // table lines that are neither the header nor the rule under it
    for (size_t p = 0; p < table.size(); p = table.find('\n', p) + 1)
        rows += table.compare(p, 2, "| ") == 0 && table.compare(p, 5, "| ---") != 0;
    EXPECT_EQ(rows, 8 + 1);
    EXPECT_NE(markdownPassTable(r, s).find("| geometry | lighting | frame |"), std::string::npos);

    // --baseline picks another axis; a value the run never had is an error.
    const BenchBaseline lights = chooseBaseline(r, "lights=10");
    EXPECT_EQ(lights.axis, "lights");
    const BenchSummary byLights = summarize(r, lights, 500);
    EXPECT_NEAR(byLights.find(0)->ratio.ratio, 2.0 / 11.0, 0.02);
    EXPECT_THROW(chooseBaseline(r, "lights=3"), Error);
    EXPECT_THROW(chooseBaseline(r, "ssao.samples=8"), Error);
    EXPECT_THROW(chooseBaseline(r, "lights"), Error);
}

// The tables' fixes of issue 23: no two columns named alike, LPP under 0.005
// with its digits, --ratio-of with the frame's ratio and the series' own
// median beside its ratio, and what auto picked.
TEST(BenchSummary, TablesNameEachColumnOnceAndShowWhatTheyCompare) {
    BenchGrid g;
    g.sizes = {{64, 36}};
    g.lights = {10};
    g.knobAxes = {BenchGrid::parseSweep("lighting.strategy=stencil_volumes,auto")};
    BenchResults r;
    r.knobAxes = {"lighting.strategy"};
    long long seq = 0;
    for (const auto& c : g.configs()) {
        r.configs.push_back({c, 0.0012, 0.25});
        if (c.knobValues[0] == "auto") r.configs.back().stats["lighting"] = "tiled, 10 lights; auto picked tiled: 10 lights";
        for (int k = 0; k < 20; ++k, ++seq) {
            const double f = c.index == 1 ? 2.0 : 1.0;
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "lights", 0.5 * f, 0.1});
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "lighting", 3.0 * f, 0.1});
            r.samples.push_back({c.index, k, seq, static_cast<std::uint64_t>(seq), "frame", 10.0 + k * 0.01, 0.2});
        }
    }
    BenchBaseline b = chooseBaseline(r, "");
    b.series = "lighting";
    const BenchSummary s = summarize(r, b, 300);
    const std::string main = markdownTable(r, s);
    EXPECT_NE(main.find("| 0.0012 | 0.25 |"), std::string::npos) << main;
    EXPECT_NE(main.find("| auto picked |"), std::string::npos) << main;
    EXPECT_NE(main.find("| tiled |"), std::string::npos) << main;
    EXPECT_NE(main.find("| frame ratio to lighting.strategy=stencil_volumes | frame 95% CI | lighting GPU ms median | "
                        "lighting ratio to lighting.strategy=stencil_volumes | 95% CI |"),
              std::string::npos)
        << main;
    EXPECT_NE(main.find("| 6.000 | 2.000 |"), std::string::npos) << "the lighting median beside its ratio\n" << main;
    ASSERT_TRUE(s.find(1)->frameRatio.valid());
    EXPECT_NEAR(s.find(1)->frameRatio.ratio, 1.0, 0.01);
    EXPECT_EQ(lppText(0.0012), "0.0012");
    EXPECT_EQ(lppText(0.25), "0.25");
    EXPECT_EQ(lppText(0.0), "0.00");
    EXPECT_NE(mainTableCaption(s, 300).find("lighting GPU ms median and ratio"), std::string::npos);

    // Every header of both tables once.
    for (const std::string& table : {main, markdownPassTable(r, s)}) {
        const std::string header = table.substr(0, table.find('\n'));
        std::vector<std::string> names;
        for (size_t p = 1; p < header.size();) {
            const size_t q = header.find('|', p);
            names.push_back(header.substr(p + 1, q - p - 2));
            p = q + 1;
        }
        std::set<std::string> unique(names.begin(), names.end());
        EXPECT_EQ(unique.size(), names.size()) << header;
    }
    EXPECT_NE(markdownPassTable(r, s).find("| lights (pass) | lighting | frame |"), std::string::npos)
        << markdownPassTable(r, s);
}

TEST(BenchResults, CsvKeepsEveryDigitSoMergedShardsEqualTheUnshardedRun) {
    // Lights per pixel and timings as a run measures them: not 4-decimal numbers.
    const BenchGrid g = smallGrid();
    BenchResults all = synthetic(g, 3, [](const BenchConfig& c) { return 1.0 + c.lights / 7.0; });
    for (auto& c : all.configs) {
        c.lpp = c.config.lights / 3.0 + 1e-9;
        c.lppLit = c.config.lights * 0.123456789012345;
    }
    const BenchResults back = BenchResults::parseCsv(all.csv(), "all.csv");
    ASSERT_EQ(back.configs.size(), all.configs.size());
    for (std::size_t i = 0; i < all.configs.size(); ++i) {
        EXPECT_EQ(back.configs[i].lpp, all.configs[i].lpp) << i;  // bit for bit, not 0.3333
        EXPECT_EQ(back.configs[i].lppLit, all.configs[i].lppLit) << i;
    }
    ASSERT_EQ(back.samples.size(), all.samples.size());
    for (std::size_t i = 0; i < all.samples.size(); ++i) {
        EXPECT_EQ(back.samples[i].gpuMs, all.samples[i].gpuMs) << i;
        EXPECT_EQ(back.samples[i].cpuMs, all.samples[i].cpuMs) << i;
    }
    // Two shards through their CSVs merge to the unsharded run's values, digit for digit.
    BenchResults parts[2];
    for (int i = 0; i < 2; ++i) {
        parts[i].knobAxes = all.knobAxes;
        for (const auto& c : all.configs)
            if (c.config.index % 2 == i) parts[i].configs.push_back(c);
        for (const auto& s : all.samples)
            if (s.config % 2 == i) parts[i].samples.push_back(s);
    }
    const BenchResults merged = BenchResults::merge(
        {BenchResults::parseCsv(parts[0].csv(), "a.csv"), BenchResults::parseCsv(parts[1].csv(), "b.csv")}, {"a.csv", "b.csv"});
    for (std::size_t i = 0; i < all.configs.size(); ++i) EXPECT_EQ(merged.configs[i].lpp, all.configs[i].lpp) << i;
    for (std::size_t i = 0; i < all.samples.size(); ++i) EXPECT_EQ(merged.samples[i].gpuMs, all.samples[i].gpuMs) << i;
}

// Shards of one run differ only in --shard and their outputs: written with
// --record (--json's newer name) they are one run too (merge refused them:
// "comes from another bench run ... --record=shard-1.json").
TEST(BenchMerge, ShardsWrittenWithRecordOrJsonAreOneRun) {
    const std::string base = "deferred-workbench bench --scene default --size 32x18 --lights 1,10 --frames 2";
    EXPECT_EQ(benchRunOf(base + " --shard 0/2 --csv shard-0.csv --record shard-0.json"),
              benchRunOf(base + " --shard 1/2 --csv shard-1.csv --record shard-1.json"));
    EXPECT_EQ(benchRunOf(base + " --shard 0/2 --json shard-0.json"), benchRunOf(base + " --shard 1/2 --record=b.json"));
    EXPECT_NE(benchRunOf(base + " --shard 0/2 --record a.json"), benchRunOf(base + " --frames 3 --shard 1/2"));
}

TEST(BenchResults, CounterColumnsFollowTheTimesAndReadBack) {
    BenchResults r = synthetic(smallGrid(), 2, [](const BenchConfig& c) { return 1.0 + c.lights; });
    r.counted = true;
    for (auto& s : r.samples) {
        if (s.series == "frame") continue;  // left unmeasured: its cells are empty
        for (int i = 0; i < PassCounts::kCount; ++i) s.counts.v[static_cast<size_t>(i)] = 1000 * s.config + 10 * i + s.sample;
    }
    const std::string csv = r.csv();
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "config,size,lights,lighting.strategy,lpp,lpp_lit,sample,seq,frame,pass,gpu_ms,"
                                             "cpu_ms,gpu_mem_peak_mib,fragments,samples,primitives,vertices,compute,bytes");
    const BenchResults back = BenchResults::parseCsv(csv, "c.csv");
    EXPECT_TRUE(back.counted);
    ASSERT_EQ(back.samples.size(), r.samples.size());
    for (size_t i = 0; i < r.samples.size(); ++i) EXPECT_EQ(back.samples[i].counts, r.samples[i].counts) << i;
    EXPECT_EQ(back.csv(), csv);
    // Shards keep them through bench merge.
    BenchResults merged = BenchResults::merge({back}, {"c.csv"});
    EXPECT_EQ(merged.csv(), csv);
    // A count that is not a whole number is refused with its line.
    std::string bad = csv;
    ASSERT_NE(bad.find(",0,10,20,30,40,50\n"), std::string::npos);
    bad.replace(bad.find(",0,10,20,30,40,50\n"), 2, ",x");
    EXPECT_THROW(BenchResults::parseCsv(bad, "c.csv"), FileError);
}

// The peak GPU memory column (issue 36): each frame's MiB read back to the
// last bit (bytes / 2^20 is exact in a double), the configuration's peak the
// largest of its rows, and a CSV written before the column still read.
TEST(BenchResults, PeakGpuMemoryColumnRoundTripsAndOlderCsvsStillRead) {
    const BenchGrid g = smallGrid();
    BenchResults r = synthetic(g, 2, [](const BenchConfig& c) { return 1.0 + c.lights; });
    for (auto& s : r.samples) s.gpuMemPeakMib = static_cast<double>(1234567 + 1000 * s.config + s.sample) / (1024.0 * 1024.0);
    const BenchResults back = BenchResults::parseCsv(r.csv(), "m.csv");
    ASSERT_EQ(back.samples.size(), r.samples.size());
    for (size_t i = 0; i < r.samples.size(); ++i) EXPECT_EQ(back.samples[i].gpuMemPeakMib, r.samples[i].gpuMemPeakMib);
    EXPECT_EQ(gpuMemPeakMib(back.samples, 1), static_cast<double>(1234567 + 1000 + 1) / (1024.0 * 1024.0));
    EXPECT_TRUE(std::isnan(gpuMemPeakMib(back.samples, 99)));

    // Without the column (a CSV from before it): every row reads, the peak unknown.
    std::string old;
    std::istringstream lines(r.csv());
    for (std::string line; std::getline(lines, line);) old += line.substr(0, line.rfind(',')) + "\n";
    const BenchResults older = BenchResults::parseCsv(old, "old.csv");
    ASSERT_EQ(older.samples.size(), r.samples.size());
    EXPECT_TRUE(std::isnan(older.samples[0].gpuMemPeakMib));
    EXPECT_DOUBLE_EQ(older.configs[2].lpp, back.configs[2].lpp);
    // A bad value names the column.
    std::string bad = r.csv();
    const size_t firstRowEnd = bad.find('\n', bad.find('\n') + 1);
    bad.replace(bad.rfind(',', firstRowEnd) + 1, firstRowEnd - bad.rfind(',', firstRowEnd) - 1, "-3");
    try {
        BenchResults::parseCsv(bad, "bad.csv");
        ADD_FAILURE() << "a negative MiB was read";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("gpu_mem_peak_mib: expected MiB"), std::string::npos) << e.what();
    }
}

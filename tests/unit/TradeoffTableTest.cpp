// The tradeoff CSV (writer, reader, merge) and the Pareto front, without GL.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <limits>
#include <random>

#include "renderer/Error.h"
#include "renderer/bench/ImageError.h"
#include "renderer/bench/ParetoFront.h"
#include "renderer/bench/TradeoffShards.h"
#include "renderer/bench/TradeoffTable.h"

using namespace dw;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<size_t> frontOf(const std::vector<ParetoPoint>& points) { return ParetoFront(points).members(); }

// The definition, point against point.
std::vector<bool> bruteForce(const std::vector<ParetoPoint>& p) {
    std::vector<bool> on(p.size());
    for (size_t i = 0; i < p.size(); ++i) {
        on[i] = std::isfinite(p[i].cost) && std::isfinite(p[i].error);
        for (size_t j = 0; j < p.size() && on[i]; ++j) {
            if (!std::isfinite(p[j].cost) || !std::isfinite(p[j].error)) continue;
            const bool noWorse = p[j].cost <= p[i].cost && p[j].error <= p[i].error;
            const bool better = p[j].cost < p[i].cost || p[j].error < p[i].error;
            if (noWorse && better) on[i] = false;
        }
    }
    return on;
}

TradeoffRow row(int point, std::vector<std::string> axisValues, const std::string& camera, double error, double ms) {
    TradeoffRow r;
    r.point = point;
    r.axisValues = std::move(axisValues);
    r.camera = camera;
    r.metric = "rms";
    r.buffer = "ao";
    r.error = error;
    r.errorLo = error * 0.9;
    r.errorHi = error * 1.1;
    r.frames = 8;
    r.frameGpuMs = ms;
    r.frameGpuMsLo = ms * 0.95;
    r.frameGpuMsHi = ms * 1.05;
    r.passGpuMs = {ms * 0.25, ms * 0.5};
    return r;
}

// Samples x resolution on two cameras and their "all" rows.
TradeoffTable study() {
    TradeoffTable t;
    t.axes = {"ssao.samples", "ssao.resolution"};
    t.passes = {"geometry", "ssao"};
    int point = 0;
    for (int samples : {8, 16, 32})
        for (const char* res : {"full", "half"}) {
            const double ms = samples * (res[0] == 'f' ? 1.0 : 0.3);
            const double err = (res[0] == 'f' ? 1.0 : 1.6) / std::sqrt(samples);
            for (const char* cam : {"0", "1", "all"})
                t.rows.push_back(row(point, {std::to_string(samples), res}, cam, err * (cam[0] == '1' ? 1.2 : 1.0), ms));
            ++point;
        }
    return t;
}

std::string messageOf(const std::string& csv) {
    try {
        TradeoffTable::parseCsv(csv, "t.csv");
    } catch (const FileError& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kHeader =
    "point,ssao.samples,camera,metric,buffer,error,error_lo,error_hi,frames,frame_gpu_ms,frame_gpu_ms_lo,"
    "frame_gpu_ms_hi,gpu_ms.ssao,pareto\n";

}  // namespace

TEST(ParetoFront, EmptySinglePointTiesAndDuplicates) {
    try {
        ParetoFront front({});
        FAIL() << "an empty sweep has no front";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "no points to compare: the sweep is empty");
    }
    EXPECT_EQ(frontOf({{3.0, 0.5}}), (std::vector<size_t>{0}));

    // Same cost: only the lower error. Same error: only the lower cost.
    EXPECT_EQ(frontOf({{2.0, 0.3}, {2.0, 0.1}}), (std::vector<size_t>{1}));
    EXPECT_EQ(frontOf({{5.0, 0.1}, {2.0, 0.1}}), (std::vector<size_t>{1}));
    // Exact duplicates dominate neither the other: both on the front, by index.
    EXPECT_EQ(frontOf({{4.0, 0.2}, {1.0, 0.9}, {4.0, 0.2}, {4.0, 0.2}}), (std::vector<size_t>{1, 0, 2, 3}));
    // A duplicate of a dominated point stays off.
    EXPECT_EQ(frontOf({{1.0, 0.1}, {4.0, 0.2}, {4.0, 0.2}}), (std::vector<size_t>{0}));
    // A staircase, given out of order; members read left to right.
    const ParetoFront stairs({{3.0, 0.2}, {1.0, 0.8}, {2.0, 0.5}, {2.5, 0.6}, {6.0, 0.05}, {6.0, 0.2}});
    EXPECT_EQ(stairs.members(), (std::vector<size_t>{1, 2, 0, 4}));
    EXPECT_TRUE(stairs.contains(4));
    EXPECT_FALSE(stairs.contains(3));
    EXPECT_FALSE(stairs.contains(5));
    EXPECT_FALSE(stairs.contains(99));
    // A point without a time or an error is off the front and dominates nothing.
    EXPECT_EQ(frontOf({{kNaN, 0.0}, {1.0, 0.5}, {0.5, kNaN}, {2.0, 0.4}}), (std::vector<size_t>{1, 3}));
    EXPECT_EQ(ParetoFront({{kNaN, kNaN}}).size(), 0u);
    // Negative errors (a similarity flipped to be minimised) work as any other.
    EXPECT_EQ(frontOf({{1.0, -30.0}, {2.0, -40.0}, {3.0, -35.0}}), (std::vector<size_t>{0, 1}));
}

TEST(ParetoFront, MatchesTheDefinitionOnRandomGridsWithManyTies) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 300; ++trial) {
        std::uniform_int_distribution<int> n(1, 40), v(0, 6);
        std::vector<ParetoPoint> p(static_cast<size_t>(n(rng)));
        for (auto& q : p) q = {double(v(rng)), double(v(rng)) * 0.125};
        const std::vector<bool> expected = bruteForce(p);
        const ParetoFront front(p);
        for (size_t i = 0; i < p.size(); ++i) ASSERT_EQ(front.contains(i), expected[i]) << "trial " << trial << " point " << i;
        for (size_t k = 1; k < front.members().size(); ++k) {
            const ParetoPoint &a = p[front.members()[k - 1]], &b = p[front.members()[k]];
            ASSERT_TRUE(a.cost < b.cost || (a.cost == b.cost && a.error == b.error)) << "left to right";
        }
    }
}

TEST(TradeoffTable, HeaderAndFrontPerCamera) {
    TradeoffTable t = study();
    EXPECT_EQ(t.csv().substr(0, t.csv().find('\n')),
              "point,ssao.samples,ssao.resolution,camera,metric,buffer,error,error_lo,error_hi,frames,frame_gpu_ms,"
              "frame_gpu_ms_lo,frame_gpu_ms_hi,gpu_ms.geometry,gpu_ms.ssao,pareto,time,time_ms,time_ms_lo,time_ms_hi,"
              "front,dominated_by,tied_with,pick,gpu_mem_peak_mib");
    t.markParetoFront();
    // Camera 0, (ms, error) by cost: 8 half (2.4, .566), 16 half (4.8, .4), 8 full (8, .354),
    // 32 half (9.6, .283), 16 full (16, .25), 32 full (32, .177): each lowers the error, all on the front.
    std::vector<int> onFront;
    for (const auto& r : t.rows)
        if (r.camera == "0" && r.pareto) onFront.push_back(r.point);
    EXPECT_EQ(onFront, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    // Make full resolution at 16 samples worse than half at 32 on camera 1 only.
    for (auto& r : t.rows)
        if (r.camera == "1" && r.point == 2) r.error = 0.5;
    t.markParetoFront();
    for (const auto& r : t.rows) {
        if (r.point == 2) {
            EXPECT_EQ(r.pareto, r.camera != "1") << r.camera;
        }
    }
    EXPECT_EQ(t.axisValue(t.rows[3], "ssao.samples"), "8");
    EXPECT_EQ(t.axisValue(t.rows[3], "ssao.resolution"), "half");
    EXPECT_EQ(t.axisValue(t.rows[3], "preset"), "");
    EXPECT_DOUBLE_EQ(t.passGpuMs(t.rows[3], "ssao"), 1.2);
    EXPECT_TRUE(std::isnan(t.passGpuMs(t.rows[3], "bloom")));

    // PSNR and SSIM: larger is better.
    TradeoffTable s;
    s.axes = {"preset"};
    for (int i = 0; i < 3; ++i) s.rows.push_back(row(i, {"SSAO" + std::to_string(i + 1)}, "0", 0.0, 1.0 + i));
    s.rows[0].metric = s.rows[1].metric = s.rows[2].metric = "psnr";
    s.rows[0].error = 30.0;
    s.rows[1].error = 28.0;
    s.rows[2].error = 40.0;
    s.markParetoFront();
    EXPECT_TRUE(s.rows[0].pareto);
    EXPECT_FALSE(s.rows[1].pareto);
    EXPECT_TRUE(s.rows[2].pareto);
    EXPECT_FALSE(TradeoffTable::lowerIsBetter("ssim"));
    EXPECT_TRUE(TradeoffTable::lowerIsBetter("flip"));

    TradeoffTable empty;
    empty.axes = {"ssao.samples"};
    try {
        empty.markParetoFront();
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "no points to compare: the sweep is empty");
    }
}

// --time PASS: the front of one pass's time against the error, which can
// differ from the frame's front; a pass not in the table is refused.
TEST(TradeoffTable, FrontByOnePassTime) {
    TradeoffTable t;
    t.axes = {"shadows.map_size"};
    t.passes = {"shadows", "lighting"};
    // (frame ms, shadows ms, error): the frame time is noise that hides the pass's cost.
    const double data[][3] = {{50.0, 1.0, 0.30}, {40.0, 2.0, 0.20}, {45.0, 4.0, 0.10}, {60.0, 4.0, 0.10}, {30.0, 8.0, 0.05}};
    for (int i = 0; i < 5; ++i) {
        TradeoffRow r = row(i, {std::to_string(128 << i)}, "0", data[i][2], data[i][0]);
        r.passGpuMs = {data[i][1], 10.0};
        t.rows.push_back(r);
    }
    t.rows[4].passGpuMs[0] = kNaN;  // the pass did not run at point 4: no time, off its front
    auto front = [&] {
        std::vector<int> on;
        for (const auto& r : t.rows)
            if (r.pareto) on.push_back(r.point);
        return on;
    };
    t.markParetoFront();
    EXPECT_EQ(front(), (std::vector<int>{4}));  // frame: 30 ms with the least error beats everything
    t.markParetoFront("shadows");
    // shadows ms: 1 (.3), 2 (.2), 4 (.1) twice (exact duplicates both stay), point 4 has none.
    EXPECT_EQ(front(), (std::vector<int>{0, 1, 2, 3}));
    EXPECT_DOUBLE_EQ(t.timeOf(t.rows[2], "shadows"), 4.0);
    EXPECT_DOUBLE_EQ(t.timeOf(t.rows[2], "frame"), 45.0);
    try {
        t.markParetoFront("ssao");
        FAIL() << "no ssao column";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--time ssao: no pass of that name was timed (expected frame or one of: "
                                             "shadows"),
                  std::string::npos)
            << e.what();
    }
    // merge ranks by the same time.
    const TradeoffTable merged = TradeoffTable::merge({t}, {"a.csv"}, "shadows");
    for (size_t i = 0; i < merged.rows.size(); ++i) EXPECT_EQ(merged.rows[i].pareto, i < 4) << i;
}

TEST(TradeoffTable, ReadsBackExactly) {
    TradeoffTable t = study();
    t.axes[1] = "camera.near";
    for (auto& r : t.rows)
        if (r.point == 0) r.axisValues[1] = "a,\"quoted\" value";
    t.rows[1].error = t.rows[1].errorLo = t.rows[1].errorHi = kNaN;  // not measured
    t.rows[2].passGpuMs[1] = kNaN;                                 // the pass did not run
    t.rows[3].frameGpuMs = 0.1 + 0.2;                              // needs 17 digits
    t.rows[4].error = 1e-9;
    t.rows[0].gpuMemPeakMib = 178833205.0 / (1024.0 * 1024.0);  // every byte, in MiB
    t.markParetoFront();
    const std::string text = t.csv();
    const TradeoffTable back = TradeoffTable::parseCsv(text, "t.csv");
    EXPECT_EQ(back.axes, t.axes);
    EXPECT_EQ(back.passes, t.passes);
    ASSERT_EQ(back.rows.size(), t.rows.size());
    EXPECT_EQ(back.rows[0].axisValues[1], "a,\"quoted\" value");
    EXPECT_TRUE(std::isnan(back.rows[1].error));
    EXPECT_TRUE(std::isnan(back.rows[2].passGpuMs[1]));
    EXPECT_EQ(back.rows[3].frameGpuMs, 0.1 + 0.2);
    EXPECT_EQ(back.rows[4].error, 1e-9);
    EXPECT_EQ(back.rows[0].gpuMemPeakMib * 1024.0 * 1024.0, 178833205.0);
    EXPECT_TRUE(std::isnan(back.rows[1].gpuMemPeakMib));  // not measured: empty
    EXPECT_EQ(back.csv(), text);
    // Ending at pick (a CSV written before the column): the same rows, the memory unknown.
    std::string atPick, line;
    std::istringstream lines(text);
    while (std::getline(lines, line)) atPick += line.substr(0, line.rfind(',')) + "\n";
    const TradeoffTable older = TradeoffTable::parseCsv(atPick, "older.csv");
    ASSERT_EQ(older.rows.size(), t.rows.size());
    EXPECT_TRUE(std::isnan(older.rows[0].gpuMemPeakMib));
    EXPECT_EQ(older.rows[3].frameGpuMs, 0.1 + 0.2);
    TradeoffTable again = back;
    again.markParetoFront();
    for (size_t i = 0; i < t.rows.size(); ++i) EXPECT_EQ(again.rows[i].pareto, t.rows[i].pareto) << i;
    // A header alone: an empty table, whose front is the clear error.
    EXPECT_EQ(TradeoffTable::parseCsv(kHeader, "t.csv").rows.size(), 0u);
}

TEST(TradeoffTable, BadInputNamesFileLineAndColumn) {
    const std::string ok = "0,8,0,rms,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25,1\n";
    EXPECT_EQ(messageOf(kHeader + ok), "(no error)");
    EXPECT_EQ(messageOf(""), "t.csv: line 1: empty (expected the tradeoff CSV header point,<axis>...,camera,metric,"
                             "buffer,error,error_lo,error_hi,frames,frame_gpu_ms,frame_gpu_ms_lo,frame_gpu_ms_hi,"
                             "gpu_ms.<pass>...,pareto,time,time_ms,time_ms_lo,time_ms_hi,front,dominated_by,tied_with,pick,"
                             "gpu_mem_peak_mib)");
    EXPECT_EQ(messageOf("config,size\n").substr(0, 44), "t.csv: line 1, column 1: expected 'point', g");
    EXPECT_EQ(messageOf("point,a,a,camera\n"), "t.csv: line 1, column 3: the column 'a' is there twice (also column 2)");
    EXPECT_EQ(messageOf("point,a,camera,metric,buffer,error,error_lo,error_hi,frames,frame_gpu_ms,frame_gpu_ms_lo,"
                        "frame_gpu_ms_hi,lights,pareto\n"),
              "t.csv: line 1, column 13: expected a pass's column gpu_ms.<pass> or 'pareto', got 'lights'");
    EXPECT_EQ(messageOf("point,a,camera,metric,buffer,error,frames\n"),
              "t.csv: line 1, column 7: expected the column 'error_lo', got 'frames'");
    EXPECT_EQ(messageOf(kHeader + ok + "1,16,0,rms,ao,x,0.4,0.6,8,2.5,2.4,2.6,1.25,0\n"),
              "t.csv: line 3, column 6: error: expected a number or nothing, got 'x'");
    EXPECT_EQ(messageOf(kHeader + "0,8,0,rms,ao,0.5,0.4,0.6,8,-2.5,2.4,2.6,1.25,1\n"),
              "t.csv: line 2, column 10: frame_gpu_ms: expected milliseconds (a finite number, at least 0), got '-2.5'");
    EXPECT_EQ(messageOf(kHeader + "0,8,0,rms,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25\n"),
              "t.csv: line 2, column 14: expected 14 fields, got 13");
    EXPECT_EQ(messageOf(kHeader + "0,8,0,rms,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25,yes\n"),
              "t.csv: line 2, column 14: pareto: expected 0 or 1, got 'yes'");
    EXPECT_EQ(messageOf(kHeader + "0,8,0,mse,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25,1\n"),
              "t.csv: line 2, column 4: metric: expected flip, rms, psnr, ssim or temporal, got 'mse'");
    EXPECT_EQ(messageOf(kHeader + "-1,8,0,rms,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25,1\n"),
              "t.csv: line 2, column 1: point: expected a whole number, at least 0, got '-1'");
    EXPECT_EQ(messageOf(kHeader + "0,8,0,rms,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25,1\n0,16,1,rms,ao,0.5,0.4,0.6,8,2.5,2.4,2.6,1.25,1\n"),
              "t.csv: line 3, column 2: point 0 has ssao.samples '16' here and '8' on line 2");
    EXPECT_EQ(messageOf(kHeader + ok + ok),
              "t.csv: line 3, column 1: point 0, camera 0, rms on ao is there twice (also line 2; a file joined twice?)");
    EXPECT_EQ(messageOf(kHeader + ok.substr(0, ok.size() - 5)),
              "t.csv: line 2: the last line has no end (is the file cut short?)");
    EXPECT_THROW(TradeoffTable::readCsv("/nonexistent/tradeoff.csv"), FileError);
}

TEST(TradeoffTable, ShardsMergeToOneTable) {
    TradeoffTable whole = study();
    whole.markParetoFront();
    // Two shards: even and odd points, the second without the geometry pass's column.
    TradeoffTable a, b;
    a.axes = b.axes = whole.axes;
    a.passes = whole.passes;
    b.passes = {"ssao"};
    for (const auto& r : whole.rows) {
        TradeoffRow copy = r;
        copy.pareto = false;
        if (r.point % 2 == 0) {
            a.rows.push_back(copy);
        } else {
            copy.passGpuMs = {r.passGpuMs[1]};
            b.rows.insert(b.rows.begin(), copy);  // any order
        }
    }
    const TradeoffTable merged = TradeoffTable::merge({b, a}, {"b.csv", "a.csv"});
    EXPECT_EQ(merged.passes, (std::vector<std::string>{"ssao", "geometry"}));
    ASSERT_EQ(merged.rows.size(), whole.rows.size());
    for (size_t i = 0; i < whole.rows.size(); ++i) {
        EXPECT_EQ(merged.rows[i].point, whole.rows[i].point);
        EXPECT_EQ(merged.rows[i].camera, whole.rows[i].camera);
        EXPECT_EQ(merged.rows[i].pareto, whole.rows[i].pareto);
        EXPECT_EQ(merged.passGpuMs(merged.rows[i], "ssao"), whole.passGpuMs(whole.rows[i], "ssao"));
        EXPECT_TRUE(merged.rows[i].point % 2 == 1 ? std::isnan(merged.passGpuMs(merged.rows[i], "geometry"))
                                                  : merged.passGpuMs(merged.rows[i], "geometry") ==
                                                        whole.passGpuMs(whole.rows[i], "geometry"));
    }
    // Cameras in order: 0, 1, ..., 10, then "all".
    TradeoffTable c;
    c.axes = {"k"};
    for (const char* cam : {"all", "10", "2", "0"}) c.rows.push_back(row(0, {"v"}, cam, 0.1, 1.0));
    const TradeoffTable ordered = TradeoffTable::merge({c}, {"c.csv"});
    EXPECT_EQ(ordered.rows[0].camera, "0");
    EXPECT_EQ(ordered.rows[1].camera, "2");
    EXPECT_EQ(ordered.rows[2].camera, "10");
    EXPECT_EQ(ordered.rows[3].camera, "all");

    try {
        TradeoffTable::merge({a, a}, {"a.csv", "again.csv"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "point 0, camera 0 is in both a.csv and again.csv (shards of one sweep never share a point)");
    }
    TradeoffTable other = b;
    other.axes = {"ssao.samples"};
    for (auto& r : other.rows) r.axisValues.resize(1);
    try {
        TradeoffTable::merge({a, other}, {"a.csv", "o.csv"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "o.csv sweeps other axes (ssao.samples) than a.csv (ssao.samples,ssao.resolution)");
    }
    TradeoffTable moved = b;
    moved.rows[0].point = 0;
    moved.rows[0].camera = "7";
    try {
        TradeoffTable::merge({a, moved}, {"a.csv", "m.csv"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "point 0 is a different configuration in a.csv and m.csv (not shards of one sweep)");
    }
    try {
        TradeoffTable::merge({TradeoffTable{}}, {"empty.csv"});
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "no points to compare: the sweep is empty");
    }
}

// Issue 23: a PSNR of inf (an image identical to the one measured against) is
// the best error there is, so it is on the front; NaN and +inf errors are not.
TEST(ParetoFront, InfinitePsnrIsOnTheFront) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    // Flipped PSNR: -inf is the lowest error. The slow identical point is on the front.
    EXPECT_EQ(frontOf({{1.0, -30.0}, {5.0, -kInf}, {6.0, -kInf}, {2.0, -35.0}}), (std::vector<size_t>{0, 3, 1}));
    EXPECT_EQ(frontOf({{1.0, kInf}, {2.0, 0.5}, {0.5, kNaN}}), (std::vector<size_t>{1}));

    TradeoffTable t;
    t.axes = {"ssao.samples"};
    for (int p = 0; p < 3; ++p) {
        TradeoffRow r = row(p, {std::to_string(8 << p)}, "0", p == 2 ? kInf : 20.0 + p, 1.0 + p);
        r.metric = "psnr";
        t.rows.push_back(r);
    }
    t.markParetoFront();
    EXPECT_TRUE(t.rows[0].pareto);
    EXPECT_TRUE(t.rows[1].pareto);
    EXPECT_TRUE(t.rows[2].pareto);  // the most expensive, but PSNR inf: nothing beats it on error
    const TradeoffTable back = TradeoffTable::parseCsv(t.csv(), "t.csv");
    EXPECT_EQ(back.rows[2].error, kInf);
}

// Issue 23: tradeoff merge refuses shards of other runs, naming both files and
// the field, and says which shards are missing.
TEST(TradeoffShards, OtherRunsAreRefusedAndMissingShardsSaid) {
    auto input = [](const std::string& name, const std::string& metric, const std::string& shard) {
        TradeoffShardInput in;
        in.name = name;
        in.fields = {{"axes", "ssao.samples"}, {"metric", metric}, {"buffer", "ao"}, {"cameras", "2 (0,1)"}};
        in.shard = shard;
        return in;
    };
    EXPECT_TRUE(TradeoffShards::check({input("a.csv", "rms", "0/2"), input("b.csv", "rms", "1/2")}).empty());
    try {
        TradeoffShards::check({input("a.csv", "rms", "0/2"), input("b.csv", "flip", "1/2")});
        FAIL() << "shards of two runs merged";
    } catch (const FileError& e) {
        EXPECT_STREQ(e.what(), "b.csv: comes from another tradeoff run than a.csv (metric 'flip' against 'rms'): shards of "
                               "different runs do not merge");
    }
    TradeoffShardInput sized = input("c.json", "rms", "");
    sized.fields.emplace_back("size", "64x48");
    TradeoffShardInput other = input("d.json", "rms", "");
    other.fields.emplace_back("size", "96x54");
    EXPECT_THROW(TradeoffShards::check({sized, other}), FileError);
    // A field only one input holds is not compared.
    EXPECT_NO_THROW(TradeoffShards::check({sized, input("e.csv", "rms", "")}));

    const auto warnings = TradeoffShards::check({input("a.json", "rms", "0/3"), input("c.json", "rms", "2/3")});
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], "shard(s) 1 of 3 are not among the inputs; their points are missing from the table");
    EXPECT_THROW(TradeoffShards::check({input("a.json", "rms", "0/3"), input("b.json", "rms", "1/2")}), FileError);
}

// Issue 23: the all-cameras error is the mean over the cameras that have one.
TEST(ImageError, MeanOverTheCamerasWithAnError) {
    const ErrorEstimate e = ImageError::meanOver({0.2, kNaN, 0.4}, 200, 1);
    EXPECT_DOUBLE_EQ(e.value, 0.3);
    EXPECT_GE(e.high, e.low);
    EXPECT_TRUE(std::isnan(ImageError::meanOver({kNaN, kNaN}, 200, 1).value));
    EXPECT_TRUE(std::isnan(ImageError::meanOver({}, 200, 1).value));
    EXPECT_EQ(ImageError::meanOver({30.0, std::numeric_limits<double>::infinity()}, 200, 1).value,
              std::numeric_limits<double>::infinity());
}

namespace {
// Counters on FrontByOnePassTime's kind of table: (frame ms, fragments, error).
TradeoffTable countedTable() {
    TradeoffTable t;
    t.axes = {"ssao.samples"};
    t.passes = {"ao", "lighting"};
    t.counted = true;
    const double data[][3] = {{30.0, 4000, 0.30}, {20.0, 8000, 0.20}, {40.0, 16000, 0.10}, {25.0, 32000, 0.05}};
    for (int i = 0; i < 4; ++i) {
        TradeoffRow r = row(i, {std::to_string(4 << i)}, "0", data[i][2], data[i][0]);
        for (size_t c = 0; c < PassCounts::kCount; ++c) r.frameCounts[c] = 1000.0 * static_cast<double>(c + 1);
        r.frameCounts[PassCounts::Fragments] = data[i][1] + 100;
        CounterValues ao, lighting;
        ao.fill(kNaN);
        lighting.fill(0.0);
        ao[PassCounts::Fragments] = data[i][1];
        lighting[PassCounts::Fragments] = 100;
        r.passCounts = {ao, lighting};
        t.rows.push_back(r);
    }
    return t;
}

std::vector<int> frontPoints(const TradeoffTable& t) {
    std::vector<int> on;
    for (const auto& r : t.rows)
        if (r.pareto) on.push_back(r.point);
    return on;
}
}  // namespace

TEST(TradeoffTable, CostAxisIsGpuMsOrACounter) {
    TradeoffTable t = countedTable();
    t.markParetoFront();
    EXPECT_EQ(frontPoints(t), (std::vector<int>{1, 3}));  // by frame ms: 20 (.2) and 25 (.05)
    t.markParetoFront("frame", "fragments");
    EXPECT_EQ(frontPoints(t), (std::vector<int>{0, 1, 2, 3}));  // fragments rise as the error falls: every point
    EXPECT_DOUBLE_EQ(t.costOf(t.rows[2], "frame", "fragments"), 16100.0);
    EXPECT_DOUBLE_EQ(t.costOf(t.rows[2], "ao", "fragments"), 16000.0);
    EXPECT_DOUBLE_EQ(t.costOf(t.rows[2], "frame", "gpu_ms"), 40.0);
    EXPECT_DOUBLE_EQ(t.costOf(t.rows[2], "frame", "bytes"), 6000.0);
    EXPECT_TRUE(std::isnan(t.costOf(t.rows[2], "ao", "samples")));
    t.rows[0].frameCounts[PassCounts::Fragments] = 99999;  // now dominated by point 1 in fragments too
    t.markParetoFront("frame", "fragments");
    EXPECT_EQ(frontPoints(t), (std::vector<int>{1, 2, 3}));
    EXPECT_TRUE(TradeoffTable::isCost("samples"));
    EXPECT_FALSE(TradeoffTable::isCost("pixels"));
    try {
        t.markParetoFront("frame", "pixels");
        FAIL() << "an unknown cost";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "--cost pixels: expected one of gpu_ms, fragments, samples, primitives, vertices, compute, bytes");
    }
    for (auto& r : t.rows) r.frameCounts[PassCounts::Compute] = kNaN;
    EXPECT_THROW(t.markParetoFront("frame", "compute"), Error);
}

TEST(TradeoffTable, CounterColumnsReadBackAndMerge) {
    TradeoffTable t = countedTable();
    t.markParetoFront("frame", "fragments");
    const std::string text = t.csv();
    const std::string header = text.substr(0, text.find('\n'));
    EXPECT_NE(header.find(",gpu_ms.ao,gpu_ms.lighting,fragments,fragments.ao,fragments.lighting,samples,samples.ao,"),
              std::string::npos)
        << header;
    EXPECT_NE(header.find(",bytes,bytes.ao,bytes.lighting,pareto"), std::string::npos) << header;
    const TradeoffTable back = TradeoffTable::parseCsv(text, "t.csv");
    EXPECT_TRUE(back.counted);
    EXPECT_EQ(back.csv(), text);
    EXPECT_DOUBLE_EQ(back.passCount(back.rows[3], "ao", PassCounts::Fragments), 32000.0);
    EXPECT_TRUE(std::isnan(back.passCount(back.rows[3], "ao", PassCounts::Samples)));
    // Shards keep their counters; the front is recomputed on the cost asked for.
    TradeoffTable a = back, b = back;
    a.rows.resize(2);
    b.rows.erase(b.rows.begin(), b.rows.begin() + 2);
    const TradeoffTable merged = TradeoffTable::merge({b, a}, {"b.csv", "a.csv"}, "frame", "fragments");
    EXPECT_EQ(merged.csv(), text);
    // A CSV of the counters without the front's columns (ending at pareto, as
    // written before both were merged) reads: the counters, no front class.
    std::string noTail, line;
    std::istringstream lines(text);
    while (std::getline(lines, line)) {
        for (int k = 0; k < 9; ++k) line.erase(line.rfind(','));  // time .. pick and gpu_mem_peak_mib
        noTail += line + "\n";
    }
    const TradeoffTable old = TradeoffTable::parseCsv(noTail, "old.csv");
    EXPECT_TRUE(old.counted);
    EXPECT_DOUBLE_EQ(old.passCount(old.rows[3], "ao", PassCounts::Fragments), 32000.0);
    EXPECT_EQ(old.rows[3].front, "");
    EXPECT_EQ(old.rows[3].pareto, back.rows[3].pareto);
    // A table without counters writes and reads the columns it always had.
    TradeoffTable plain = t;
    plain.counted = false;
    EXPECT_EQ(plain.csv().find("fragments"), std::string::npos);
    EXPECT_FALSE(TradeoffTable::parseCsv(plain.csv(), "p.csv").counted);
    // A counter column out of place is named.
    std::string bad = text;
    bad.replace(bad.find("samples.ao"), 10, "samples.xx");
    try {
        TradeoffTable::parseCsv(bad, "t.csv");
        FAIL();
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("expected the counter column 'samples.ao', got 'samples.xx'"), std::string::npos)
            << e.what();
    }
}

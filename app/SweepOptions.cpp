#include "app/SweepOptions.h"
#include "renderer/OptionLimits.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

#include "renderer/Error.h"

namespace dw {

namespace {

// --plot-size, else the command's default (c.plotSize, "WxH").
std::pair<int, int> readPlotSize(CommandLine& cl, const SweepCommand& c) {
    if (const auto size = cl.size("--plot-size")) return *size;
    const auto x = c.plotSize.find('x');
    return {std::stoi(c.plotSize.substr(0, x)), std::stoi(c.plotSize.substr(x + 1))};
}

// --plot: a .png (the scripts write PNG only) at least 50x50 (the scripts' least).
void checkPlot(const std::string& plot, int width, int height) {
    std::string ext = std::filesystem::path(plot).extension().string();
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".png") throw UsageError("--plot writes a PNG; give a file name ending in .png, got '" + plot + "'");
    if (width < 50 || height < 50)
        throw UsageError("--plot-size expects at least 50x50, got " + std::to_string(width) + "x" + std::to_string(height));
}

// The run's record: --record FILE, or --json FILE (its older name: bench's
// and tradeoff's JSON became the record, one format). Both given must name
// one file. Returns the flag given (for messages) and the file, if any.
std::pair<std::string, std::optional<std::string>> readRecordFlag(CommandLine& cl) {
    const auto record = cl.value("--record");
    const auto json = cl.value("--json");
    if (record && json && *record != *json)
        throw UsageError("--record and --json are one option (the run's experiment record; --json is its older name): "
                         "give one, got --record " + *record + " and --json " + *json);
    if (record) return {"--record", record};
    return {"--json", json};
}

// --plot-size without --plot changes nothing: said, not ignored.
void notePlotSizeAlone(CommandLine& cl, const SweepCommand& c, bool plot) {
    if (!plot && cl.value("--plot-size"))
        std::fprintf(stderr, "%s: note: --plot-size sizes the plot; without --plot none is drawn\n", c.name.c_str());
}

}  // namespace

int SweepOptions::readResamples(CommandLine& cl) {
    return cl.whole("--resamples", 2000);
}

std::vector<std::pair<int, int>> SweepOptions::readSizes(CommandLine& cl, bool several) {
    if (!several) return {cl.size().value_or(std::pair{640, 360})};
    std::vector<std::pair<int, int>> sizes = cl.sizeList();
    if (sizes.empty()) sizes.emplace_back(640, 360);
    return sizes;
}

SweepOptions SweepOptions::read(CommandLine& cl, const SweepCommand& c) {
    SweepOptions o;
    for (const auto& s : cl.values("--sweep")) {
        BenchKnobAxis axis;
        try {
            axis = BenchGrid::parseSweep(s);
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
        for (const auto& a : o.sweeps)
            if (a.knob == axis.knob) throw UsageError("--sweep " + axis.knob + " is given twice");
        o.sweeps.push_back(std::move(axis));
    }
    o.excludes = cl.values("--exclude");
    for (const auto& e : o.excludes) {
        try {
            o.exclusion.add(e);
        } catch (const Error& err) {
            throw UsageError(err.what());
        }
    }
    o.frames = cl.whole("--frames", c.frames);
    o.warmup = cl.whole("--warmup", 1);
    o.block = cl.whole("--block", 1);
    o.resamples = readResamples(cl);
    o.orbit = cl.whole("--orbit", 0);
    o.walkthrough = cl.flag("--walkthrough");
    if (const auto shard = cl.shard()) std::tie(o.shard.index, o.shard.count) = *shard;
    const std::string stem = c.name + o.shardSuffix();
    o.csv = cl.value("--csv").value_or(stem + ".csv");
    const auto [recordFlag, record] = readRecordFlag(cl);
    o.jsonFlag = recordFlag;
    o.json = record.value_or(stem + ".json");
    o.plot = cl.value("--plot");
    // --plot none: no plot (tradeoff draws one by default; drawing it costs a
    // Python start and matplotlib, about half of a short sweep's CPU time:
    // docs/tradeoffs.md).
    if (o.plot == "none") o.plot.reset();
    else if (!o.plot && c.plotByDefault) o.plot = stem + ".png";
    std::tie(o.plotWidth, o.plotHeight) = readPlotSize(cl, c);
    notePlotSizeAlone(cl, c, o.plot.has_value());
    o.quiet = cl.flag("--quiet");
    return o;
}

std::string SweepOptions::shardSuffix() const {
    return shard.whole() ? "" : "-shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count);
}

std::string SweepOptions::shardText() const { return std::to_string(shard.index) + "/" + std::to_string(shard.count); }

void SweepOptions::checkOutputs(const SweepCommand& c, const CommandLine::NamedFiles& inputs) const {
    CommandLine::NamedFiles writes = {{"--csv", csv}, {jsonFlag, json}};
    if (plot) writes.emplace_back("--plot", *plot);
    CommandLine::requireDistinctFiles(writes, inputs);
    if (plot) checkPlot(*plot, plotWidth, plotHeight);
    CommandLine::requireWritable(csv, c.name + " CSV");
    CommandLine::requireWritable(json, c.name + " JSON");
    if (plot) CommandLine::requireWritable(*plot, "plot");
}

std::string SweepOptions::help(const SweepCommand& c) {
    const std::string stem = c.name;
    return "  --sweep      " + c.sweepWhat + "; repeatable, each knob once\n"
           "  --exclude    a corner of the grid left out: every named axis at one of its values, e.g.\n"
           "               lighting.strategy=fullscreen,lights=10000; repeatable\n"
           "  --frames     counted frames per configuration (default " + std::to_string(c.frames) + "); --warmup frames after each\n"
           "               switch are left out (default 1); --block K counted frames in a row (default 1:\n"
           "               A B C A B C ...); --resamples for the 95% bootstrap intervals (default 2000)\n"
           "  --orbit N    N cameras on a circle about the run's camera; --walkthrough: each keyframe of the\n"
           "               scene JSON's camera.path; " + c.camerasWhat + "\n"
           "  --shard i/n  " + c.shardWhat + "; join the shards with " + stem + " merge\n"
           "  --csv, --record  " + c.filesWhat + ";\n"
           "               default " + stem + ".csv and " + stem + ".json (" + stem + "-shard-I-of-N.* with --shard);\n"
           "               --json FILE is the same option as --record (its older name)\n"
           "  --plot       " + c.plotWhat + "; --plot none draws none; --plot-size in pixels (default " + c.plotSize + ")\n"
           "  --quiet      no progress lines on stderr\n";
}

SweepMergeOptions SweepMergeOptions::read(CommandLine& cl, const SweepCommand& c) {
    SweepMergeOptions m;
    m.out = cl.value("--out");
    std::tie(m.jsonFlag, m.json) = readRecordFlag(cl);
    m.plot = cl.value("--plot");
    if (m.plot == "none") m.plot.reset();  // as a run's --plot none
    std::tie(m.plotWidth, m.plotHeight) = readPlotSize(cl, c);
    notePlotSizeAlone(cl, c, m.plot.has_value());
    return m;
}

void SweepMergeOptions::check(const CommandLine& cl, const SweepCommand& c, const CommandLine::NamedFiles& moreReads) {
    inputs = cl.positional();
    if (inputs.empty()) throw UsageError(c.name + " merge needs the shards' CSV files");
    if (!out) throw UsageError(c.name + " merge needs --out FILE.csv");
    CommandLine::NamedFiles writes = {{"--out", *out}}, reads;
    if (json) writes.emplace_back(jsonFlag, *json);
    if (plot) writes.emplace_back("--plot", *plot);
    for (const auto& in : inputs) reads.emplace_back("the shard " + in, in);
    reads.insert(reads.end(), moreReads.begin(), moreReads.end());
    CommandLine::requireDistinctFiles(writes, reads);
    if (plot) checkPlot(*plot, plotWidth, plotHeight);
    CommandLine::requireWritable(*out, "merged CSV");
    if (json) CommandLine::requireWritable(*json, "merged JSON");
    if (plot) CommandLine::requireWritable(*plot, "plot");
}

std::string SweepMergeOptions::help(const SweepCommand& c) {
    return "  merge        joins the shards' files into --out (and --record (or --json), --plot as a run writes them)\n"
           "               into one table, as one run of the whole grid would have; --plot-size as above (default " +
           c.plotSize + ")\n";
}

}  // namespace dw

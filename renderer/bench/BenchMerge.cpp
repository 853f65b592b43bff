#include "renderer/bench/BenchMerge.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "renderer/Error.h"
#include "renderer/bench/BenchSummary.h"
#include "renderer/graph/PassTimer.h"
#include "renderer/io/JsonGuard.h"

namespace dw {

namespace fs = std::filesystem;

namespace {

std::string fieldOr(const BenchFields& f, const std::string& key, const std::string& fallback) {
    for (const auto& [k, v] : f)
        if (k == key) return v;
    return fallback;
}

}  // namespace

// An argument as a POSIX shell reads it back: as it is when it holds only
// safe characters, else in single quotes (a quote inside as '\'').
std::string shellQuoted(const std::string& arg) {
    const bool safe = !arg.empty() && std::all_of(arg.begin(), arg.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("_-+=.,:/@%", c);
    });
    if (safe) return arg;
    std::string q = "'";
    for (char c : arg) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

namespace {

// shellQuoted's words, split back.
std::vector<std::string> shellWords(const std::string& text) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false, quoted = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted) {
            if (c == '\'') quoted = false;
            else word += c;
        } else if (c == '\'') {
            quoted = inWord = true;
        } else if (c == '\\' && i + 1 < text.size()) {
            word += text[++i];
            inWord = true;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            if (inWord) words.push_back(word);
            word.clear();
            inWord = false;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (inWord) words.push_back(word);
    return words;
}

}  // namespace

// The run a shard's JSON describes, apart from which shard, where its files
// went and how its tables were made: its command without argv[0], --shard,
// --csv, --json, --plot, --plot-size, --baseline, --ratio-of, --resamples,
// --resume and --quiet (shards differing only in those measured the same grid; bench
// merge makes its own tables), its options in any order but --sweep's and
// --set's among themselves (the order of the axes, and of the assignments,
// counts). --no-lpp counts: it leaves out a column.
std::string benchRunOf(const std::string& command) {
    // Outputs (--record is --json's newer name) and what only the summary uses.
    static const std::set<std::string> ignored = {"--shard",    "--csv",      "--json",      "--record", "--plot",
                                                  "--plot-size", "--baseline", "--ratio-of", "--resamples", "--resume"};
    static const std::set<std::string> bare = {"--quiet", "--no-lpp", "--keep-scene-lights", "--walkthrough"};
    const std::vector<std::string> tokens = shellWords(command);
    std::vector<std::string> words0, unordered, ordered;  // the subcommand's words, then the options
    for (std::size_t i = 1; i < tokens.size(); ++i) {     // tokens[0]: argv[0]
        std::string option = tokens[i];
        if (option.rfind("--", 0) != 0) {
            words0.push_back(option);
            continue;
        }
        const std::string flag = option.substr(0, option.find('='));
        if (flag == option && !bare.count(flag) && i + 1 < tokens.size())
            option += "=" + tokens[++i];  // "--flag value" as "--flag=value"
        if (flag == "--quiet" || ignored.count(flag)) continue;
        (flag == "--sweep" || flag == "--set" ? ordered : unordered).push_back(option);
    }
    std::sort(unordered.begin(), unordered.end());
    std::string run;
    for (const auto& o : words0) run += (run.empty() ? "" : " ") + o;
    for (const auto& o : unordered) run += (run.empty() ? "" : " ") + o;
    for (const auto& o : ordered) run += (run.empty() ? "" : " ") + o;
    return run;
}

namespace {

BenchFields fieldsOf(const nlohmann::json& j) {
    BenchFields f;
    if (j.is_object())
        for (auto it = j.begin(); it != j.end(); ++it)
            f.emplace_back(it.key(), it.value().is_string() ? it.value().get<std::string>() : it.value().dump());
    return f;
}

}  // namespace

namespace {

// What merge learns from the shards' JSONs as it reads them.
struct ShardsSeen {
    BenchFields machine, settings;  // the first JSON's
    std::string machineNote;
    // The run they come from, and which shards of how many.
    std::string firstRun, firstRunFrom;
    int shardCount = 0;
    std::vector<int> shardIndices;
    // The series the shards' ratios compared and the baseline they divided
    // by, when all their JSONs agree ("-" when they differ): merge's
    // defaults for --ratio-of and --baseline.
    std::string ratioOf, baseline;
};

// Every configuration of a run counts the same frames: one with fewer (or
// none) was cut short, even at a line's end.
void checkShardFrames(const std::string& in, const BenchResults& part, const std::map<int, int>& framesOf,
                      int expected, const std::string& whence) {
    for (const auto& c : part.configs) {
        const auto it = framesOf.find(c.config.index);
        const int n = it == framesOf.end() ? 0 : it->second;
        if (n == 0)
            throw FileError(in, "configuration " + std::to_string(c.config.index) +
                                    " has no frame samples (is the file cut short?)");
        if (n != expected)
            throw FileError(in, "configuration " + std::to_string(c.config.index) + " has " + std::to_string(n) +
                                    " frames, " + whence + " " + std::to_string(expected) +
                                    (n < expected ? " (is the file cut short?)" : " (rows of another run?)"));
    }
}

// The shard's run (its command without --shard and outputs) and shard i/n, checked against the others'.
void checkShardRun(const std::string& json, const BenchFields& s, ShardsSeen& seen) {
    if (const std::string command = fieldOr(s, "command", ""); !command.empty()) {
        const std::string run = benchRunOf(command);
        if (seen.firstRunFrom.empty()) {
            seen.firstRun = run;
            seen.firstRunFrom = json;
        } else if (run != seen.firstRun) {
            throw FileError(json, "comes from another bench run than " + seen.firstRunFrom + " ('" + run +
                                      "' against '" + seen.firstRun + "'): shards of different runs do not merge");
        }
    }
    if (const std::string shard = fieldOr(s, "shard", ""); !shard.empty()) {
        try {
            const BenchShard sh = BenchShard::parse(shard);
            if (seen.shardCount != 0 && sh.count != seen.shardCount)
                throw FileError(json, "is shard " + shard + ", the others are of " + std::to_string(seen.shardCount) +
                                          " shards");
            seen.shardCount = sh.count;
            seen.shardIndices.push_back(sh.index);
        } catch (const FileError&) {
            throw;
        } catch (const Error&) {
            throw FileError(json, "its settings.shard '" + shard + "' is not i/n");
        }
    }
}

// The shard's JSON beside its CSV: its configurations all in the CSV, its
// frame count, baseline, run, shard and machine.
void readShardJson(const std::string& in, const fs::path& sibling, const BenchResults& part,
                   const std::map<int, int>& framesOf, int most, ShardsSeen& seen) {
    // Bounded depth like every JSON the workbench reads; numbers may be any double.
    const nlohmann::json file = readJsonFile(sibling.string(), {kMaxJsonDepth, false});
    const nlohmann::json& j = benchSummaryOf(file);  // a record's results, or an older summary
    const BenchFields s = fieldsOf(j.value("settings", nlohmann::json::object()));
    if (j.contains("configs") && j["configs"].is_array())
        for (const auto& c : j["configs"])
            if (c.is_object() && c.contains("config") && c["config"].is_number_integer() &&
                !framesOf.count(c["config"].get<int>()) &&
                std::none_of(part.configs.begin(), part.configs.end(),
                             [&](const auto& r) { return r.config.index == c["config"].get<int>(); }))
                throw FileError(in, "configuration " + std::to_string(c["config"].get<int>()) + " of " +
                                        sibling.string() + " has no samples (is the file cut short?)");
    auto agree = [](std::string& sofar, const std::string& value) {
        if (sofar != "-") sofar = sofar.empty() || sofar == value ? value : "-";
    };
    if (j.contains("baseline") && j["baseline"].is_object()) {
        const nlohmann::json& b = j["baseline"];
        if (b.contains("series") && b["series"].is_string()) agree(seen.ratioOf, b["series"].get<std::string>());
        if (b.contains("axis") && b["axis"].is_string() && b.contains("value") && b["value"].is_string())
            agree(seen.baseline, b["axis"].get<std::string>() + "=" + b["value"].get<std::string>());
    }
    const std::string frames = fieldOr(s, "frames", "");
    if (!frames.empty() && std::all_of(frames.begin(), frames.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); }))
        checkShardFrames(in, part, framesOf, std::stoi(frames), "its JSON (" + sibling.string() + ") says");
    else
        checkShardFrames(in, part, framesOf, most, "others have");
    checkShardRun(sibling.string(), s, seen);
    const BenchFields m = fieldsOf(j.value("machine", nlohmann::json::object()));
    if (seen.machine.empty()) {
        seen.machine = m;
        seen.settings = s;
    } else if (fieldOr(m, "gl_renderer", "") != fieldOr(seen.machine, "gl_renderer", "") ||
               fieldOr(m, "cpu", "") != fieldOr(seen.machine, "cpu", "")) {
        seen.machineNote = "the shards ran on different machines; each shard's JSON names its own";
    }
}

// One shard's CSV, checked, and its JSON when there is one.
BenchResults readShard(const std::string& in, ShardsSeen& seen) {
    BenchResults part = BenchResults::readCsv(in);
    // How many frames each configuration must have, the shard's JSON says;
    // without it, the most any configuration has.
    std::map<int, int> framesOf;
    for (const auto& sample : part.samples)
        if (sample.series == "frame") ++framesOf[sample.config];
    int most = 0;
    for (const auto& [config, n] : framesOf) most = std::max(most, n);
    const fs::path sibling = fs::path(in).replace_extension(".json");
    if (fs::exists(sibling)) readShardJson(in, sibling, part, framesOf, most, seen);
    else checkShardFrames(in, part, framesOf, most, "others have");
    return part;
}

// Shards of the run that are not among the inputs, said as a warning.
void warnMissingShards(const ShardsSeen& seen, std::size_t inputs, const std::function<void(const std::string&)>& say) {
    if (seen.shardCount > 0 && seen.shardIndices.size() == inputs) {
        std::string missing;
        for (int i = 0; i < seen.shardCount; ++i)
            if (std::find(seen.shardIndices.begin(), seen.shardIndices.end(), i) == seen.shardIndices.end())
                missing += (missing.empty() ? "" : ", ") + std::to_string(i);
        if (!missing.empty())
            say("bench merge: warning: shard(s) " + missing + " of " + std::to_string(seen.shardCount) +
                " are not among the inputs; their configurations are missing from the table");
    } else if (seen.shardCount > 0 && inputs < static_cast<std::size_t>(seen.shardCount)) {
        // Some inputs have no JSON to say which shard they are.
        say("bench merge: warning: " + std::to_string(inputs) + " input(s) of a run of " +
            std::to_string(seen.shardCount) + " shards (" + std::to_string(inputs - seen.shardIndices.size()) +
            " without a JSON beside them to say which shard they are): some shards are missing from the table");
    }
}

// The ratios' series and baseline: as given, else as the shards' JSONs agree, else the defaults.
BenchBaseline mergedBaseline(const BenchResults& all, const ShardsSeen& seen,
                             const std::optional<std::string>& baselineGiven,
                             const std::optional<std::string>& ratioOfGiven,
                             const std::function<void(const std::string&)>& say) {
    auto inherited = [](const std::string& fromShards) { return !fromShards.empty() && fromShards != "-"; };
    const std::string ratioOf = ratioOfGiven            ? *ratioOfGiven
                                : inherited(seen.ratioOf) ? seen.ratioOf
                                                          : PassTimer::kFrameSeries;
    const std::string baselineSpec = baselineGiven ? *baselineGiven : inherited(seen.baseline) ? seen.baseline : "";
    if (!ratioOfGiven && seen.ratioOf == "-")
        say("bench merge: note: the shards' JSONs name different --ratio-of series; the ratios are of " + ratioOf +
            " (give --ratio-of to choose)");
    if (!baselineGiven && seen.baseline == "-")
        say("bench merge: note: the shards' JSONs name different baselines; the ratios use the default one (give "
            "--baseline to choose)");
    BenchBaseline baseline = chooseBaseline(all, baselineSpec);
    baseline.series = ratioOf;
    // A shard runs whole groups along its run's baseline axis, so each ratio
    // compares frames of one process; along another axis they come from
    // different shards (other processes, maybe other machines).
    const std::string shardAxis = inherited(seen.baseline) ? seen.baseline.substr(0, seen.baseline.find('=')) : "";
    if (seen.shardCount > 1 && !shardAxis.empty() && !baseline.axis.empty() && baseline.axis != shardAxis)
        say("bench merge: warning: the shards were grouped along " + shardAxis + ", the ratios are along " +
            baseline.axis + ": they compare configurations measured by different shards (other processes, maybe "
            "other machines)");
    if (!hasSeries(all, ratioOf)) {
        std::set<std::string> names;
        for (const auto& sample : all.samples) names.insert(sample.series);
        std::string list;
        for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
        throw Error(std::string("--ratio-of") + (ratioOfGiven ? "" : " (from the shards' JSONs)") +
                    ": no configuration of these shards has samples of '" + ratioOf + "' (" + list +
                    "); give --ratio-of frame or a pass they ran");
    }
    return baseline;
}

}  // namespace

BenchMerged mergeBenchShards(const std::vector<std::string>& inputs, const std::optional<std::string>& baselineGiven,
                             const std::optional<std::string>& ratioOfGiven,
                             const std::function<void(const std::string&)>& say) {
    ShardsSeen seen;
    std::vector<BenchResults> parts;
    for (const auto& in : inputs) parts.push_back(readShard(in, seen));
    BenchResults all = BenchResults::merge(std::move(parts), inputs);
    if (all.configs.empty())
        throw Error("bench merge: the inputs hold no configuration (empty shards: more shards than the grid's "
                    "comparison groups)");
    warnMissingShards(seen, inputs.size(), say);
    all.machine = seen.machine;
    if (!seen.machineNote.empty()) all.machine.emplace_back("note", seen.machineNote);
    all.settings.clear();
    for (const auto& [k, v] : seen.settings)
        if (k != "shard" && k != "seconds") all.settings.emplace_back(k, v);
    std::string from;
    for (const auto& in : inputs) from += (from.empty() ? "" : " ") + in;
    all.settings.emplace_back("merged_from", from);
    BenchBaseline baseline = mergedBaseline(all, seen, baselineGiven, ratioOfGiven, say);
    return {std::move(all), std::move(baseline)};
}

}  // namespace dw

#pragma once
// The options `bench` and `tradeoff` share, read, checked and explained in one
// place: --sweep, --exclude, --frames/--warmup/--block, --resamples,
// --orbit/--walkthrough, --shard, --csv/--record/--plot/--plot-size, --quiet,
// and their `merge` subcommands' --out/--record/--plot/--plot-size and shards.
// --record FILE is the run's experiment record (docs/records.md); --json FILE
// is the same option under its older name (both given must name one file).
// What differs between the two commands (the file stem, the default frame
// count, whether a plot is drawn without --plot, the plot's size, what a
// shard holds) is a SweepCommand. Errors: UsageError naming the flag (exit
// 2), FileError for an output that could not be written. docs/bench.md and
// docs/tradeoffs.md describe the options.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "headless/CommandLine.h"
#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/GridExclusion.h"

namespace dw {

// What the shared options mean in one command.
struct SweepCommand {
    std::string name;                   // "bench": the default files' stem, the messages' prefix, "NAME merge"
    int frames = 10;                    // --frames' default
    std::string plotSize = "800x500";   // --plot-size's default, WxH px
    bool plotByDefault = false;         // a plot NAME.png without --plot (tradeoff), or only with --plot (bench)
    std::string plotWhat;               // the --plot help line: what the plot shows and which script draws it
    std::string sweepWhat;              // the --sweep help line: what an axis may name
    std::string shardWhat;              // the --shard help line: which part of the grid shard i runs
    std::string camerasWhat;            // the --orbit help line: how several cameras enter the table
    std::string filesWhat;              // the --csv/--json help line: what the two files hold
};

struct SweepOptions {
    std::vector<BenchKnobAxis> sweeps;  // --sweep, in the order given; a knob at most once
    GridExclusion exclusion;            // --exclude
    std::vector<std::string> excludes;  // the --exclude texts as given (for records)
    int frames = 10, warmup = 1, block = 1;
    int resamples = 2000;
    int orbit = 0;  // --orbit N; 0: none
    bool walkthrough = false;
    BenchShard shard;
    std::string csv, json;           // NAME[-shard-I-of-N].csv/.json unless given; json: the record
    std::string jsonFlag = "--json";  // the flag that named it: --record, or --json (its older name)
    std::optional<std::string> plot;  // set when plotByDefault, unless --plot none
    int plotWidth = 0, plotHeight = 0;
    bool quiet = false;

    // Declares and reads every shared flag of `cl` (before cl.finish()).
    static SweepOptions read(CommandLine& cl, const SweepCommand& c);
    // "-shard-I-of-N", empty for the whole grid.
    std::string shardSuffix() const;
    // "I/N".
    std::string shardText() const;
    // Before the run, so a long run is never lost to a bad path: the outputs
    // distinct from each other and from `inputs`, the plot a .png of at least
    // 50x50, every output writable.
    void checkOutputs(const SweepCommand& c, const CommandLine::NamedFiles& inputs) const;

    // --resamples N (100..1e6, default 2000): for a run and for a merge.
    static int readResamples(CommandLine& cl);
    // --size: WxH, or (several) a comma list of distinct sizes.
    static std::vector<std::pair<int, int>> readSizes(CommandLine& cl, bool several);
    // The shared options' help lines, for the command's usage text.
    static std::string help(const SweepCommand& c);
};

// NAME merge SHARD... --out ALL.csv [--json FILE] [--plot FILE.png] [--plot-size WxH].
struct SweepMergeOptions {
    std::vector<std::string> inputs;  // the shards, as given
    std::optional<std::string> out, json, plot;  // json: the merged record (--record or --json)
    std::string jsonFlag = "--json";
    int plotWidth = 0, plotHeight = 0;

    // Declares and reads the flags (before cl.finish()).
    static SweepMergeOptions read(CommandLine& cl, const SweepCommand& c);
    // After cl.finish(): the shards (cl.positional()) given, --out given,
    // the outputs distinct from each other, from the shards and from
    // `moreReads` (files merging also reads), the plot a .png of at least
    // 50x50, every output writable.
    void check(const CommandLine& cl, const SweepCommand& c, const CommandLine::NamedFiles& moreReads = {});
    static std::string help(const SweepCommand& c);
};

}  // namespace dw

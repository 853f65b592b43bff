#pragma once
// bench merge: the shards of one grid (their CSVs, and the JSON beside each
// when there is one) joined back into the grid they came from, checked to be
// of one run (the same command apart from where its files went), whole (every
// configuration with the frames its JSON says) and told which shards are
// missing; the baseline and ratio series taken from the shards' JSONs unless
// given. Reads: the CSVs and JSONs (JsonGuard). Writes: nothing (the caller
// prints the tables and writes the files). Needs no GL.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "renderer/bench/BenchResults.h"
#include "renderer/bench/BenchSummary.h"

namespace dw {

struct BenchMerged {
    BenchResults results;   // machines and settings from the first shard's JSON, "merged_from" added
    BenchBaseline baseline; // with the series the ratios compare
};

// Throws FileError naming a shard that is cut short, of another run or of a
// different shard count; Error for clashing configurations, an empty merge,
// or a --ratio-of series no shard has. `say` gets each warning or note line.
BenchMerged mergeBenchShards(const std::vector<std::string>& inputs, const std::optional<std::string>& baselineGiven,
                             const std::optional<std::string>& ratioOfGiven,
                             const std::function<void(const std::string&)>& say);

// An argument as a POSIX shell reads it back (bench writes its command so).
std::string shellQuoted(const std::string& arg);
// The run a shard's JSON describes: its command without what does not change
// the grid (runOf's comment says which), the options in a canonical order.
std::string benchRunOf(const std::string& command);

}  // namespace dw

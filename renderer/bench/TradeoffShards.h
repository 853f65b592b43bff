#pragma once
// Whether the inputs of `tradeoff merge` are shards of one run, as `bench
// merge` checks its shards (BenchMerge). Each input is described by the
// fields its CSV rows hold and, when its record is at hand (the input is the
// record, or a record sits beside the CSV as <name>.json), the fields of the
// record's grid:
//   metric, buffer   the metrics / buffers of its rows (or --metric, --buffer)
//   axes             the swept axes' names (CSV header, or the record's grid)
//   cameras          the cameras its rows name ("all" left out), or --orbit
//                    / --walkthrough from the record
//   against          --against ("reference" or knob=value,...)
//   size             the render size, WxH
//   grid             the swept values, --exclude and the --knobs centre
// A field is compared only between inputs that both hold it. Needs no GL.
#include <string>
#include <utility>
#include <vector>

namespace dw {

struct TradeoffShardInput {
    std::string name;  // the file, as given
    std::vector<std::pair<std::string, std::string>> fields;  // (field, value) as above
    std::string shard;  // "i/n" from its record; "" when unknown
};

class TradeoffShards {
public:
    // Throws FileError naming the later input, the earlier one and the field
    // ("comes from another tradeoff run than A (metric 'rms' against
    // 'flip') ..."), or when two inputs are shards of different counts.
    // Returns warnings: shards of the run that are not among the inputs
    // ("shard(s) 1 of 3 are not among the inputs; ...").
    static std::vector<std::string> check(const std::vector<TradeoffShardInput>& inputs);
};

}  // namespace dw

#include "renderer/bench/TradeoffShards.h"

#include <algorithm>

#include "renderer/Error.h"
#include "renderer/bench/BenchGrid.h"

namespace dw {

std::vector<std::string> TradeoffShards::check(const std::vector<TradeoffShardInput>& inputs) {
    // Each field's first value and the input it came from.
    std::vector<std::pair<std::string, std::pair<std::string, std::string>>> first;
    int shardCount = 0;
    std::string shardCountFrom;
    std::vector<int> shardIndices;
    for (const auto& in : inputs) {
        for (const auto& [field, value] : in.fields) {
            auto it = std::find_if(first.begin(), first.end(), [&](const auto& f) { return f.first == field; });
            if (it == first.end()) {
                first.push_back({field, {value, in.name}});
            } else if (it->second.first != value) {
                throw FileError(in.name, "comes from another tradeoff run than " + it->second.second + " (" + field +
                                             " '" + value + "' against '" + it->second.first +
                                             "'): shards of different runs do not merge");
            }
        }
        if (in.shard.empty()) continue;
        BenchShard sh;
        try {
            sh = BenchShard::parse(in.shard);
        } catch (const Error&) {
            throw FileError(in.name, "its shard '" + in.shard + "' is not i/n");
        }
        if (shardCount != 0 && sh.count != shardCount)
            throw FileError(in.name, "is shard " + in.shard + ", " + shardCountFrom + " is of " +
                                         std::to_string(shardCount) + " shards: not shards of one run");
        if (shardCount == 0) shardCountFrom = in.name;
        shardCount = sh.count;
        shardIndices.push_back(sh.index);
    }
    std::vector<std::string> warnings;
    if (shardCount > 1 && shardIndices.size() == inputs.size()) {
        std::string missing;
        for (int i = 0; i < shardCount; ++i)
            if (std::find(shardIndices.begin(), shardIndices.end(), i) == shardIndices.end())
                missing += (missing.empty() ? "" : ", ") + std::to_string(i);
        if (!missing.empty())
            warnings.push_back("shard(s) " + missing + " of " + std::to_string(shardCount) +
                               " are not among the inputs; their points are missing from the table");
    } else if (shardCount > 1 && inputs.size() < static_cast<size_t>(shardCount)) {
        warnings.push_back(std::to_string(inputs.size()) + " input(s) of a run of " + std::to_string(shardCount) +
                           " shards (" + std::to_string(inputs.size() - shardIndices.size()) +
                           " without a record beside them to say which shard they are): some shards are missing "
                           "from the table");
    }
    return warnings;
}

}  // namespace dw

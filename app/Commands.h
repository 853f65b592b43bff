#pragma once
#include <string>
// The subcommands of deferred-workbench, as one table: main() dispatches on
// it and prints the usage from it. A new subcommand is one function (its own
// <Name>Command.cpp, returning the exit code) and one line in kCommands.
#include <span>

namespace dw {

int runGuiCommand(int argc, char** argv);
int runRenderCommand(int argc, char** argv);
int runListCommand(int argc, char** argv);
int runBenchCommand(int argc, char** argv);
int runReferenceCommand(int argc, char** argv);
int runCompareCommand(int argc, char** argv);
int runReplayCommand(int argc, char** argv);
int runTradeoffCommand(int argc, char** argv);
// tradeoff --attribute (app/TradeoffAttribute.cpp): where one view's error comes from.
int runTradeoffAttribute(int argc, char** argv);
// tradeoff --search (app/TradeoffSearch.cpp): coordinate descent to the least error under the budget.
struct TradeoffStudyOptions;
struct TradeoffOptions;
struct SweepOptions;
int runTradeoffSearch(const TradeoffStudyOptions& s, const TradeoffOptions& o, const SweepOptions& so,
                      const std::string& command);

struct Command {
    const char* name;
    const char* synopsis;  // the arguments, as the usage line shows them
    const char* summary;   // one line: what it does
    // argv[1] is the command's name (or, for the default command, absent or
    // its first flag); each reads its own flags from the right index.
    int (*run)(int argc, char** argv);
};

// The first entry runs when the first argument is a flag or there is none.
inline constexpr Command kCommands[] = {
    {"gui", "[--scene S] [--preset P] [--set k=v]...", "open the workbench window (the default)", runGuiCommand},
    {"render", "--scene S --out FILE [...]", "render one buffer headless to .png/.exr; time the passes", runRenderCommand},
    {"bench", "--sweep k=a,b --lights N,.. [...]", "time configurations side by side (bench merge: join shards)", runBenchCommand},
    {"reference", "--scene S --out FILE [...]", "the CPU ground truth of a view (Embree, double precision)", runReferenceCommand},
    {"tradeoff", "--sweep k=a,b | --presets A,B [...]", "GPU ms against error per setting, and the Pareto front (tradeoff merge: join shards)", runTradeoffCommand},
    {"compare", "A B | --a k=v --b k=v [...]", "error of one image against another: statistics, SSIM, FLIP, gates", runCompareCommand},
    {"replay", "RECORD.json [--record FILE]", "restore an experiment record, measure again, say what changed", runReplayCommand},
    {"list", "scenes|buffers|knobs|passes|presets", "the scenes, buffers, knobs, passes or presets there are", runListCommand},
};

inline std::span<const Command> commands() { return kCommands; }

}  // namespace dw

#pragma once
// A small argument reader for the subcommands: --flag value, --flag=value,
// repeated flags, and positional words. Usage errors throw UsageError.
// Positional words keep their order on the command line whatever flags stand
// between them: a bare flag (flag()) that took the next word as its value
// gives it back at the place it stood, not at the end (`compare --hdr REF
// TEST` kept TEST as the reference otherwise).
#include <optional>
#include <string>
#include <vector>

#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/RunConfig.h"

namespace dw {

class UsageError : public Error {
public:
    using Error::Error;
};

class CommandLine {
public:
    // `command` names the command for the numeric options' table
    // (renderer/OptionLimits.h): "render", "bench merge", ...
    CommandLine(int argc, char** argv, int first, std::string command);
    // Declares a flag that takes a value; returns the last one given.
    std::optional<std::string> value(const std::string& flag);
    std::vector<std::string> values(const std::string& flag);
    // Declares a bare flag: a word it took as its value is a positional word
    // again, in its place; --flag=value is a UsageError (it takes no value).
    // Declare every bare flag before reading positional() (std::logic_error otherwise).
    bool flag(const std::string& flag);
    // The positional words in their order on the command line.
    std::vector<std::string> positional() const;
    // The flags of every command that renders: --scene, --preset (read here:
    // a missing or broken preset throws), --set. Size and frame counts differ
    // per command; checking against the knobs is RunConfig::validate().
    RunConfig runConfig();
    // Throws UsageError for anything not consumed by value()/values()/flag().
    void finish(const std::string& command) const;

    // (what, path) pairs: what a command writes or reads, named as its messages say.
    using NamedFiles = std::vector<std::pair<std::string, std::string>>;
    // Throws UsageError when two of `writes` are the same file, or one is a
    // file of `reads`: the later write would replace the other (the same
    // path, or two names of one existing file). A device such as /dev/null
    // takes any number of writes.
    static void requireDistinctFiles(const NamedFiles& writes, const NamedFiles& reads = {});
    // The files a run configuration reads: its scene and its preset, where they are files.
    static NamedFiles inputFiles(const RunConfig& run);

    // Fails now (FileError) when `path` could not be written at the end of a
    // run: its folder is missing or read-only, it is a folder or a read-only
    // file, or the file system refuses a new file there. Leaves nothing
    // behind: a file it creates to find out is removed; `what` names it.
    static void requireWritable(const std::string& path, const std::string& what);
    // "a,b,c" -> {a, b, c}; an empty item is a UsageError naming `flag`.
    static std::vector<std::string> parseList(const std::string& flag, const std::string& text);

    // The numeric options, each read through its entry in
    // limits::kNumericOptions under this command's name (std::logic_error
    // when it has none: every numeric option is declared there with its
    // range). A value of the wrong form or outside the range is a
    // UsageError of one line naming the flag, its range and what was given.
    std::optional<int> whole(const std::string& flag);
    int whole(const std::string& flag, int fallback) { return whole(flag).value_or(fallback); }
    std::optional<double> real(const std::string& flag);
    // WIDTHxHEIGHT.
    std::optional<std::pair<int, int>> size(const std::string& flag = "--size");
    // Comma lists; an item given twice is a UsageError.
    std::vector<int> wholeList(const std::string& flag);
    std::vector<std::pair<int, int>> sizeList(const std::string& flag = "--size");
    // i/n -> (i, n), 0 <= i < n.
    std::optional<std::pair<int, int>> shard(const std::string& flag = "--shard");
    // The help lines of `command`'s numeric options and their ranges, from the table.
    static std::string rangesHelp(const std::string& command);

private:
    const NumericOption& numeric(const std::string& flag, OptionForm form) const;
    struct Arg {
        std::string name;
        std::optional<std::string> value;
        bool inlineValue = false;  // --flag=value: the value is the flag's own, never a positional word
        int valueIndex = -1;       // argv index of a value taken from the next word
        bool used = false;
    };
    std::string command_;
    std::vector<Arg> args_;
    std::vector<std::pair<int, std::string>> positional_;  // (argv index, word)
    mutable bool positionalRead_ = false;
};

}  // namespace dw

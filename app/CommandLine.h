#pragma once
// A small argument reader for the subcommands: --flag value, --flag=value,
// repeated flags, and positional words. Usage errors throw UsageError.
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
    CommandLine(int argc, char** argv, int first);
    // Declares a flag that takes a value; returns the last one given.
    std::optional<std::string> value(const std::string& flag);
    std::vector<std::string> values(const std::string& flag);
    bool flag(const std::string& flag);
    std::vector<std::string> positional() const { return positional_; }
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
    static int parseInt(const std::string& flag, const std::string& text, int min, int max);
    // "a,b,c" -> {a, b, c}; an empty item is a UsageError naming `flag`.
    static std::vector<std::string> parseList(const std::string& flag, const std::string& text);
    // "1280x720" -> (1280, 720); errors name `flag`.
    static std::pair<int, int> parseSize(const std::string& text, const std::string& flag = "--size");

private:
    struct Arg {
        std::string name;
        std::optional<std::string> value;
        bool used = false;
    };
    std::vector<Arg> args_;
    std::vector<std::string> positional_;
};

}  // namespace dw

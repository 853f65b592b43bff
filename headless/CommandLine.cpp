#include "headless/CommandLine.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <stdexcept>
#include <cstring>

#include <charconv>
#include <cstdio>
#include <filesystem>

#include "renderer/OptionText.h"
#include "renderer/bench/BenchGrid.h"

namespace dw {

CommandLine::CommandLine(int argc, char** argv, int first, std::string command) : command_(std::move(command)) {
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (a.rfind("--", 0) == 0 && a.size() > 2) {
            Arg arg;
            const auto eq = a.find('=');
            if (eq != std::string::npos) {
                arg.name = a.substr(0, eq);
                arg.value = a.substr(eq + 1);
                arg.inlineValue = true;
            } else {
                arg.name = a;
                // Takes the next word as its value unless that is another flag;
                // flag() gives it back in its place when the flag is bare.
                if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) {
                    arg.value = argv[++i];
                    arg.valueIndex = i;
                }
            }
            args_.push_back(arg);
        } else {
            positional_.emplace_back(i, a);
        }
    }
}

std::vector<std::string> CommandLine::positional() const {
    positionalRead_ = true;
    auto sorted = positional_;
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> words;
    for (auto& [index, word] : sorted) words.push_back(std::move(word));
    return words;
}

std::optional<std::string> CommandLine::value(const std::string& flag) {
    std::optional<std::string> v;
    for (auto& a : args_)
        if (a.name == flag) {
            if (!a.value) throw UsageError(flag + " needs a value");
            v = a.value;
            a.used = true;
        }
    return v;
}

std::vector<std::string> CommandLine::values(const std::string& flag) {
    std::vector<std::string> v;
    for (auto& a : args_)
        if (a.name == flag) {
            if (!a.value) throw UsageError(flag + " needs a value");
            v.push_back(*a.value);
            a.used = true;
        }
    return v;
}

bool CommandLine::flag(const std::string& flag) {
    bool seen = false;
    for (auto& a : args_)
        if (a.name == flag) {
            if (a.value && a.inlineValue) throw UsageError(flag + " takes no value, got '" + a.name + "=" + *a.value + "'");
            // A bare flag may have taken a positional word: give it back where it stood.
            if (a.value) {
                if (positionalRead_)
                    throw std::logic_error("CommandLine: " + flag + " declared after positional() was read");
                positional_.emplace_back(a.valueIndex, *a.value);
                a.value.reset();
            }
            a.used = true;
            seen = true;
        }
    return seen;
}

RunConfig CommandLine::runConfig() {
    RunConfig run;
    const std::optional<std::string> scene = value("--scene");
    const std::vector<std::string> presets = values("--preset");
    if (scene && scene->empty()) throw UsageError("--scene needs a built-in scene's name or a file, got an empty one");
    for (const auto& p : presets)
        if (p.empty()) throw UsageError("--preset needs a built-in preset's name or a file, got an empty one");
    run.scene = scene.value_or("");
    // Repeated --preset: each in the order given, a later one's knobs over an earlier one's.
    for (const auto& p : presets) run.addPreset(p);
    run.sets = values("--set");
    const std::optional<std::string> animation = value("--animation");
    if (animation && animation->empty())
        throw UsageError("--animation needs a clip's name or index, or none, got an empty one");
    run.animation = animation.value_or("");
    return run;
}

void CommandLine::finish(const std::string& command) const {
    for (const auto& a : args_)
        if (!a.used) throw UsageError("'" + command + "' does not take " + a.name);
}

std::vector<std::string> CommandLine::parseList(const std::string& flag, const std::string& text) {
    try {
        return splitList(text, flag);
    } catch (const UsageError&) {
        throw;
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
}

namespace {

// As every refusal of an option's value words them (renderer/OptionText: Python and the window say the same).
std::string numberText(double v) { return optionNumberText(v); }
std::string rangeText(const NumericOption& o) { return optionRangeText(o); }

// One whole number of `o`'s range; `flag` names it in the message (e.g. "--size width").
int parseWhole(const NumericOption& o, const std::string& flag, const std::string& text, const std::string& given) {
    long long v = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc::result_out_of_range || (ec == std::errc() && p == text.data() + text.size() && !o.holds(static_cast<double>(v))))
        throw UsageError(flag + " must be " + rangeText(o) + ", got '" + given + "'");
    if (ec != std::errc() || p != text.data() + text.size() || text.empty())
        throw UsageError(flag + " expects " + rangeText(o) + ", got '" + given + "'");
    return static_cast<int>(v);
}

std::pair<int, int> parseSizeText(const NumericOption& o, const std::string& flag, const std::string& text) {
    const auto x = text.find('x');
    if (x == std::string::npos)
        throw UsageError(flag + " expects WIDTHxHEIGHT (e.g. 1280x720), each " + rangeText(o) + ", got '" + text + "'");
    return {parseWhole(o, flag + " width", text.substr(0, x), text), parseWhole(o, flag + " height", text.substr(x + 1), text)};
}

}  // namespace

const NumericOption& CommandLine::numeric(const std::string& flag, OptionForm form) const {
    const NumericOption* o = findNumericOption(command_, flag);
    if (!o || o->form != form)
        throw std::logic_error("CommandLine: " + command_ + " " + flag + " is not declared in limits::kNumericOptions as read");
    return *o;
}

std::optional<int> CommandLine::whole(const std::string& flag) {
    const NumericOption& o = numeric(flag, OptionForm::Whole);
    const auto text = value(flag);
    if (!text) return std::nullopt;
    return parseWhole(o, flag, *text, *text);
}

std::optional<double> CommandLine::real(const std::string& flag) {
    const NumericOption& o = numeric(flag, OptionForm::Real);
    const auto text = value(flag);
    if (!text) return std::nullopt;
    double v = 0;
    const auto [p, ec] = std::from_chars(text->data(), text->data() + text->size(), v);
    const bool parsed = !text->empty() && p == text->data() + text->size() &&
                        (ec == std::errc() || ec == std::errc::result_out_of_range);
    if (!parsed) throw UsageError(flag + " expects " + rangeText(o) + ", got '" + *text + "'");
    if (ec != std::errc() || !o.holds(v)) throw UsageError(flag + " must be " + rangeText(o) + ", got '" + *text + "'");
    return v;
}

std::optional<std::pair<int, int>> CommandLine::size(const std::string& flag) {
    const NumericOption& o = numeric(flag, OptionForm::Size);
    const auto text = value(flag);
    if (!text) return std::nullopt;
    return parseSizeText(o, flag, *text);
}

std::vector<int> CommandLine::wholeList(const std::string& flag) {
    const NumericOption& o = numeric(flag, OptionForm::WholeList);
    std::vector<int> values;
    const auto text = value(flag);
    if (!text) return values;
    for (const auto& item : parseList(flag, *text)) {
        const int v = parseWhole(o, flag, item, item);
        if (std::find(values.begin(), values.end(), v) != values.end())
            throw UsageError(flag + ": '" + item + "' is given twice");
        values.push_back(v);
    }
    return values;
}

std::vector<std::pair<int, int>> CommandLine::sizeList(const std::string& flag) {
    const NumericOption& o = numeric(flag, OptionForm::SizeList);
    std::vector<std::pair<int, int>> sizes;
    const auto text = value(flag);
    if (!text) return sizes;
    for (const auto& item : parseList(flag, *text)) {
        const auto size = parseSizeText(o, flag, item);
        if (std::find(sizes.begin(), sizes.end(), size) != sizes.end())
            throw UsageError(flag + ": '" + item + "' is given twice");
        sizes.push_back(size);
    }
    return sizes;
}

std::optional<std::pair<int, int>> CommandLine::shard(const std::string& flag) {
    const NumericOption& o = numeric(flag, OptionForm::Shard);
    const auto text = value(flag);
    if (!text) return std::nullopt;
    const auto slash = text->find('/');
    const std::string form = flag + " expects i/n with 0 <= i < n (e.g. 0/4), n " + rangeText(o) + ", got '" + *text + "'";
    if (slash == std::string::npos) throw UsageError(form);
    // One message for every way i/n is wrong: the form and both ranges in one line.
    try {
        const int n = parseWhole(o, flag + " n", text->substr(slash + 1), *text);
        const NumericOption index{o.command, o.flag, OptionForm::Whole, OptionRange{0, n - 1}, "shard index, below n"};
        return std::pair{parseWhole(index, flag + " i", text->substr(0, slash), *text), n};
    } catch (const UsageError&) {
        throw UsageError(form);
    }
}

std::string CommandLine::rangesHelp(const std::string& command) {
    std::string s;
    for (const NumericOption& o : limits::kNumericOptions) {
        if (o.command != command) continue;
        char line[160];
        const std::string range = o.minOpen ? "> " + numberText(o.min) + " .. " + numberText(o.max)
                                            : numberText(o.min) + " .. " + numberText(o.max);
        std::snprintf(line, sizeof line, "  %-14s %s%s (%s)\n", std::string(o.flag).c_str(), range.c_str(),
                      o.form == OptionForm::Size || o.form == OptionForm::SizeList ? " each of WxH"
                      : o.form == OptionForm::Shard                                 ? " for n of i/n"
                      : o.form == OptionForm::WholeList                             ? " each"
                                                                                    : "",
                      std::string(o.what).c_str());
        s += line;
    }
    return s.empty() ? s : command + "'s numeric options (outside its range, or not a number: a usage error naming it):\n" + s;
}

void CommandLine::requireDistinctFiles(const NamedFiles& writes, const NamedFiles& reads) {
    namespace fs = std::filesystem;
    // The same path, or two names of one existing file (a hard link).
    auto same = [](const std::string& a, const std::string& b) {
        std::error_code ec;
        if (a.empty() || b.empty()) return false;
        for (const std::string& p : {a, b})
            if (fs::exists(p, ec) && !fs::is_regular_file(p, ec)) return false;
        if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
        const fs::path ka = fs::weakly_canonical(fs::absolute(a, ec), ec);
        if (ec) return false;
        const fs::path kb = fs::weakly_canonical(fs::absolute(b, ec), ec);
        return !ec && ka == kb;
    };
    auto refuse = [](const std::string& a, const std::string& b, const std::string& path) {
        throw UsageError(a + " and " + b + " are the same file (" + path + "): one would replace the other");
    };
    for (std::size_t i = 0; i < writes.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j)
            if (same(writes[j].second, writes[i].second)) refuse(writes[j].first, writes[i].first, writes[i].second);
        for (const auto& [what, path] : reads)
            if (same(path, writes[i].second)) refuse(what, writes[i].first, writes[i].second);
    }
}

CommandLine::NamedFiles CommandLine::inputFiles(const RunConfig& run) {
    namespace fs = std::filesystem;
    NamedFiles files;
    std::error_code ec;
    const std::string scene = run.sceneSpec();
    if (fs::is_regular_file(scene, ec)) files.emplace_back("the scene", scene);
    for (const auto& p : run.presetSpecs())
        if (fs::is_regular_file(p, ec)) files.emplace_back("the preset", p);
    return files;
}

void CommandLine::requireWritable(const std::string& path, const std::string& what) {
    namespace fs = std::filesystem;
    if (path.empty()) throw UsageError("the " + what + " needs a file name, got an empty one");
    std::error_code ec;
    const fs::path p(path);
    if (p.filename().empty()) throw FileError(path, "cannot write the " + what + ": not a file name");
    if (fs::is_directory(p, ec)) throw FileError(path, "cannot write the " + what + ": it is a folder");
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) throw FileError(path, "cannot write the " + what + ": no folder " + dir.string());
    const bool exists = fs::exists(p, ec);
    if (!exists && fs::is_symlink(fs::symlink_status(p, ec)))
        throw FileError(path, "cannot write the " + what + ": it is a link to nothing");
    if (access((exists ? p : dir).c_str(), W_OK) != 0)
        throw FileError(path, "cannot write the " + what + ": " + (exists ? "the file" : "its folder") + " is not writable");
    if (exists && !fs::is_regular_file(p, ec)) return;  // a device or a pipe: opening it could block or consume
    const int fd = exists ? open(p.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC | O_NONBLOCK)
                          : open(p.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw FileError(path, "cannot write the " + what + ": " + std::strerror(errno));
    close(fd);
    if (!exists) unlink(p.c_str());
}

}  // namespace dw

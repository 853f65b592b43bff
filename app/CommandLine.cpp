#include "app/CommandLine.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <charconv>
#include <filesystem>

#include "renderer/bench/BenchGrid.h"

namespace dw {

CommandLine::CommandLine(int argc, char** argv, int first) {
    for (int i = first; i < argc; ++i) {
        std::string a = argv[i];
        if (a.rfind("--", 0) == 0 && a.size() > 2) {
            Arg arg;
            const auto eq = a.find('=');
            if (eq != std::string::npos) {
                arg.name = a.substr(0, eq);
                arg.value = a.substr(eq + 1);
            } else {
                arg.name = a;
                // Takes the next word as its value unless that is another flag.
                if (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) arg.value = argv[++i];
            }
            args_.push_back(arg);
        } else {
            positional_.push_back(a);
        }
    }
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
            // A bare flag may have swallowed a positional word: give it back.
            if (a.value) {
                positional_.push_back(*a.value);
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

int CommandLine::parseInt(const std::string& flag, const std::string& text, int min, int max) {
    int v = 0;
    auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size())
        throw UsageError(flag + " expects a whole number, got '" + text + "'");
    if (v < min || v > max)
        throw UsageError(flag + " must be between " + std::to_string(min) + " and " + std::to_string(max));
    return v;
}

std::pair<int, int> CommandLine::parseSize(const std::string& text, const std::string& flag) {
    const auto x = text.find('x');
    if (x == std::string::npos) throw UsageError(flag + " expects WIDTHxHEIGHT (e.g. 1280x720), got '" + text + "'");
    return {parseInt(flag + " width", text.substr(0, x), limits::kSize.min, limits::kSize.max),
            parseInt(flag + " height", text.substr(x + 1), limits::kSize.min, limits::kSize.max)};
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

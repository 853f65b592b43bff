#include "headless/PlotScript.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "headless/CommandLine.h"

extern char** environ;

namespace dw {

namespace fs = std::filesystem;

namespace {

fs::path locate(const std::string& script, const std::string& env) {
    std::vector<fs::path> candidates;
    if (const char* e = std::getenv(env.c_str())) candidates.emplace_back(e);
#ifdef DW_SOURCE_SCRIPTS_DIR
    candidates.push_back(fs::path(DW_SOURCE_SCRIPTS_DIR) / script);
#endif
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back(exe.parent_path() / script);
        candidates.push_back(exe.parent_path().parent_path() / "share/deferred-workbench" / script);
    }
    for (const auto& c : candidates)
        if (fs::is_regular_file(c, ec)) return c;
    return {};
}

// Runs `python args...`; its exit code, or -1 when it could not start.
int runPython(const std::string& python, std::vector<std::string> args) {
    args.insert(args.begin(), python);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(nullptr);
    pid_t pid = 0;
    if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return -1;
    if (!WIFEXITED(status)) return -1;
    return WEXITSTATUS(status) == 127 ? -1 : WEXITSTATUS(status);
}

}  // namespace

bool runPlotScript(const std::string& script, const std::string& scriptEnv, const std::vector<std::string>& args,
                   const std::string& who) {
    const fs::path path = locate(script, scriptEnv);
    if (path.empty()) {
        std::fprintf(stderr, "%s: cannot find %s (set %s to scripts/%s)\n", who.c_str(), script.c_str(), scriptEnv.c_str(),
                     script.c_str());
        return false;
    }
    std::vector<std::string> pythons;
    if (const char* env = std::getenv("DW_PYTHON")) pythons.emplace_back(env);
    pythons.emplace_back("/usr/bin/python3");
    pythons.emplace_back("python3");
    std::vector<std::string> full = {path.string()};
    full.insert(full.end(), args.begin(), args.end());
    bool anyPython = false;
    for (const auto& python : pythons) {
        const int code = runPython(python, full);
        if (code == 0) return true;
        if (code == 3 || code == -1) {  // no matplotlib there, or no such interpreter: try the next
            anyPython = anyPython || code == 3;
            continue;
        }
        std::fprintf(stderr, "%s: the plot script failed (%s, exit %d); the CSV and JSON are written\n", who.c_str(),
                     path.c_str(), code);
        return false;
    }
    std::fprintf(stderr, "%s: %s; the CSV and JSON are written\n", who.c_str(),
                 anyPython ? "no python3 here has matplotlib (Debian: apt-get install python3-matplotlib, or "
                             "scripts/setup-deps.sh --tests)"
                           : "cannot run python3 for the plot (Debian: apt-get install python3-matplotlib)");
    return false;
}

void checkPlotFile(const std::string& plot, int width, int height) {
    std::string ext = fs::path(plot).extension().string();
    for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".png") throw UsageError("--plot writes a PNG; give a file name ending in .png, got '" + plot + "'");
    if (width < 50 || height < 50)
        throw UsageError("--plot-size expects at least 50x50, got " + std::to_string(width) + "x" + std::to_string(height));
}

}  // namespace dw

// deferred-workbench: the workbench window (default) and the headless subcommands,
// dispatched through the table in app/Commands.h.
#include <algorithm>
#include <cstdio>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "app/Commands.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/gl/ShaderSource.h"

namespace {

void printUsage(std::FILE* to) {
    std::vector<std::pair<std::string, std::string>> lines;
    for (const dw::Command& c : dw::commands())
        lines.emplace_back(std::string("deferred-workbench ") + c.name + " " + c.synopsis, c.summary);
    lines.emplace_back("deferred-workbench help [COMMAND]", "this text, or a command's options");
    lines.emplace_back("deferred-workbench COMMAND --help", "a command's options");
    size_t width = 0;
    for (const auto& l : lines) width = std::max(width, l.first.size());
    std::fprintf(to, "Deferred Workbench: a workbench for real-time deferred shading.\n\nusage:\n");
    for (const auto& [call, summary] : lines)
        std::fprintf(to, "  %-*s  %s\n", static_cast<int>(width), call.c_str(), summary.c_str());
}

const dw::Command* findCommand(const std::string& name) {
    for (const dw::Command& c : dw::commands())
        if (name == c.name) return &c;
    return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string word = argc > 1 ? argv[1] : "";
    // Which command a usage error belongs to: its own help is the pointer, not every command's usage.
    const dw::Command* command = word.empty() || word.rfind("--", 0) == 0 ? &dw::commands().front() : findCommand(word);
    try {
        if (word == "--help" || word == "-h" || word == "help") {
            // "help render" is "render --help".
            if (word == "help" && argc > 2) {
                const dw::Command* c = findCommand(argv[2]);
                if (!c) throw dw::UsageError("unknown command '" + std::string(argv[2]) + "'");
                char help[] = "--help";
                char* args[] = {argv[0], argv[2], help, nullptr};
                return c->run(3, args);
            }
            printUsage(stdout);
            return 0;
        }
        if (word == "--version") {
            std::printf("deferred-workbench 0.1.0\n");
            return 0;
        }
        // No command, or flags only: the first command (the window).
        if (word.empty() || word.rfind("--", 0) == 0) return dw::commands().front().run(argc, argv);
        if (const dw::Command* c = findCommand(word)) return c->run(argc, argv);
        throw dw::UsageError("unknown command '" + word + "'");
    } catch (const dw::UsageError& e) {
        std::fprintf(stderr, "deferred-workbench: %s\n", e.what());
        if (command) std::fprintf(stderr, "(deferred-workbench help %s lists its options)\n", command->name);
        else printUsage(stderr);
        return 2;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "deferred-workbench: error: out of memory (a smaller --size, or fewer samples, needs less)\n");
        return 1;
    } catch (const dw::gl::ShaderError& e) {
        std::fprintf(stderr, "deferred-workbench: shader error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "deferred-workbench: error: %s\n", e.what());
        return 1;
    }
}

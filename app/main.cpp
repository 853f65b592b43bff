// deferred-workbench: the workbench window (default) and the headless subcommands.
#include <cstdio>
#include <cstring>
#include <string>

#include "app/CommandLine.h"
#include "app/Commands.h"
#include "renderer/Error.h"
#include "renderer/gl/ShaderSource.h"

namespace {

void printUsage() {
    std::printf(
        "Deferred Workbench: a workbench for real-time deferred shading.\n\n"
        "usage: deferred-workbench [gui] [--scene S] [--preset P]     open the workbench window\n"
        "       deferred-workbench render --scene S --out FILE [...]  render a buffer to .png/.exr\n"
        "       deferred-workbench list scenes|buffers|knobs|passes|presets\n"
        "       deferred-workbench <command> --help\n");
}

}  // namespace

int main(int argc, char** argv) {
    const std::string cmd = argc > 1 ? argv[1] : "gui";
    try {
        if (cmd == "render") return dw::runRenderCommand(argc, argv);
        if (cmd == "list") return dw::runListCommand(argc, argv);
        if (cmd == "--help" || cmd == "-h" || cmd == "help") {
            printUsage();
            return 0;
        }
        if (cmd == "--version") {
            std::printf("deferred-workbench 0.1.0\n");
            return 0;
        }
        if (cmd == "gui" || cmd.rfind("--", 0) == 0) return dw::runGuiCommand(argc, argv);
        throw dw::UsageError("unknown command '" + cmd + "'");
    } catch (const dw::UsageError& e) {
        std::fprintf(stderr, "deferred-workbench: %s\n", e.what());
        printUsage();
        return 2;
    } catch (const dw::gl::ShaderError& e) {
        std::fprintf(stderr, "deferred-workbench: shader error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "deferred-workbench: error: %s\n", e.what());
        return 1;
    }
}

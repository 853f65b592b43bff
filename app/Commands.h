#pragma once
// The subcommands of deferred-workbench. Each returns the process exit code.
namespace dw {

int runRenderCommand(int argc, char** argv);
int runListCommand(int argc, char** argv);
int runGuiCommand(int argc, char** argv);

}  // namespace dw

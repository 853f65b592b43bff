#pragma once
// The plots of bench and tradeoff: a matplotlib script of scripts/ run on
// the command's CSV with Debian's python3 (python3-matplotlib). One place
// that finds the script and an interpreter that has matplotlib.
#include <string>
#include <vector>

namespace dw {

// Runs scripts/<script> with `args` (after the script's path). The script is
// looked for at $<scriptEnv>, the source tree's scripts/, beside the binary,
// then in ../share/deferred-workbench. Interpreters tried: $DW_PYTHON,
// /usr/bin/python3, python3 on the PATH; the script exits 3 when matplotlib
// is missing. False, after saying why on stderr (prefixed "`who`: "), when
// no plot was drawn.
bool runPlotScript(const std::string& script, const std::string& scriptEnv, const std::vector<std::string>& args,
                   const std::string& who);

// A plot bench and tradeoff can draw: `plot` names a .png (the scripts write
// PNG only; any case), at least 50x50 pixels (the scripts' least). Throws
// UsageError naming --plot or --plot-size.
void checkPlotFile(const std::string& plot, int width, int height);

}  // namespace dw

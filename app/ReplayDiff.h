#pragma once
// deferred-workbench replay --diff A.json B.json: what differs between two
// experiment records, measuring nothing, in replay's words (app/ReplayReport):
// each record's own sha256s ("record edited"), the command, the scene and its
// files (a built-in's content), the shader files, knobs, seeds, camera,
// camera path, size, frames, warm-up, buffer, grid, build, GL and host
// fields, then "inputs changed (N): ..." and B's results against A's as
// replay compares a new run with a record: timings and the image, bench's
// configurations, tradeoff's rows, and the verdict. docs/records.md.
#include <string>

namespace dw {

// Exit 0: the results are the same (replay's rules: the image identical; for
// bench every configuration in both, lights per pixel equal, no timing ratio
// sure to lie outside [0.8, 1.25]; for tradeoff every row in both with an
// equal error, no frame time moved and the pick the same); 1: they differ (or the records are of
// different commands); 2: a record is refused (the reason on stderr).
int runReplayDiff(const std::string& pathA, const std::string& pathB);

}  // namespace dw

#pragma once
// `compare --sequence REFERENCE_PATTERN TEST_PATTERN`: two image sequences,
// frame by frame (FLIP and RMS, each with its tile-bootstrap interval, and
// their means over frames with a bootstrap over frames) and over time (the
// temporal error, renderer/metrics/TemporalError.h, with its interval over
// frame pairs). A pattern names frame t by one printf integer conversion:
// "frames/ref%03d.exr" (%d, %Nd or %0Nd). The frames are t = first, first +
// 1, ... while the reference's file exists, where first is 0, or 1 when the
// reference has no frame 0; the test must have exactly those.
#include <string>

namespace dw {

struct SequenceCompareOptions {
    std::string referencePattern, testPattern;
    bool forceHdr = false, forceLdr = false;  // else HDR by the files' extension (.exr, .hdr, .pfm)
};

// Prints the report; returns compare's exit code: 0 measured, 3 the frames
// differ in size, channels or kind, or the sequences in length (one line naming
// the file), 4 a frame cannot be read (one line naming the file). Throws
// UsageError for a pattern without exactly one integer conversion or with no
// frame; Error for a non-finite pixel (naming the frame's file).
int compareSequences(const SequenceCompareOptions& options);

// The file of frame `t` of `pattern`; throws UsageError for a pattern without
// exactly one integer conversion (%d, %Nd, %0Nd).
std::string sequenceFrameName(const std::string& pattern, int t);

}  // namespace dw

#include "app/CompareSequence.h"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "app/CompareInput.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/bench/ImageError.h"
#include "renderer/io/ImageIO.h"
#include "renderer/metrics/FinitePixels.h"
#include "renderer/metrics/TemporalError.h"

namespace dw {

namespace {

constexpr int kExitShape = 3, kExitFile = 4;

struct Sequence {
    std::vector<std::string> files;
    std::vector<FloatImage> frames;
};

// Frame t's file exists (a file, not a folder).
bool frameExists(const std::string& pattern, int t) {
    std::error_code ec;
    return std::filesystem::is_regular_file(sequenceFrameName(pattern, t), ec);
}

// The reference's frames: from 0 (or 1) while its files exist.
std::vector<std::string> referenceFiles(const std::string& pattern) {
    const int first = frameExists(pattern, 0) ? 0 : 1;
    std::vector<std::string> files;
    for (int t = first; frameExists(pattern, t); ++t) files.push_back(sequenceFrameName(pattern, t));
    if (files.empty())
        throw UsageError("--sequence: no reference frame: neither " + sequenceFrameName(pattern, 0) + " nor " +
                         sequenceFrameName(pattern, 1) + " exists");
    return files;
}

// The line naming what does not match, or "" when the test has exactly the reference's frames.
std::string unmatchedFrame(const std::string& refPattern, const std::string& testPattern, int first, int count) {
    if (first == 1 && frameExists(testPattern, 0))
        return "the test has frame 0 (" + sequenceFrameName(testPattern, 0) + ") and the reference does not (" +
               sequenceFrameName(refPattern, 0) + "): the reference begins at 1";
    for (int t = first; t < first + count; ++t)
        if (!frameExists(testPattern, t))
            return "test frame " + std::to_string(t) + " is missing: " + sequenceFrameName(testPattern, t) +
                   " does not exist (the reference has " + sequenceFrameName(refPattern, t) + ")";
    const int next = first + count;
    if (frameExists(testPattern, next))
        return "the test has more frames than the reference: " + sequenceFrameName(testPattern, next) +
               " exists, the reference's " + sequenceFrameName(refPattern, next) + " does not";
    return {};
}

std::string shapeOf(const FloatImage& f) {
    return std::to_string(f.width) + "x" + std::to_string(f.height) + "x" + std::to_string(f.channels);
}

// Reads every frame; the first one of another shape than reference frame 0 is named.
std::string loadFrames(Sequence& ref, Sequence& test) {
    for (Sequence* s : {&ref, &test})
        for (const std::string& file : s->files) {
            CompareInputs::checkMemory(file);
            s->frames.push_back(loadImageFloat(file));
            const FloatImage& f = s->frames.back();
            const FloatImage& first = ref.frames.front();
            if (f.width != first.width || f.height != first.height || f.channels != first.channels)
                return "the frames differ in size or channels: " + file + " is " + shapeOf(f) + ", " +
                       ref.files.front() + " is " + shapeOf(first) + " (width x height x channels)";
            FinitePixels::require(f, file);
        }
    return {};
}

// Every frame of one kind: HDR (.exr, .hdr, .pfm) or LDR; "" or the line naming the odd one.
std::string kindOf(const Sequence& ref, const Sequence& test, bool& hdr) {
    hdr = CompareInputs::isHdrFile(ref.files.front());
    for (const Sequence* s : {&ref, &test})
        for (const std::string& file : s->files)
            if (CompareInputs::isHdrFile(file) != hdr)
                return file + " is " + (hdr ? "LDR" : "HDR") + " and " + ref.files.front() + " is " +
                       (hdr ? "HDR" : "LDR") + ": compare needs both HDR or both LDR (--hdr or --ldr chooses)";
    return {};
}

void printFrames(const Sequence& ref, const Sequence& test, bool hdr, int first) {
    std::vector<double> flips, rmss;
    std::printf("  frame  FLIP [95%% interval]            RMS [95%% interval]\n");
    for (size_t t = 0; t < ref.frames.size(); ++t) {
        const ErrorEstimate flip = ImageError::measure(ref.frames[t], test.frames[t], "flip", hdr);
        const ErrorEstimate rms = ImageError::measure(ref.frames[t], test.frames[t], "rms", hdr);
        std::printf("  %5d  %.6f [%.6f, %.6f]  %.6g [%.6g, %.6g]\n", first + static_cast<int>(t), flip.value, flip.low,
                    flip.high, rms.value, rms.low, rms.high);
        flips.push_back(flip.value);
        rmss.push_back(rms.value);
    }
    const ErrorEstimate flip = ImageError::meanOver(flips), rms = ImageError::meanOver(rmss);
    std::printf("  mean FLIP      %.6f [%.6f, %.6f] (%s; 95%% bootstrap over frames)\n", flip.value, flip.low,
                flip.high, hdr ? "HDR-FLIP" : "LDR-FLIP");
    std::printf("  mean RMS       %.6g [%.6g, %.6g] (95%% bootstrap over frames)\n", rms.value, rms.low, rms.high);
}

void printTemporal(const TemporalErrorResult& r, int first) {
    std::printf("  frame pair  temporal error (mean |d_t - r_t| of luminance)\n");
    for (size_t t = 0; t < r.pairs.size(); ++t)
        std::printf("  %4d->%-4d  %.6g\n", first + static_cast<int>(t), first + static_cast<int>(t) + 1, r.pairs[t]);
    std::printf("  temporal error %.6g [%.6g, %.6g] (mean over %zu frame pairs; 95%% bootstrap over pairs; "
                "docs/metrics.md)\n",
                r.mean, r.interval.low, r.interval.high, r.pairs.size());
}

}  // namespace

std::string sequenceFrameName(const std::string& pattern, int t) {
    const size_t pct = pattern.find('%');
    size_t end = pct == std::string::npos ? pct : pattern.find_first_not_of("0123456789", pct + 1);
    if (pct == std::string::npos || end == std::string::npos || pattern[end] != 'd' ||
        pattern.find('%', end + 1) != std::string::npos)
        throw UsageError("a sequence's file pattern (compare --sequence, render --out-sequence) names frame t by "
                         "one integer conversion (%d, %4d, %03d), got '" + pattern + "'");
    const std::string width = pattern.substr(pct + 1, end - pct - 1);  // "", "4" or "03"
    if (width.size() > 2) throw UsageError("sequence pattern: '%" + width + "d' in '" + pattern + "' is too wide");
    std::string number = std::to_string(t);
    const size_t w = width.empty() ? 0 : static_cast<size_t>(std::stoi(width));
    if (number.size() < w) number.insert(0, w - number.size(), !width.empty() && width[0] == '0' ? '0' : ' ');
    return pattern.substr(0, pct) + number + pattern.substr(end + 1);
}

int compareSequences(const SequenceCompareOptions& o) {
    sequenceFrameName(o.testPattern, 0);  // a bad pattern fails before any file is read
    Sequence ref, test;
    ref.files = referenceFiles(o.referencePattern);
    const int first = frameExists(o.referencePattern, 0) ? 0 : 1;
    const int count = static_cast<int>(ref.files.size());
    if (count < 2) {
        std::fprintf(stderr, "deferred-workbench: %s: a sequence of 1 frame has no frame-to-frame change and no "
                     "interval over frames; give at least 2 frames\n", o.referencePattern.c_str());
        return kExitShape;
    }
    if (const std::string why = unmatchedFrame(o.referencePattern, o.testPattern, first, count); !why.empty()) {
        std::fprintf(stderr, "deferred-workbench: %s\n", why.c_str());
        return kExitShape;
    }
    for (int t = first; t < first + count; ++t) test.files.push_back(sequenceFrameName(o.testPattern, t));
    bool hdr = o.forceHdr;
    if (!o.forceHdr && !o.forceLdr) {
        if (const std::string why = kindOf(ref, test, hdr); !why.empty()) {
            std::fprintf(stderr, "deferred-workbench: %s\n", why.c_str());
            return kExitShape;
        }
    }
    try {
        if (const std::string why = loadFrames(ref, test); !why.empty()) {
            std::fprintf(stderr, "deferred-workbench: %s\n", why.c_str());
            return kExitShape;
        }
    } catch (const FileError& e) {
        std::fprintf(stderr, "deferred-workbench: cannot read %s\n", e.what());
        return kExitFile;
    }
    std::printf("compare --sequence: reference %s\n                    test      %s\n", o.referencePattern.c_str(),
                o.testPattern.c_str());
    std::printf("  frames %d..%d (%d), %s, %s\n", first, first + count - 1, count, shapeOf(ref.frames[0]).c_str(),
                hdr ? "HDR" : "LDR");
    printFrames(ref, test, hdr, first);
    printTemporal(TemporalError::measure(ref.frames, test.frames), first);
    return 0;
}

}  // namespace dw

// deferred-workbench compare: the error of one image against another (two
// files, or two renders of one scene with two knob sets), through the metrics
// of renderer/metrics/, gated the way OpenImageIO's idiff gates.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/CompareInput.h"
#include "app/CompareSequence.h"
#include "app/Commands.h"
#include "headless/CommandLine.h"
#include "renderer/Error.h"
#include "renderer/io/ImageIO.h"
#include "renderer/io/TextFile.h"
#include "renderer/metrics/ComparisonGates.h"
#include "renderer/metrics/ComparisonHeatMap.h"
#include "renderer/metrics/ComparisonMemory.h"
#include "renderer/metrics/HeatMap.h"
#include "renderer/metrics/ImageComparison.h"

namespace dw {

namespace {

// Exit codes (idiff's 0-4, then the workbench's own).
constexpr int kExitPass = 0, kExitWarn = 1, kExitFail = 2, kExitShape = 3, kExitFile = 4, kExitError = 5;

constexpr const char* kUsage =
    "usage: deferred-workbench compare REFERENCE TEST [options]\n"
    "       deferred-workbench compare --a k=v[,k=v...] --b k=v[,k=v...] [--scene S] [--preset P] [--set k=v]...\n"
    "                                  [--size WxH] [--buffer final|lbuffer|NAME] [--frames N] [options]\n"
    "       deferred-workbench compare --against reference [--b k=v[,k=v...]] [--scene S] [--preset P] [--set k=v]...\n"
    "                                  [--size WxH] [--buffer final|lbuffer|ao|ao.raw|shadow] [--ao-rays N] [options]\n"
    "       deferred-workbench compare --sequence REFERENCE_PATTERN TEST_PATTERN [--hdr|--ldr]\n"
    "  Two image files: EXR/HDR/PFM are HDR (linear radiance: HDR-FLIP, SSIM on v/(1+v));\n"
    "  anything else (PNG, JPEG, ...) LDR (display values: LDR-FLIP, SSIM as stored).\n"
    "  Two renders: the scene rendered twice with the same --scene/--preset/--set, then side A's\n"
    "  and side B's knobs (--a, --b: comma-separated knob=value, or repeat the flag; a side\n"
    "  without its flag renders the shared configuration alone); A is the\n"
    "  reference. --buffer final (default) compares the displayed image (LDR), any other buffer\n"
    "  its raw float values (HDR; lbuffer is the linear radiance). Default size 1280x720.\n"
    "  Against the reference: side A is the CPU ground truth (docs/reference.md) of the same\n"
    "  configuration with --b's knobs (the knobs that define the model are the render's), rendered\n"
    "  once and cached; final against its tone-mapped image (no bloom, DoF or anti-aliasing: set\n"
    "  them false, aa.method=none, on the render), lbuffer against its L-buffer, ao (= ao.filtered) or ao.raw against its ray-traced AO,\n"
    "  shadow (= lighting.shadow, the shadow factor) against its shadow rays\n"
    "  (--ao-rays, default 64).\n"
    "  Two sequences (--sequence): each pattern names frame t by one integer conversion\n"
    "  (frames/ref%03d.exr); the frames are 0, 1, ... (or 1, 2, ...) while the reference's exist,\n"
    "  and the test must have the same ones. Per frame FLIP and RMS with their intervals, their\n"
    "  means over frames, and the temporal error: the mean over frame pairs of mean |d_t - r_t|,\n"
    "  d_t and r_t the test's and the reference's frame-to-frame change of luminance\n"
    "  (docs/metrics.md, \"Temporal error\"), with a bootstrap interval over the pairs. A missing\n"
    "  or extra frame, or frames of another size, exit 3 naming the file; an unreadable one 4.\n"
    "options:\n"
    "  --error-map FILE.exr  per-pixel maps: absdiff.<channel>..., ssim (mean of the colour\n"
    "                      channels' SSIM), flip\n"
    "  --heat-map FILE.png   the FLIP map through the Turbo colour map, 0 (dark blue) to 1 (dark red);\n"
    "                      default with --error-map: beside it, FILE.png\n"
    "  --json FILE           every figure under fixed keys (docs/metrics.md)\n"
    "  --fail X, --warn X    per-channel |reference - test| thresholds (default 1e-6, as idiff)\n"
    "  --failpercent P       fail only when more than P % of the pixels exceed --fail (default 0)\n"
    "  --warnpercent P       warn only when more than P % of the pixels exceed --warn (default 0)\n"
    "  --hardfail X, --hardwarn X  fail / warn when any one difference exceeds X (default: none)\n"
    "  --fail-flip X         fail when the mean FLIP exceeds X\n"
    "  --fail-ssim X         fail when the mean SSIM is BELOW X\n"
    "  --ppd N               FLIP's pixels per degree (default 67.02: 0.7 m from a 0.7 m wide 3840 px screen)\n"
    "  --hdr, --ldr          treat both images as HDR / LDR whatever the files' types\n"
    "Gates as idiff's: FAILURE when more than --failpercent % of the pixels have a channel differing by\n"
    "more than --fail (or --hardfail, --fail-flip, --fail-ssim trip); else WARNING when more than\n"
    "--warnpercent % differ by more than --warn (or --hardwarn trips); else PASS.\n"
    "exit: 0 pass, 1 warn, 2 fail, 3 the images differ in size or channels (or HDR/LDR kind),\n"
    "      4 a file cannot be read (one line naming it), 5 any other error (usage, a non-finite pixel)\n";

// "a=1,b=2" -> {"a=1", "b=2"}; a piece without '=' continues the value before
// it (a knob value with a comma in it).
std::vector<std::string> splitSets(const std::string& flag, const std::vector<std::string>& values) {
    std::vector<std::string> sets;
    for (const std::string& v : values) {
        size_t start = 0;
        while (start <= v.size()) {
            const size_t comma = v.find(',', start);
            const std::string piece = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            if (piece.find('=') == std::string::npos && !sets.empty() && start > 0) sets.back() += "," + piece;
            else if (piece.empty() || piece.find('=') == std::string::npos || piece[0] == '=')
                throw UsageError(flag + " expects knob=value[,knob=value...], got '" + v + "'");
            else sets.push_back(piece);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
    }
    return sets;
}

nlohmann::json numberOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string channelName(int c, int channels) {
    static const char* kRgba[] = {"R", "G", "B", "A"};
    if (channels == 1) return "Y";
    if (channels == 3 || channels == 4) return kRgba[c];
    return std::to_string(c);
}

std::string perChannel(const std::vector<DifferenceFigures>& f, double DifferenceFigures::*field, int channels) {
    std::string s;
    char buf[64];
    for (size_t c = 0; c < f.size(); ++c) {
        std::snprintf(buf, sizeof buf, "%s%s %.6g", c ? "  " : "", channelName(static_cast<int>(c), channels).c_str(),
                      f[c].*field);
        s += buf;
    }
    return s;
}

void printReport(const CompareImage& a, const CompareImage& b, const ImageComparison& c, Verdict verdict,
                 const std::vector<std::string>& reasons) {
    const DifferenceStatistics& d = c.difference;
    const int ch = c.absoluteDifference.channels;
    std::printf("compare: reference %s\n         test      %s\n", a.describe.c_str(), b.describe.c_str());
    std::printf("  %s, %s\n", DifferenceStatistics::shape(a.image).c_str(), c.hdr ? "HDR" : "LDR");
    std::printf("  mean error   %-12.6g (%s)\n", d.overall.mean, perChannel(d.perChannel, &DifferenceFigures::mean, ch).c_str());
    std::printf("  RMS error    %-12.6g (%s)\n", d.overall.rms, perChannel(d.perChannel, &DifferenceFigures::rms, ch).c_str());
    std::printf("  PSNR         %.4g dB (peak max(1, largest value), as OpenImageIO)\n", d.overall.psnr);
    std::printf("  max error    %-12.6g at (%d, %d) channel %s\n", d.overall.max, d.overall.maxX, d.overall.maxY,
                channelName(d.overall.maxChannel, ch).c_str());
    if (c.ssim) {
        std::string per;
        char buf[48];
        for (size_t i = 0; i < c.ssim->perChannel.size(); ++i) {
            std::snprintf(buf, sizeof buf, "%s%s %.6f", i ? "  " : "",
                          channelName(static_cast<int>(i), static_cast<int>(c.ssim->perChannel.size())).c_str(),
                          c.ssim->perChannel[i]);
            per += buf;
        }
        std::printf("  SSIM         %.6f (%s; %s values)\n", c.ssim->mean, per.c_str(), ssimEncodingName(c.ssimEncoding));
    }
    if (c.flip) {
        std::printf("  FLIP         %.6f (%s, %.2f pixels per degree", c.flip->mean, c.flip->hdr ? "HDR-FLIP" : "LDR-FLIP",
                    c.flip->pixelsPerDegree);
        if (c.flip->hdr)
            std::printf("; exposures %.4g to %.4g stops, %d", c.flip->startExposure, c.flip->stopExposure,
                        c.flip->exposureCount);
        std::printf(")\n");
    }
    for (const std::string& n : c.notes) std::printf("  %s\n", n.c_str());
    const double pixels = static_cast<double>(d.pixelCount);
    std::printf("  %lld pixels (%.3g%%) over warn %g\n", d.overall.warnCount, 100.0 * d.overall.warnCount / pixels,
                d.warnThreshold);
    std::printf("  %lld pixels (%.3g%%) over fail %g\n", d.overall.failCount, 100.0 * d.overall.failCount / pixels,
                d.failThreshold);
    for (const std::string& r : reasons) std::printf("  %s\n", r.c_str());
    std::printf("%s\n", verdictName(verdict));
}

nlohmann::json sideJson(const CompareInput& in, const CompareImage& img) {
    nlohmann::json j;
    j["label"] = img.label;
    j["hdr"] = img.hdr;
    j["description"] = img.describe;
    if (in.kind == CompareInput::Kind::File) {
        j["kind"] = "file";
        j["path"] = in.path;
    } else {
        j["kind"] = "render";
        j["scene"] = in.run.sceneSpec();
        j["preset"] = in.run.presetSpec();
        j["set"] = in.run.sets;
        j["buffer"] = in.buffer;
        j["size"] = {in.run.width, in.run.height};
    }
    return j;
}

nlohmann::json reportJson(const CompareInput& inA, const CompareImage& a, const CompareInput& inB, const CompareImage& b,
                          const ImageComparison& c, const ComparisonGates& gates, Verdict verdict,
                          const std::vector<std::string>& reasons) {
    const DifferenceStatistics& d = c.difference;
    nlohmann::json j;
    j["reference"] = sideJson(inA, a);
    j["test"] = sideJson(inB, b);
    j["width"] = a.image.width;
    j["height"] = a.image.height;
    j["channels"] = a.image.channels;
    j["hdr"] = c.hdr;
    j["mean"] = d.overall.mean;
    j["rms"] = d.overall.rms;
    j["psnr"] = numberOrNull(d.overall.psnr);  // null: identical (infinite PSNR)
    j["max"] = d.overall.max;
    j["max_pixel"] = {d.overall.maxX, d.overall.maxY};
    j["max_channel"] = d.overall.maxChannel;
    nlohmann::json mean = nlohmann::json::array(), rms = mean, psnr = mean, max = mean, fails = mean, warns = mean;
    for (const DifferenceFigures& f : d.perChannel) {
        mean.push_back(f.mean);
        rms.push_back(f.rms);
        psnr.push_back(numberOrNull(f.psnr));
        max.push_back(f.max);
        fails.push_back(f.failCount);
        warns.push_back(f.warnCount);
    }
    j["mean_per_channel"] = mean;
    j["rms_per_channel"] = rms;
    j["psnr_per_channel"] = psnr;
    j["max_per_channel"] = max;
    j["fail_count_per_channel"] = fails;
    j["warn_count_per_channel"] = warns;
    j["ssim"] = c.ssim ? nlohmann::json(c.ssim->mean) : nlohmann::json(nullptr);
    j["ssim_per_channel"] = c.ssim ? nlohmann::json(c.ssim->perChannel) : nlohmann::json::array();
    j["ssim_encoding"] = ssimEncodingName(c.ssimEncoding);
    j["flip"] = c.flip ? nlohmann::json(c.flip->mean) : nlohmann::json(nullptr);
    j["flip_variant"] = c.flip ? (c.flip->hdr ? "HDR-FLIP" : "LDR-FLIP") : "";
    j["flip_pixels_per_degree"] = c.flip ? nlohmann::json(c.flip->pixelsPerDegree) : nlohmann::json(nullptr);
    if (c.flip && c.flip->hdr)
        j["flip_exposures"] = {{"start", c.flip->startExposure}, {"stop", c.flip->stopExposure}, {"count", c.flip->exposureCount}};
    j["notes"] = c.notes;
    j["pixel_count"] = d.pixelCount;
    j["fail_count"] = d.overall.failCount;
    j["warn_count"] = d.overall.warnCount;
    j["thresholds"] = {{"fail", d.failThreshold},
                       {"warn", d.warnThreshold},
                       {"failpercent", gates.failPercent},
                       {"warnpercent", gates.warnPercent},
                       {"hardfail", numberOrNull(gates.hardFail)},
                       {"hardwarn", numberOrNull(gates.hardWarn)},
                       {"fail_flip", gates.failFlip ? nlohmann::json(*gates.failFlip) : nlohmann::json(nullptr)},
                       {"fail_ssim", gates.failSsim ? nlohmann::json(*gates.failSsim) : nlohmann::json(nullptr)}};
    j["verdict"] = verdict == Verdict::Pass ? "pass" : verdict == Verdict::Warn ? "warn" : "fail";
    j["exit_code"] = static_cast<int>(verdict);
    j["reasons"] = reasons;
    return j;
}

// --sequence REFERENCE_PATTERN TEST_PATTERN, with --hdr or --ldr and no other option.
int sequenceCompare(const std::vector<std::string>& files, bool otherOptions, bool forceHdr, bool forceLdr) {
    if (files.size() != 2)
        throw UsageError("--sequence needs two frame patterns (REFERENCE_PATTERN TEST_PATTERN), got " +
                         std::to_string(files.size()));
    if (otherOptions)
        throw UsageError("--sequence compares two sequences of image files: it takes --hdr or --ldr, no other option");
    return compareSequences({files[0], files[1], forceHdr, forceLdr});
}

int compare(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "compare");
    if (cl.flag("--help")) {
        std::cout << kUsage << CommandLine::rangesHelp("compare");
        return 0;
    }
    // An input file that cannot be read (here: the preset) exits 4, as an image does.
    auto unreadable = [](const FileError& e) {
        std::fprintf(stderr, "deferred-workbench: cannot read %s\n", e.what());
        return kExitFile;
    };
    RunConfig base;
    try {
        base = cl.runConfig();
    } catch (const FileError& e) {
        return unreadable(e);
    }
    const auto size = cl.size();
    const auto bufferFlag = cl.value("--buffer");
    const auto framesFlag = cl.whole("--frames");
    const std::vector<std::string> aSets = splitSets("--a", cl.values("--a"));
    const std::vector<std::string> bSets = splitSets("--b", cl.values("--b"));
    const auto against = cl.value("--against");
    const auto aoRaysFlag = cl.whole("--ao-rays");
    const auto errorMap = cl.value("--error-map");
    auto heatMap = cl.value("--heat-map");
    const auto json = cl.value("--json");
    ComparisonSettings settings;
    // Each held to its range in limits::kNumericOptions (renderer/OptionLimits.h).
    int gateFlags = 0;  // how many gate and FLIP options were given (--sequence takes none)
    auto real = [&](const char* flag) {
        const auto v = cl.real(flag);
        gateFlags += v.has_value();
        return v;
    };
    settings.failThreshold = real("--fail").value_or(1e-6);
    settings.warnThreshold = real("--warn").value_or(1e-6);
    ComparisonGates gates;
    gates.failPercent = real("--failpercent").value_or(0);
    gates.warnPercent = real("--warnpercent").value_or(0);
    gates.hardFail = real("--hardfail").value_or(gates.hardFail);
    gates.hardWarn = real("--hardwarn").value_or(gates.hardWarn);
    gates.failFlip = real("--fail-flip");
    gates.failSsim = real("--fail-ssim");
    if (const auto ppd = real("--ppd")) settings.flip.pixelsPerDegree = *ppd;
    const bool forceHdr = cl.flag("--hdr"), forceLdr = cl.flag("--ldr");
    const bool sequence = cl.flag("--sequence");
    cl.finish("compare");
    if (forceHdr && forceLdr) throw UsageError("--hdr and --ldr cannot both be given");
    const std::vector<std::string> files = cl.positional();
    if (sequence)
        return sequenceCompare(files, !aSets.empty() || !bSets.empty() || against || size || bufferFlag || framesFlag ||
                                          errorMap || heatMap || json || aoRaysFlag || gateFlags > 0 ||
                                          !base.scene.empty() || !base.presetSpec().empty() || !base.sets.empty(),
                               forceHdr, forceLdr);

    CompareInput inA, inB;
    if (against && *against != "reference")
        throw UsageError("--against: only 'reference' (the CPU ground truth) is known, not '" + *against + "'");
    if (against && !aSets.empty()) throw UsageError("--against reference is side A: give the render's knobs with --b, not --a");
    if (aoRaysFlag && !against) throw UsageError("--ao-rays applies to --against reference");
    if (!aSets.empty() || !bSets.empty() || against) {
        if (!files.empty())
            throw UsageError("compare takes two image files, or --a/--b knob sets or --against reference, not both (got '" + files[0] + "')");
        try {
            base.validate();
        } catch (const FileError& e) {
            return unreadable(e);
        }
        std::tie(base.width, base.height) = size.value_or(std::pair{1280, 720});
        // Renders are held to the image memory budget as files are (RGBA read back).
        if (const std::string why = comparison_memory::refusal(base.width, base.height, 4); !why.empty())
            throw UsageError("--size " + std::to_string(base.width) + "x" + std::to_string(base.height) + ": " + why);
        base.frames = framesFlag.value_or(1);
        for (auto* side : {&inA, &inB}) {
            side->kind = CompareInput::Kind::Render;
            side->run = base;
            side->buffer = bufferFlag.value_or("final");
            if (side->buffer == "ao") side->buffer = "ao.filtered";  // the AO the lighting pass uses
            if (side->buffer == "shadow") side->buffer = "lighting.shadow";  // the reference's shadow factor
        }
        inA.label = "--a";
        inB.label = "--b";
        inA.run.sets.insert(inA.run.sets.end(), aSets.begin(), aSets.end());
        inB.run.sets.insert(inB.run.sets.end(), bSets.begin(), bSets.end());
        if (against) {
            inA.kind = CompareInput::Kind::Reference;
            inA.label = "reference";
            inA.run.sets = inB.run.sets;  // the model's knobs are the render's
            inA.aoRays = aoRaysFlag.value_or(64);
            CompareInputs::referenceBufferFor(inA.buffer);  // a buffer without a counterpart fails before rendering
            if (inA.buffer == "ao.raw") {
                // ao.raw is at the method's resolution (<method>.resolution); the reference's AO at the frame's.
                KnobRegistry knobs = RunConfig::declaredKnobs();
                for (const std::string& set : inB.run.sets) knobs.applyAssignment(set);
                const std::string method = knobs.choice(knobs.requireEnum("ao.method"));
                const std::string knob = method + ".resolution";
                if (const auto id = knobs.find(knob); id && knobs.format(*id) != "full")
                    throw UsageError("--against reference --buffer ao.raw: ao.raw is at " + knob + " (" + knobs.format(*id) +
                                     "), the reference's AO at the frame's size: add --b " + knob +
                                     "=full, or compare ao (ao.filtered)");
            }
        }
        inA.run.validate();
        inB.run.validate();
    } else {
        if (files.size() != 2)
            throw UsageError("compare needs two image files (REFERENCE TEST), --a and --b knob sets, or --against reference; got " +
                             std::to_string(files.size()) + " file" + (files.size() == 1 ? "" : "s"));
        for (const auto& [flag, given] : {std::pair{"--size", size.has_value()}, std::pair{"--buffer", bufferFlag.has_value()},
                                          std::pair{"--frames", framesFlag.has_value()}})
            if (given) throw UsageError(std::string(flag) + " applies to renders (--a/--b), not to two files");
        if (!base.scene.empty() || !base.presetSpec().empty() || !base.sets.empty())
            throw UsageError("--scene, --preset and --set apply to renders (--a/--b), not to two files");
        inA.path = inA.label = files[0];
        inB.path = inB.label = files[1];
    }
    if (errorMap && !isFloatFormat(*errorMap))
        throw UsageError("--error-map writes float maps: give it an .exr name, got '" + *errorMap + "'");
    if (errorMap && !heatMap) heatMap = std::filesystem::path(*errorMap).replace_extension(".png").string();
    CommandLine::NamedFiles writes, reads;
    if (errorMap) writes.emplace_back("--error-map", *errorMap);
    if (heatMap) writes.emplace_back("--heat-map", *heatMap);
    if (json) writes.emplace_back("--json", *json);
    if (inA.kind == CompareInput::Kind::File) {
        reads = {{"the reference", inA.path}, {"the test", inB.path}};
    } else {
        reads = CommandLine::inputFiles(base);
    }
    CommandLine::requireDistinctFiles(writes, reads);
    // An output that cannot be written fails before any image is read or rendered.
    for (const auto& [what, path] : writes) CommandLine::requireWritable(path, what + " file");

    CompareInputs inputs;
    CompareImage a, b;
    try {
        a = inputs.produce(inA);
        b = inputs.produce(inB);
    } catch (const FileError& e) {
        return unreadable(e);
    }
    if (forceHdr || forceLdr) a.hdr = b.hdr = forceHdr;
    if (a.image.width != b.image.width || a.image.height != b.image.height || a.image.channels != b.image.channels) {
        std::fprintf(stderr, "deferred-workbench: the images differ in size or channels: %s is %s, %s is %s (width x height x channels)\n",
                     a.label.c_str(), DifferenceStatistics::shape(a.image).c_str(), b.label.c_str(),
                     DifferenceStatistics::shape(b.image).c_str());
        return kExitShape;
    }
    if (a.hdr != b.hdr) {
        std::fprintf(stderr, "deferred-workbench: %s is %s and %s is %s: compare needs both HDR or both LDR (--hdr or --ldr chooses)\n",
                     a.label.c_str(), a.hdr ? "HDR" : "LDR", b.label.c_str(), b.hdr ? "HDR" : "LDR");
        return kExitShape;
    }
    settings.hdr = a.hdr;
    // HDR-FLIP's exposures at once: as many as the image memory budget holds.
    settings.flip.maxThreads = comparison_memory::flipThreadsWithin(a.image.width, a.image.height, a.image.channels);
    const ImageComparison c = ImageComparison::measure(a.image, b.image, settings, a.label, b.label);
    std::vector<std::string> reasons;
    const Verdict verdict = gates.judge(c, reasons);
    printReport(a, b, c, verdict, reasons);
    if (errorMap) {
        std::vector<std::string> names;
        const FloatImage map = c.errorMap(names);
        writeImage(*errorMap, map, names);
        std::printf("wrote %s (", errorMap->c_str());
        for (size_t i = 0; i < names.size(); ++i) std::printf("%s%s", i ? ", " : "", names[i].c_str());
        std::printf(")\n");
    }
    if (heatMap) {
        writeImage(*heatMap, ComparisonHeatMap::of(c));
        if (c.flip)
            std::printf("wrote %s (FLIP through Turbo: 0 dark blue .. 1 dark red)\n", heatMap->c_str());
        else
            std::printf("wrote %s (largest |difference| of the channels through Turbo: 0 .. %g)\n", heatMap->c_str(),
                        ComparisonHeatMap::top(c));
    }
    if (json) {
        writeFileAtomically(*json, reportJson(inA, a, inB, b, c, gates, verdict, reasons).dump(2) + "\n");
        std::printf("wrote %s\n", json->c_str());
    }
    return static_cast<int>(verdict);
}

}  // namespace

int runCompareCommand(int argc, char** argv) {
    // compare's exit codes 1-4 carry its verdicts, so its own errors (usage,
    // a non-finite pixel, an unwritable output) exit 5, not main()'s 1 or 2.
    try {
        return compare(argc, argv);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "deferred-workbench: %s\n(deferred-workbench help compare lists its options)\n", e.what());
        return kExitError;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "deferred-workbench: error: %s\n", e.what());
        return kExitError;
    }
}

}  // namespace dw

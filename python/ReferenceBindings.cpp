// The measuring half's images: Session.reference (the CPU reference of the
// view), dw.compare (every metric of `compare` for two arrays) and
// dw.load_image; their files as reference's and compare's flags write them.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "python/Arguments.h"
#include "python/Arrays.h"
#include "python/Bindings.h"
#include "python/ReferenceTrace.h"
#include "renderer/OptionLimits.h"
#include "renderer/io/TextFile.h"
#include "renderer/metrics/ComparisonHeatMap.h"
#include "renderer/metrics/ComparisonMemory.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/metrics/TemporalError.h"

namespace py = pybind11;

namespace dw::python {
namespace {

// A dict of plain values as indented JSON (Python's json module), whole or not at all.
void writeJsonObject(const std::string& path, const py::dict& d) {
    const std::string text = py::module_::import("json").attr("dumps")(d, py::arg("indent") = 2).cast<std::string>() + "\n";
    py::gil_scoped_release release;
    writeFileAtomically(path, text);
}

py::dict figuresDict(const DifferenceFigures& f) {
    py::dict d;
    d["mean"] = f.mean;
    d["rms"] = f.rms;
    d["psnr"] = f.psnr;
    d["max"] = f.max;
    d["max_pixel"] = py::make_tuple(f.maxX, f.maxY);
    d["max_channel"] = f.maxChannel;
    d["warn_count"] = f.warnCount;
    d["fail_count"] = f.failCount;
    return d;
}

py::dict referenceStats(const reference::ReferenceStatistics& s) {
    py::dict d;
    d["seconds"] = s.seconds;
    d["build_seconds"] = s.buildSeconds;
    d["threads"] = s.threads;
    d["primary_rays"] = s.primaryRays;
    d["shadow_rays"] = s.shadowRays;
    d["ao_rays"] = s.aoRays;
    d["blended_hits"] = s.blendedHits;
    d["ao_standard_error_mean"] = s.aoStandardErrorMean;
    d["ao_standard_error_max"] = s.aoStandardErrorMax;
    d["triangles"] = s.triangles;
    d["pixel_samples"] = s.pixelSamples;
    d["spp_error_mean"] = s.sppErrorMean;
    d["spp_error_max"] = s.sppErrorMax;
    return d;
}

// The statistics with the samples-per-pixel verdict's figure (as reference --stats-out writes them).
py::dict referenceStats(const reference::ReferenceImages& images) {
    py::dict d = referenceStats(images.stats);
    const double relative = reference::meanRelativeSppError(images);
    d["spp_relative_error_mean"] = relative;
    d["spp_enough"] = relative < reference::kSppEnough;
    return d;
}

py::object sessionReference(WorkbenchSession& s, const std::string& buffer, const py::object& aoRaysObject,
                            const py::object& seedObject, const py::object& threadsObject, bool cache,
                            std::optional<std::string> cacheDir, bool stats, std::optional<std::string> out,
                            std::optional<std::string> statsOut, const py::object& progress, const py::object& sppObject,
                            const std::string& filter) {
    const auto& names = reference::referenceBuffers();
    if (std::find(names.begin(), names.end(), buffer) == names.end())
        throw UnknownBufferError("unknown reference buffer '" + buffer + "' (lbuffer, final, ao, shadow or spp_error)");
    ReferenceOptions o = referenceOptions("reference", aoRaysObject, seedObject, threadsObject, cache, cacheDir);
    o.pixelSamples = intArg(sppObject, "reference: spp", limits::kPixelSamples, "reference --spp");
    try {
        o.pixelFilter = reference::pixelFilterNamed(filter);
    } catch (const Error& e) {
        throw py::value_error(std::string("reference: filter: ") + e.what());
    }
    const int aoRays = o.aoRays, seed = o.seed;
    requireCallable(progress, "reference: progress");
    requirePath(out, "reference: out");
    requirePath(statsOut, "reference: stats_out");
    s.requireOwningThread();
    const reference::ReferenceImages images = traceReference(progress, [&](reference::ReferenceProgress* p) {
        o.progress = p;
        return s.reference(o);
    });
    if (out) {
        py::gil_scoped_release release;
        writeImage(*out, *images.buffer(buffer));
    }
    py::dict statsDict = referenceStats(images);
    if (statsOut) {
        py::dict file = statsDict;
        file["scene"] = s.sceneName();
        file["width"] = s.width();
        file["height"] = s.height();
        file["buffer"] = buffer;
        file["ao_rays_per_pixel"] = aoRays;
        file["seed"] = seed;
        file["pixel_samples"] = o.pixelSamples;
        file["pixel_filter"] = reference::pixelFilterName(o.pixelFilter);
        writeJsonObject(*statsOut, file);
    }
    py::array_t<float> a = toArray(*images.buffer(buffer));
    if (!stats) return a;
    return py::make_tuple(a, statsDict);
}

// The image memory budget (DW_IMAGE_LIMIT_MB) before a pixel is copied, as
// compare on files: Error naming the array that is over it.
void requireWithinImageBudget(const py::array& reference, const py::array& test) {
    for (const auto& [array, what] : {std::pair{&reference, "reference"}, std::pair{&test, "test"}})
        if (array->ndim() >= 2)
            if (const std::string why = comparison_memory::refusal(
                    static_cast<int>(std::min<py::ssize_t>(array->shape(1), std::numeric_limits<int>::max())),
                    static_cast<int>(std::min<py::ssize_t>(array->shape(0), std::numeric_limits<int>::max())),
                    array->ndim() == 3 ? static_cast<int>(std::min<py::ssize_t>(array->shape(2), 1 << 20)) : 1);
                !why.empty())
                throw Error(std::string("compare: ") + what + " is " + why);
}

// The comparison's figures as compare --json writes them.
py::dict comparisonDict(const ImageComparison& c) {
    py::dict d = figuresDict(c.difference.overall);
    d["hdr"] = c.hdr;
    d["pixel_count"] = c.difference.pixelCount;
    py::list perChannel;
    for (const auto& f : c.difference.perChannel) perChannel.append(figuresDict(f));
    d["per_channel"] = perChannel;
    d["ssim"] = c.ssim ? py::object(py::float_(c.ssim->mean)) : py::object(py::none());
    d["flip"] = c.flip ? py::object(py::float_(c.flip->mean)) : py::object(py::none());
    d["notes"] = c.notes;
    return d;
}

py::dict compareArrays(const py::array& reference, const py::array& test, bool hdr, const py::object& warnObject,
                       const py::object& failObject, bool maps, std::optional<std::string> errorMap,
                       std::optional<std::string> heatMap, std::optional<std::string> json) {
    // compare's --warn and --fail: finite, at least 0.
    requirePath(errorMap, "compare: error_map");
    requirePath(heatMap, "compare: heat_map");
    requirePath(json, "compare: json");
    const double warnThreshold = numberArg(warnObject, "compare: warn_threshold", limits::kThreshold, "compare --warn");
    const double failThreshold = numberArg(failObject, "compare: fail_threshold", limits::kThreshold, "compare --fail");
    if (errorMap && !isFloatFormat(*errorMap))
        throw Error("error_map writes float maps: give it an .exr name, got '" + *errorMap + "'");
    requireWithinImageBudget(reference, test);
    const FloatImage a = toFloatImage(reference, "reference");
    const FloatImage b = toFloatImage(test, "test");
    ComparisonSettings settings;
    settings.hdr = hdr;
    // HDR-FLIP's exposures at once: as many as the budget holds (the result is the same).
    settings.flip.maxThreads = comparison_memory::flipThreadsWithin(a.width, a.height, a.channels);
    settings.warnThreshold = warnThreshold;
    settings.failThreshold = failThreshold;
    ImageComparison c;
    {
        py::gil_scoped_release release;
        c = ImageComparison::measure(a, b, settings);
    }
    py::dict d = comparisonDict(c);
    {
        py::gil_scoped_release release;
        if (errorMap) {
            std::vector<std::string> names;
            const FloatImage map = c.errorMap(names);
            writeImage(*errorMap, map, names);
        }
        if (heatMap) writeImage(*heatMap, ComparisonHeatMap::of(c));
    }
    if (json) writeJsonObject(*json, d);
    if (maps) {
        py::dict m;
        m["difference"] = toArray(c.absoluteDifference);
        if (c.ssim) m["ssim"] = toArray(c.ssim->map);
        if (c.flip) m["flip"] = toArray(c.flip->map);
        d["maps"] = m;
    }
    return d;
}

py::array loadImage(const std::string& path) {
    requirePath(path, "load_image: path");
    FloatImage image;
    {
        py::gil_scoped_release release;
        image = loadImageFloat(path);
    }
    if (isFloatFormat(path)) return toArray(image);
    BufferImage bytes;
    bytes.width = image.width;
    bytes.height = image.height;
    bytes.channels = image.channels;
    bytes.eightBit = true;
    bytes.bytes.resize(image.pixels.size());
    for (size_t i = 0; i < image.pixels.size(); ++i)
        bytes.bytes[i] = static_cast<std::uint8_t>(std::lround(std::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f));
    return toArray(bytes);
}

}  // namespace

void bindReference(SessionClass& session) {
    session.def("reference", &sessionReference, py::arg("buffer") = "lbuffer", py::arg("ao_rays") = 64,
                py::arg("seed") = 1, py::arg("threads") = 0, py::arg("cache") = true, py::arg("cache_dir") = py::none(),
                py::arg("stats") = false, py::arg("out") = py::none(), py::arg("stats_out") = py::none(),
                py::arg("progress") = py::none(), py::arg("spp") = 1, py::arg("filter") = "box",
                "The CPU reference of this view (as `reference`): float32 H x W x C; stats=True: (array, dict).\n"
                "spp=N samples per pixel over the pixel's footprint (filter=\"box\" or \"tent\"), as reference --spp;\n"
                "buffer=\"spp_error\" is each pixel's standard error over its samples.\n"
                "progress(fraction) is called while it traces; Ctrl-C, or an exception in progress, cancels it.\n"
                "out=PATH writes the image as reference --out does (.exr raw, .png in [0, 1]); stats_out=PATH the\n"
                "statistics as JSON (reference --stats-out's figures under the same keys).");
}

// dw.temporal_error: the frames of each side as arrays (a list, or a T x H x W (x C) array).
py::dict temporalErrorOf(const py::sequence& reference, const py::sequence& test) {
    std::vector<FloatImage> ref, tst;
    for (const auto* side : {&reference, &test}) {
        auto& frames = side == &reference ? ref : tst;
        const char* what = side == &reference ? "temporal_error: reference frame" : "temporal_error: test frame";
        for (size_t t = 0; t < side->size(); ++t) {
            const std::string name = std::string(what) + " " + std::to_string(t);
            frames.push_back(toFloatImage(py::array(py::object((*side)[t])), name.c_str()));
        }
    }
    TemporalErrorResult r;
    {
        py::gil_scoped_release release;
        r = TemporalError::measure(ref, tst);
    }
    py::dict d;
    d["mean"] = r.mean;
    d["low"] = r.interval.low;
    d["high"] = r.interval.high;
    d["pairs"] = r.pairs;
    d["frames"] = ref.size();
    return d;
}

void bindCompare(py::module_& m) {
    m.def("temporal_error", &temporalErrorOf, py::arg("reference"), py::arg("test"),
          "The temporal error of a test sequence against a reference sequence (docs/metrics.md, \"Temporal error\"):\n"
          "each a list of H x W (x C) arrays, or one T x H x W (x C) array (uint8 read as v / 255), T >= 2, one shape.\n"
          "A dict: mean (over frame pairs of the mean |d_t - r_t| of luminance, d_t and r_t the test's and the\n"
          "reference's frame-to-frame change), low and high (its 95% bootstrap interval over pairs), pairs (each\n"
          "pair's error, frames 0->1 first) and frames (T). dw.Error for sequences of other lengths or shapes,\n"
          "fewer than 2 frames or a non-finite pixel, naming the frame.");
    m.def("compare", &compareArrays, py::arg("reference"), py::arg("test"), py::arg("hdr") = false,
          py::arg("warn_threshold") = 1e-6, py::arg("fail_threshold") = 1e-6, py::arg("maps") = false,
          py::arg("error_map") = py::none(), py::arg("heat_map") = py::none(), py::arg("json") = py::none(),
          "Every metric of `compare` for two arrays of one shape (uint8 read as v / 255): a dict; maps=True adds\n"
          "the per-pixel error maps. error_map=FILE.exr, heat_map=FILE.png and json=PATH write what compare's\n"
          "--error-map, --heat-map and --json write (the JSON: this dict's figures, without maps).");
    m.def("load_image", &loadImage, py::arg("path"),
          "An image file through the workbench's ImageIO: uint8 for 8-bit formats, float32 for .exr/.hdr/.tif.");
}

}  // namespace dw::python

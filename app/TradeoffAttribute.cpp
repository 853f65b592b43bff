// deferred-workbench tradeoff --attribute: where the error of one view at
// the current settings comes from, family by family (ErrorAttribution);
// docs/tradeoffs.md, "Where the error comes from".
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "app/Commands.h"
#include "app/SweepOptions.h"
#include "headless/CommandLine.h"
#include "headless/HeadlessGlContext.h"
#include "headless/PlotScript.h"
#include "renderer/Error.h"
#include "renderer/OptionLimits.h"
#include "renderer/bench/BenchResults.h"
#include "renderer/study/CachedReferences.h"
#include "renderer/study/ErrorAttribution.h"

namespace dw {

namespace {

std::string attributeUsage() {
    return "usage: deferred-workbench tradeoff --attribute [--scene S] [--preset P] [--set knob=value]... [--size WxH]\n"
           "                                   [--metric flip|rms] [--buffer final|lbuffer|ao|shadow] [--ao-rays N]\n"
           "                                   [--resamples N] [--csv FILE] [--plot FILE.png|none] [--plot-size WxH] [--quiet]\n"
           "For one view at the settings given: the error against the CPU reference of the settings as they are,\n"
           "of every approximation family at its most accurate setting, and of each family alone made exact and\n"
           "alone left approximate, with 95% intervals (docs/tradeoffs.md). Default files attribution.csv and\n"
           "attribution.png (a bar chart by scripts/attribution_plot.py).\n";
}

struct AttributeFiles {
    std::string csv = "attribution.csv";
    std::optional<std::string> plot = std::string("attribution.png");
    int plotWidth = 800, plotHeight = 500;
    bool quiet = false;
};

AttributeFiles readFiles(CommandLine& cl, const RunConfig& run) {
    AttributeFiles f;
    if (const auto csv = cl.value("--csv")) f.csv = *csv;
    if (const auto plot = cl.value("--plot")) f.plot = *plot == "none" ? std::nullopt : std::optional<std::string>(*plot);
    if (const auto size = cl.size("--plot-size")) {
        f.plotWidth = size->first;
        f.plotHeight = size->second;
    }
    f.quiet = cl.flag("--quiet");
    CommandLine::NamedFiles writes = {{"attribution CSV", f.csv}};
    if (f.plot) {
        checkPlotFile(*f.plot, f.plotWidth, f.plotHeight);
        writes.emplace_back("plot", *f.plot);
    }
    CommandLine::requireDistinctFiles(writes, CommandLine::inputFiles(run));
    return f;
}

}  // namespace

int runTradeoffAttribute(int argc, char** argv) {
    CommandLine cl(argc, argv, 2, "tradeoff");
    (void)cl.flag("--attribute");
    if (cl.flag("--help")) {
        std::cout << attributeUsage();
        return 0;
    }
    AttributionOptions o;
    o.run = cl.runConfig();
    o.run.sceneTime = cl.real("--scene-time").value_or(0.0);
    const auto [w, h] = SweepOptions::readSizes(cl, false).front();
    o.run.width = w;
    o.run.height = h;
    o.metric = cl.value("--metric").value_or("flip");
    o.buffer = cl.value("--buffer").value_or("final");
    o.resamples = SweepOptions::readResamples(cl);
    const int aoRays = cl.whole("--ao-rays", 64);
    if (!limits::kAoRays.holds(aoRays))
        throw UsageError("--ao-rays must be between " + std::to_string(limits::kAoRays.min) + " and " +
                         std::to_string(limits::kAoRays.max));
    try {
        ErrorAttribution::checkMetricAndBuffer(o.metric, o.buffer);
    } catch (const Error& e) {
        throw UsageError(e.what());
    }
    const AttributeFiles files = readFiles(cl, o.run);
    cl.finish("tradeoff --attribute");
    if (!cl.positional().empty()) throw UsageError("tradeoff: unexpected argument '" + cl.positional()[0] + "'");
    CommandLine::requireWritable(files.csv, "attribution CSV");
    if (files.plot) CommandLine::requireWritable(*files.plot, "plot");

    ErrorAttribution attribution(o);  // the metric, the buffer, the scene: before any GL
    for (const auto& line : attribution.scene().warnings) std::fprintf(stderr, "warning: %s\n", line.c_str());
    auto context = HeadlessGlContext::create();
    const auto say = [&](const std::string& line) {
        if (!files.quiet) std::fprintf(stderr, "%s\n", line.c_str());
    };
    const auto warn = [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); };
    CachedReferences references(aoRays, 1, {say, warn, {}});
    const AttributionResult r = attribution.run(references.function(), say);
    std::printf("## tradeoff --attribute: %s\n\n%s", attribution.scene().name.c_str(), ErrorAttribution::table(r).c_str());
    std::fflush(stdout);
    writeBenchFile(files.csv, ErrorAttribution::csv(r), "attribution CSV");
    std::printf("wrote %s\n", files.csv.c_str());
    if (!files.plot) return 0;
    if (!runPlotScript("attribution_plot.py", "DW_ATTRIBUTION_PLOT_SCRIPT",
                       {"--csv", files.csv, "--out", *files.plot, "--size",
                        std::to_string(files.plotWidth) + "x" + std::to_string(files.plotHeight)},
                       "tradeoff --attribute"))
        return 1;
    std::printf("wrote %s (%dx%d)\n", files.plot->c_str(), files.plotWidth, files.plotHeight);
    return 0;
}

}  // namespace dw

#include "renderer/study/ErrorAttribution.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>

#include "renderer/Error.h"
#include "renderer/RenderSession.h"
#include "renderer/bench/CsvLine.h"
#include "renderer/metrics/Bootstrap.h"
#include "renderer/metrics/ImageComparison.h"
#include "renderer/reference/ReferenceModel.h"
#include "renderer/scene/SceneLoader.h"
#include "renderer/study/ApproximationFamilies.h"

namespace dw {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Per 16x16 tile (ImageError::kTile), the sum of the per-pixel quantity the
// metric averages (rms: the squared difference over channels; flip: the FLIP
// value) and the tile's pixel count.
struct TileSums {
    std::vector<double> sums, counts;
};

TileSums tileSums(const FloatImage& reference, const FloatImage& test, const std::string& metric, bool hdr) {
    ComparisonSettings settings;
    settings.hdr = hdr;
    settings.flipMetric = metric == "flip";
    const ImageComparison c = ImageComparison::measure(reference, test, settings);
    if (metric == "flip" && !c.flip)
        throw Error("FLIP cannot be measured here: " + (c.notes.empty() ? std::string("no reason given") : c.notes.front()));
    const int w = reference.width, h = reference.height, ch = reference.channels, tile = ImageError::kTile;
    const int tx = (w + tile - 1) / tile, ty = (h + tile - 1) / tile;
    TileSums t;
    t.sums.assign(static_cast<size_t>(tx) * ty, 0.0);
    t.counts.assign(t.sums.size(), 0.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double v = 0.0;
            if (metric == "flip") {
                v = c.flip->map.at(x, y, 0);
            } else {
                for (int k = 0; k < ch; ++k) v += double(c.absoluteDifference.at(x, y, k)) * c.absoluteDifference.at(x, y, k);
                v /= ch;
            }
            const size_t i = static_cast<size_t>(y / tile) * tx + static_cast<size_t>(x / tile);
            t.sums[i] += v;
            t.counts[i] += 1.0;
        }
    return t;
}

// The metric from summed tiles: the mean (flip) or its square root (rms).
double fromSums(double sum, double count, const std::string& metric) {
    const double mean = count > 0.0 ? sum / count : kNaN;
    return metric == "rms" ? std::sqrt(mean) : mean;
}

// error(a) - error(b) on the same tiles, the tiles resampled together: a
// paired percentile bootstrap (95%).
ErrorDifference pairedDifference(const TileSums& a, const TileSums& b, const std::string& metric, int resamples,
                                 std::uint64_t seed) {
    ErrorDifference d;
    double sa = 0.0, sb = 0.0, n = 0.0;
    for (size_t t = 0; t < a.sums.size(); ++t) {
        sa += a.sums[t];
        sb += b.sums[t];
        n += a.counts[t];
    }
    d.value = fromSums(sa, n, metric) - fromSums(sb, n, metric);
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<size_t> pick(0, a.sums.size() - 1);
    std::vector<double> draws;
    draws.reserve(static_cast<size_t>(resamples));
    for (int r = 0; r < resamples; ++r) {
        double ra = 0.0, rb = 0.0, rn = 0.0;
        for (size_t k = 0; k < a.sums.size(); ++k) {
            const size_t t = pick(rng);
            ra += a.sums[t];
            rb += b.sums[t];
            rn += a.counts[t];
        }
        if (rn > 0.0) draws.push_back(fromSums(ra, rn, metric) - fromSums(rb, rn, metric));
    }
    if (draws.empty()) {
        d.low = d.high = kNaN;
        return d;
    }
    std::sort(draws.begin(), draws.end());
    const auto at = [&](double q) { return draws[static_cast<size_t>(std::floor(q * (draws.size() - 1) + 0.5))]; };
    d.low = at(0.025);
    d.high = at(0.975);
    return d;
}

// `sets` on a copy of `knobs`; the ones that would change what the reference
// models (reference::ReferenceModel) are left out and named in `kept`.
std::vector<std::string> applicable(const std::vector<std::string>& sets, const KnobRegistry& knobs, const Scene& scene,
                                    std::vector<std::string>& kept) {
    const std::string model = reference::ReferenceModel::fromKnobs(knobs, scene).canonical();
    std::vector<std::string> out;
    for (const std::string& s : sets) {
        KnobRegistry k = knobs;
        k.applyAssignment(s);
        if (reference::ReferenceModel::fromKnobs(k, scene).canonical() == model) out.push_back(s);
        else kept.push_back(s.substr(0, s.find('=')));
    }
    return out;
}

std::string number(double v) {
    if (std::isnan(v)) return "";
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", v);
    return text;
}

// "0.0123 [0.0110, 0.0135]"; "0.0123 (no interval)" without one.
std::string withInterval(double v, double lo, double hi) {
    if (std::isnan(v)) return "-";
    if (std::isnan(lo) || std::isnan(hi)) return number(v) + " (no interval)";
    return number(v) + " [" + number(lo) + ", " + number(hi) + "]";
}

// Every interval of the result withdrawn (too few tiles to resample).
void withdrawIntervals(AttributionResult& r) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (ErrorEstimate* e : {&r.asIs, &r.allExact}) e->low = e->high = nan;
    r.total.low = r.total.high = nan;
    for (AttributionFamily& f : r.families) {
        for (ErrorEstimate* e : {&f.onlyExact, &f.onlyApproximate}) e->low = e->high = nan;
        for (ErrorDifference* d : {&f.removed, &f.added}) d->low = d->high = nan;
    }
}

// Whether a part's interval holds 0: that part cannot be told from none.
bool holdsZero(const ErrorDifference& d) { return !(d.low > 0.0) && !(d.high < 0.0); }

}  // namespace

struct AttributionRun::Measured {
    std::string key;  // every knob's value: equal keys render the same image
    ErrorEstimate error;
    TileSums tiles;
};

void AttributionRun::start(const KnobRegistry& asIs, const Scene& scene, FloatImage truth, const std::string& metric,
                           const std::string& buffer, int resamples) {
    ErrorAttribution::checkMetricAndBuffer(metric, buffer);
    asIs_ = asIs;
    truth_ = std::move(truth);
    metric_ = metric;
    buffer_ = buffer;
    resamples_ = resamples;
    result_ = {};
    result_.metric = metric;
    result_.buffer = buffer;
    result_.width = truth_.width;
    result_.height = truth_.height;
    std::vector<std::string> allExact;
    for (const ApproximationFamily& f : approximationFamilies()) {
        AttributionFamily a;
        a.name = f.name;
        a.what = f.what;
        a.exact = applicable(f.exact, asIs_, scene, a.kept);
        allExact.insert(allExact.end(), a.exact.begin(), a.exact.end());
        std::string kept;
        for (const auto& n : a.kept) kept += " " + n;
        if (!kept.empty()) result_.notes.push_back(f.name + ": left as it is (the reference models it here):" + kept);
        result_.families.push_back(std::move(a));
    }
    sets_ = {{}, allExact};
    for (const AttributionFamily& f : result_.families) {
        std::vector<std::string> others;
        for (const std::string& x : allExact)
            if (std::find(f.exact.begin(), f.exact.end(), x) == f.exact.end()) others.push_back(x);
        sets_.push_back(f.exact);
        sets_.push_back(std::move(others));
    }
    measured_.assign(sets_.size(), nullptr);
    next_ = 0;
    error_.clear();
    done_ = false;
    running_ = true;
}

double AttributionRun::progress() const {
    return sets_.empty() ? 0.0 : static_cast<double>(next_) / static_cast<double>(sets_.size());
}

bool AttributionRun::step(RenderSession& session) {
    if (!running_) return false;
    try {
        measure(session, next_++);
        if (next_ == sets_.size()) finish();
    } catch (const std::exception& e) {
        error_ = e.what();
        running_ = false;
    }
    return running_;
}

// Configuration `c` on the session, its knobs put back after.
void AttributionRun::measure(RenderSession& session, size_t c) {
    const KnobRegistry saved = session.knobs();
    session.knobs().copyValues(asIs_);
    for (const std::string& s : sets_[c]) session.knobs().applyAssignment(s);
    std::string key;
    for (int id = 0; id < static_cast<int>(session.knobs().size()); ++id) key += session.knobs().format(id) + ",";
    for (size_t i = 0; i < c; ++i)
        if (measured_[i]->key == key) {
            measured_[c] = measured_[i];
            session.knobs().copyValues(saved);
            return;
        }
    try {
        session.render(FrameRequest{{TradeoffRunner::gpuOutput(buffer_)}});
        const FloatImage image = TradeoffRunner::measuredImage(session, buffer_);
        auto m = std::make_shared<Measured>();
        m->key = key;
        const bool hdr = buffer_ != "final";
        m->error = ImageError::measure(truth_, image, metric_, hdr, resamples_, 12345 + c);
        m->tiles = tileSums(truth_, image, metric_, hdr);
        measured_[c] = std::move(m);
        ++result_.renders;
    } catch (...) {
        session.knobs().copyValues(saved);
        throw;
    }
    session.knobs().copyValues(saved);
}

// The rows' errors and the paired parts.
void AttributionRun::finish() {
    const Measured& asIs = *measured_[0];
    const Measured& exact = *measured_[1];
    result_.asIs = asIs.error;
    result_.allExact = exact.error;
    std::uint64_t seed = 54321;
    result_.total = pairedDifference(asIs.tiles, exact.tiles, metric_, resamples_, seed);
    for (size_t f = 0; f < result_.families.size(); ++f) {
        AttributionFamily& a = result_.families[f];
        const Measured& onlyExact = *measured_[2 + 2 * f];
        const Measured& onlyApproximate = *measured_[3 + 2 * f];
        a.onlyExact = onlyExact.error;
        a.onlyApproximate = onlyApproximate.error;
        a.removed = pairedDifference(asIs.tiles, onlyExact.tiles, metric_, resamples_, ++seed);
        a.added = pairedDifference(onlyApproximate.tiles, exact.tiles, metric_, resamples_, ++seed);
        result_.sumRemoved += a.removed.value;
        result_.sumAdded += a.added.value;
    }
    // A bootstrap of fewer tiles than an interval needs only repeats them.
    const size_t tiles = asIs.tiles.sums.size();
    if (!enoughForInterval(tiles)) {
        withdrawIntervals(result_);
        result_.notes.push_back("only " + std::to_string(tiles) + " 16x16-px tile(s): too few for an interval (at least " +
                                std::to_string(kMinIntervalSamples) + "); no part can be told from 0");
    }
    running_ = false;
    done_ = true;
}

void ErrorAttribution::checkMetricAndBuffer(const std::string& metric, const std::string& buffer) {
    if (metric != "flip" && metric != "rms")
        throw Error("--attribute needs an error metric whose parts subtract: flip or rms, got '" + metric + "'");
    TradeoffRunner::gpuOutput(buffer);
}

ErrorAttribution::ErrorAttribution(AttributionOptions options) : o_(std::move(options)) {
    checkMetricAndBuffer(o_.metric, o_.buffer);
    if (o_.resamples < 1) throw Error("--resamples must be at least 1");
    o_.run.validate();
    scene_ = loadScene(o_.run.sceneSpec());
}

AttributionResult ErrorAttribution::run(const TradeoffReference& reference,
                                        const std::function<void(const std::string&)>& say) {
    RenderSession session;
    session.setScene(scene_, o_.run);
    session.resize(o_.run.width, o_.run.height);
    FloatImage truth = reference(scene_, session.knobs(), session.camera(), o_.run.width, o_.run.height, o_.buffer);
    AttributionRun run;
    run.start(session.knobs(), scene_, std::move(truth), o_.metric, o_.buffer, o_.resamples);
    for (int n = 1; run.running(); ++n) {
        if (say) say("tradeoff --attribute: configuration " + std::to_string(n) + " of " + std::to_string(run.configurations()));
        run.step(session);
    }
    if (!run.error().empty()) throw Error(run.error());
    return run.result();
}

std::string ErrorAttribution::table(const AttributionResult& r) {
    std::ostringstream out;
    out << "Where the " << r.metric << " error of `" << r.buffer << "` comes from (" << r.width << "x" << r.height
        << ", against the CPU reference; 95% intervals, paired over 16x16-px tiles):\n\n";
    out << "| row | error | removed: as_is - only_exact | added: only_approximate - all_exact |\n";
    out << "| --- | --- | --- | --- |\n";
    out << "| as_is | " << withInterval(r.asIs.value, r.asIs.low, r.asIs.high) << " | | |\n";
    out << "| all_exact | " << withInterval(r.allExact.value, r.allExact.low, r.allExact.high) << " | | |\n";
    for (const AttributionFamily& f : r.families) {
        auto part = [](const ErrorDifference& d) {
            if (d.value == 0.0 && d.low == 0.0 && d.high == 0.0) return std::string("0 (the same image)");
            return withInterval(d.value, d.low, d.high) + (holdsZero(d) ? " (cannot be told from 0)" : "");
        };
        out << "| " << f.name << " | only exact " << withInterval(f.onlyExact.value, f.onlyExact.low, f.onlyExact.high)
            << "; only approximate "
            << withInterval(f.onlyApproximate.value, f.onlyApproximate.low, f.onlyApproximate.high) << " | "
            << part(f.removed) << " | " << part(f.added) << " |\n";
    }
    out << "\ntotal (as_is - all_exact): " << withInterval(r.total.value, r.total.low, r.total.high)
        << "; the parts sum to " << number(r.sumRemoved) << " removed and " << number(r.sumAdded) << " added";
    if (r.total.value != 0.0 && std::isfinite(r.total.value))
        out << " (" << number(100.0 * r.sumRemoved / r.total.value) << "% and " << number(100.0 * r.sumAdded / r.total.value)
            << "% of the total: approximations interact, so the parts need not add up)";
    out << "\n";
    for (const std::string& n : r.notes) out << "note: " << n << "\n";
    return out.str();
}

std::string ErrorAttribution::csv(const AttributionResult& r) {
    std::ostringstream out;
    out << "row,metric,buffer,error,error_lo,error_hi,only_exact,only_exact_lo,only_exact_hi,only_approximate,"
           "only_approximate_lo,only_approximate_hi,removed,removed_lo,removed_hi,added,added_lo,added_hi,sets\n";
    auto e3 = [](const ErrorEstimate& e) { return csvNumber(e.value) + "," + csvNumber(e.low) + "," + csvNumber(e.high); };
    auto d3 = [](const ErrorDifference& d) { return csvNumber(d.value) + "," + csvNumber(d.low) + "," + csvNumber(d.high); };
    out << "as_is," << r.metric << "," << r.buffer << "," << e3(r.asIs) << ",,,,,,,,,,,,,\n";
    out << "all_exact," << r.metric << "," << r.buffer << "," << e3(r.allExact) << ",,,,,,," << d3(r.total) << ",,,,\n";
    for (const AttributionFamily& f : r.families) {
        std::string sets;
        for (const auto& s : f.exact) sets += (sets.empty() ? "" : " ") + s;
        out << f.name << "," << r.metric << "," << r.buffer << ",,,," << e3(f.onlyExact) << "," << e3(f.onlyApproximate)
            << "," << d3(f.removed) << "," << d3(f.added) << ",\"" << sets << "\"\n";
    }
    return out.str();
}

}  // namespace dw

#pragma once
// The points a `tradeoff` run measures. Axes are knobs (as --set takes
// them), "preset" (a preset's knobs under the run's --set) or the camera's
// clip planes "camera.near" / "camera.far" (scene fields, not knobs).
//   grid          every combination, the last axis fastest (--sweep, --presets);
//   one at a time every axis varies alone while the others hold their centre
//                 value (--knobs speed/quality): the centre point first, then
//                 each axis' other values in order;
//   listed        the points one by one (tradeoff --study: each study's own
//                 grid, TradeoffStudies), with the label axis "study" naming
//                 each point's study (not applied to the renderer).
// Points are numbered before --exclude leaves some out, so a number means the
// same point in every shard and after a merge. Needs no GL.
#include <string>
#include <vector>

#include "renderer/bench/BenchGrid.h"
#include "renderer/bench/GridExclusion.h"
#include "renderer/knobs/KnobRegistry.h"

namespace dw {

struct TradeoffAxis {
    std::string name;
    // As the CSV writes them. TradeoffRunner writes each knob value as the
    // knob writes it and each clip plane as %.6g (once, when it checks them).
    std::vector<std::string> values;
    // Each value as a run applies it, read once from its written text by
    // TradeoffRunner: a knob axis the knob's value (KnobRegistry::set; an
    // enum's choice number, a bool 0 or 1), a clip plane its distance in
    // scene units. Empty for "preset" (a value is the preset's name) and
    // before TradeoffRunner has read them.
    std::vector<double> numbers;
};

struct TradeoffPoint {
    int index = 0;
    std::vector<std::string> values;  // one per axis
    std::vector<size_t> at;           // one per axis: the value's position in the axis' values (and numbers)
};

class TradeoffSweep {
public:
    std::vector<TradeoffAxis> axes;
    bool oneAtATime = false;
    std::vector<std::string> centre;  // one per axis, for oneAtATime
    GridExclusion exclusion;
    // Not empty: the points in this order, each one's value position per axis
    // (neither grid nor one at a time).
    std::vector<std::vector<size_t>> listed;

    static bool isCameraAxis(const std::string& name) { return name == "camera.near" || name == "camera.far"; }
    // The axis naming each point's study (a label, set on nothing).
    static bool isStudyAxis(const std::string& name) { return name == "study"; }
    // An axis that is a knob: not preset, a clip plane or study.
    static bool isKnobAxis(const std::string& name) {
        return name != "preset" && !isCameraAxis(name) && !isStudyAxis(name);
    }

    // Every point, in order, without the excluded ones. Throws Error when
    // there are no axes, or none is left ("the sweep is empty after --exclude").
    std::vector<TradeoffPoint> points() const;
    // How many points before --exclude.
    size_t count() const;

    // --knobs speed/quality: every knob marked as trading speed for quality,
    // one at a time about its value in `current`: a bool both ways, an enum
    // every choice, a number its value x1/4, x1/2, x2, x4 (clamped to its
    // range, whole for an int; its range's quarters when the value is 0).
    static TradeoffSweep aroundCurrent(const KnobRegistry& current);

private:
    std::vector<std::vector<size_t>> gridChoices() const;
    std::vector<std::vector<size_t>> oneAtATimeChoices() const;
    std::vector<std::vector<size_t>> listedChoices() const;
};

}  // namespace dw

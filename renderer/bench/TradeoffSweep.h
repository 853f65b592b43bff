#pragma once
// The points a `tradeoff` run measures. Axes are knobs (as --set takes
// them), "preset" (a preset's knobs under the run's --set) or the camera's
// clip planes "camera.near" / "camera.far" (scene fields, not knobs).
//   grid          every combination, the last axis fastest (--sweep, --presets);
//   one at a time every axis varies alone while the others hold their centre
//                 value (--knobs speed/quality): the centre point first, then
//                 each axis' other values in order.
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

    static bool isCameraAxis(const std::string& name) { return name == "camera.near" || name == "camera.far"; }

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
};

}  // namespace dw

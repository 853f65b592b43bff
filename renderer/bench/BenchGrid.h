#pragma once
// The configurations `bench` measures: every combination of the render sizes,
// the light counts and the values of each swept knob, in one fixed order
// (size outermost, then lights, then the knob axes as given, the last one
// fastest), numbered from 0. The number travels with every sample, so shards
// of the grid (BenchShard) merge back into the grid they came from. Needs no GL.
#include <string>
#include <utility>
#include <vector>

namespace dw {

struct BenchKnobAxis {
    std::string knob;                 // a knob's name ("lighting.strategy")
    std::vector<std::string> values;  // as --set takes them, in the order given (BenchRunner: as the knob writes them)
    // Each value as KnobRegistry::set takes it, read once from its text by
    // BenchRunner (KnobAssignment); empty before.
    std::vector<double> numbers;
};

struct BenchConfig {
    int index = 0;  // in the full grid
    int width = 0, height = 0;
    int lights = 0;                       // point lights generated (or the scene's own count)
    std::vector<std::string> knobValues;  // one per knob axis
    std::vector<size_t> knobAt;           // one per knob axis: the value's position in its values (and numbers)
    std::string size() const { return std::to_string(width) + "x" + std::to_string(height); }
};

// A slice of the grid for one process (--shard i/n): the comparison groups
// (BenchGrid::groupsAlong the baseline's axis) whose number % n == i, so
// every configuration is run in the same process as the one it is compared with.
struct BenchShard {
    int index = 0, count = 1;
    bool takes(int group) const { return group % count == index; }
    bool whole() const { return count == 1; }
    // "i/n" with 0 <= i < n; throws dw::Error otherwise.
    static BenchShard parse(const std::string& text);
};

class BenchGrid {
public:
    std::vector<std::pair<int, int>> sizes;  // width, height
    std::vector<int> lights;                 // light counts; empty: the scene's own lights
    std::vector<BenchKnobAxis> knobAxes;

    // Every configuration; `sceneLights` stands in for the light count when
    // `lights` is empty.
    std::vector<BenchConfig> configs(int sceneLights = 0) const;
    size_t count() const;
    // Comparison groups: configurations that differ only on `axis` ("size",
    // "lights" or a knob axis; empty: none) share a group. Groups are numbered
    // in the order they first appear; the result has one number per config.
    std::vector<int> groupsAlong(const std::vector<BenchConfig>& configs, const std::string& axis) const;
    // "knob=a,b,c" -> an axis (the values are checked against the knob later:
    // the runners read each value once and carry it typed to the CSV).
    static BenchKnobAxis parseSweep(const std::string& text);
    // What parseSweep checks of an axis however it was made (the Python
    // module's sweep dicts): a name, values, none empty, none twice. Throws
    // dw::Error naming the axis.
    static void checkAxis(const BenchKnobAxis& axis);
};

// "a,b,c" -> {"a", "b", "c"}; empty items are errors (named by `what`).
std::vector<std::string> splitList(const std::string& text, const std::string& what);

}  // namespace dw

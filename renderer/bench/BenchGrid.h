#pragma once
// The configurations `bench` measures: every combination of the render sizes,
// the light counts and the values of each swept knob, in one fixed order
// (size outermost, then lights, then the knob axes as given, the last one
// fastest), numbered from 0. The number travels with every sample, so shards
// of the grid (--shard i/n: the configurations whose number % n == i) merge
// back into the grid they came from. Needs no GL.
#include <string>
#include <utility>
#include <vector>

namespace dw {

struct BenchKnobAxis {
    std::string knob;                 // a knob's name ("lighting.strategy")
    std::vector<std::string> values;  // as --set takes them, in the order given
};

struct BenchConfig {
    int index = 0;  // in the full grid
    int width = 0, height = 0;
    int lights = 0;                       // point lights generated (or the scene's own count)
    std::vector<std::string> knobValues;  // one per knob axis
    std::string size() const { return std::to_string(width) + "x" + std::to_string(height); }
};

struct BenchShard {
    int index = 0, count = 1;
    bool takes(int config) const { return config % count == index; }
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
    // "knob=a,b,c" -> an axis (the values are checked against the knob later).
    static BenchKnobAxis parseSweep(const std::string& text);
};

// "a,b,c" -> {"a", "b", "c"}; empty items are errors (named by `what`).
std::vector<std::string> splitList(const std::string& text, const std::string& what);

}  // namespace dw

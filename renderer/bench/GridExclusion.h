#pragma once
// --exclude for bench and tradeoff: corners of a grid not worth running
// (fullscreen at 10 000 lights). Each --exclude is one corner,
//   axis=value[,value...][,axis=value[,value...]]...
// an item without '=' adds a value to the axis before it; a configuration is
// left out when, on every axis the corner names, its value is one of the
// corner's values. So `--exclude lighting.strategy=fullscreen,lights=10000`
// drops one corner, `--exclude ssao.samples=4,8` two slices. Needs no GL.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace dw {

class GridExclusion {
public:
    using Axes = std::vector<std::pair<std::string, std::vector<std::string>>>;  // name -> values, in order

    // One --exclude text. Throws dw::Error on syntax ("axis=value" expected, an empty item).
    void add(const std::string& text);
    bool empty() const { return corners_.empty(); }

    // Checks each named axis and value against the grid's axes, writing each
    // value as `canonical(axis, value)` first (how the knob writes it; may
    // throw Error for a bad value). Throws Error naming the --exclude, and
    // the axes or values there are, for an axis or value the grid does not have.
    void resolve(const Axes& axes, const std::function<std::string(const std::string&, const std::string&)>& canonical = {});

    // Whether the configuration whose value on an axis is valueOf(axis) is left out.
    bool excludes(const std::function<std::string(const std::string&)>& valueOf) const;

private:
    struct Corner {
        std::string text;
        std::vector<std::pair<std::string, std::vector<std::string>>> conditions;
    };
    std::vector<Corner> corners_;
};

}  // namespace dw

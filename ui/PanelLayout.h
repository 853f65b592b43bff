#pragma once
// The workbench's panel arrangement (Dear ImGui 1.86 has no docking): three
// columns (scene/lights/presets | viewport over timings and probe |
// inspector/parameters/messages), each split into rows, each row into panels
// side by side. Every size is a weight of its parent, so the arrangement
// follows the window at any size: arrange() partitions the area below the
// menu bar exactly, panels never overlap and never leave the window. Closed
// panels give their room to their neighbours. The gaps between panels are
// splitters the user drags (drag()); the weights are saved as JSON.
//
// No ImGui here: the arithmetic is tested on its own (tests/gui).
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace dw::ui {

struct PanelRect {
    float x = 0, y = 0, w = 0, h = 0;  // window pixels, y down
};

class PanelLayout {
public:
    static constexpr float kGap = 5.0f;          // splitter thickness, px
    static constexpr float kMinWidth = 150.0f;   // smallest panel, px, where the window has room
    static constexpr float kMinHeight = 70.0f;

    PanelLayout() { reset(); }
    // The default arrangement.
    void reset();

    struct Placed {
        std::string panel;
        PanelRect rect;
    };
    // A gap between two neighbours: dragging it moves weight from one to the other.
    struct Splitter {
        PanelRect rect;
        bool vertical = false;  // a vertical bar, dragged left/right
        // The first of the two neighbours (row, item -1: the splitter is at a
        // coarser level), and the second one's index at that level.
        int column = -1, row = -1, item = -1, next = -1;
        float firstSize = 0, secondSize = 0;  // the neighbours' sizes along the drag, px
        float firstMin = 0, secondMin = 0;    // and the least each may have
    };
    struct Arrangement {
        std::vector<Placed> panels;
        std::vector<Splitter> splitters;
        const PanelRect* find(const std::string& panel) const;
    };
    // The open panels (isOpen(name)) in the area x in [0, width), y in [top, height).
    Arrangement arrange(float width, float height, float top, const std::function<bool(const std::string&)>& isOpen) const;
    // Moves `s` by `delta` px (x for a vertical bar, y otherwise), keeping
    // both neighbours at least the minimum size where the window has room.
    // `s` comes from the arrangement of the frame the drag happens in.
    void drag(const Splitter& s, float delta);

    // Every panel name the layout places, in column/row/item order.
    std::vector<std::string> panels() const;

    nlohmann::json toJson() const;
    // Reads a saved layout (toJson's, or an older version's): every weight
    // that has a place in this version is taken, the rest stays the default
    // (a panel added since keeps its default width beside the saved ones).
    // Returns what was dropped, one line each naming where (columns[1].rows[0]...):
    // weights that are not positive numbers, columns, rows or panels this
    // version does not have; empty when everything was used. Throws
    // std::runtime_error, the layout unchanged, when `j` is not an object with
    // a "columns" array.
    std::vector<std::string> fromJson(const nlohmann::json& j);

private:
    struct Row {
        std::vector<std::string> panels;
        std::vector<float> widths;
        float height = 1.0f;
    };
    struct Column {
        std::vector<Row> rows;
        float width = 1.0f;
    };
    std::vector<Column> columns_;
};

}  // namespace dw::ui

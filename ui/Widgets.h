#pragma once
// Small ImGui helpers shared by the panels.
#include <imgui.h>

#include <map>
#include <string>
#include <vector>

namespace dw::ui {

// ImGui texture id for a GL texture name.
inline ImTextureID textureId(unsigned name) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(name)); }
// Shows a GL texture (rows bottom-up) the right way up.
void image(unsigned texture, ImVec2 size);
void helpMarker(const std::string& text);
// ImGui::Begin for a panel of the workbench layout (PanelLayout): the layout
// places and sizes it every frame, so it is neither moved nor resized by hand
// (the gaps between panels are the splitters) nor saved in imgui.ini.
bool beginPanel(const char* title, bool* open, ImGuiWindowFlags extra = 0);
// A text field whose buffer follows every keystroke (so a button beside it
// sees what was typed; ImGuiInputTextFlags_EnterReturnsTrue would hold the
// text back until Enter), returning true when Enter ends the edit.
bool inputTextEnter(const char* label, const char* hint, char* buffer, size_t size, int flags = 0);
// SameLine when an item `width` px wide still fits on this line, else a new line.
void sameLineIfFits(float width);
// Text cut to `width` px with "..." and the whole text as a tooltip when cut.
void clippedText(const std::string& text, float width);
// ImGui::SetTooltip that stays inside the window: the text wraps at 45 em or
// the window's width less a margin, whichever is less (ImGui keeps a tooltip
// inside the display only when it is narrower than the display; one long line,
// such as the A/B numbers whole, ran off the window's edge).
void tooltip(const char* format, ...) IM_FMTARGS(1);
// `name` in lines of at most `width` px, broken after '_' or '.' where it has
// to be (then anywhere), so a long knob or output name is read whole in a
// narrow column instead of cut ("directional_in_gb").
std::vector<std::string> breakName(const std::string& name, float width);
// A number in a table cell, right-aligned, with `decimals` fixed decimals.
void numberCell(double value, int decimals = 3);
// Text that wraps, in a colour, for errors and reasons.
void wrappedColored(const ImVec4& color, const std::string& text);
// Named items for --layout-out and the GUI tests: noteItem(name) records
// where the last item was drawn (screen pixels) and the frame it was drawn in,
// and the window it lies in; drawnItems() lists them.
struct DrawnItem {
    float x = 0, y = 0, w = 0, h = 0;
    int frame = -1;      // ImGui::GetFrameCount() when drawn
    std::string window;  // the panel it was drawn in
    // The visible part of the panel that holds it (its clip rectangle then).
    float clipX = 0, clipY = 0, clipW = 0, clipH = 0;
};
void noteItem(const std::string& name);
// The same for a rectangle that is not an item (a table cell's room).
void noteRect(const std::string& name, ImVec2 min, ImVec2 max);
const std::map<std::string, DrawnItem>& drawnItems();
extern const ImVec4 kErrorColor;
extern const ImVec4 kDimColor;
extern const ImVec4 kOkColor;

}  // namespace dw::ui

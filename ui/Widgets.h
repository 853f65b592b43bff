#pragma once
// Small ImGui helpers shared by the panels.
#include <imgui.h>

#include <string>

namespace dw::ui {

// ImGui texture id for a GL texture name.
inline ImTextureID textureId(unsigned name) { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(name)); }
// Shows a GL texture (rows bottom-up) the right way up.
void image(unsigned texture, ImVec2 size);
void helpMarker(const std::string& text);
// Text that wraps, in a colour, for errors and reasons.
void wrappedColored(const ImVec4& color, const std::string& text);
extern const ImVec4 kErrorColor;
extern const ImVec4 kDimColor;
extern const ImVec4 kOkColor;

}  // namespace dw::ui

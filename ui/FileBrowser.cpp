#include "ui/FileBrowser.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "ui/Widgets.h"

namespace dw::ui {

namespace fs = std::filesystem;

void FileBrowser::open(const std::string& start) {
    std::error_code ec;
    fs::path p = start.empty() ? fs::current_path(ec) : fs::absolute(start, ec);
    while (!p.empty() && !fs::is_directory(p, ec) && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
    if (p.empty() || !fs::is_directory(p, ec)) p = fs::current_path(ec);
    folder = p.lexically_normal().string();
    error.clear();
    listed_.clear();
    requestOpen = true;
}

std::vector<FileBrowser::Entry> FileBrowser::list(const std::string& folder, const std::vector<std::string>& extensions,
                                                  std::string& error) {
    std::vector<Entry> folders, files;
    std::error_code ec;
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        error = "cannot list " + folder + ": " + ec.message();
        return {};
    }
    error.clear();
    for (const auto& e : it) {
        const std::string name = e.path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code fe;
        if (e.is_directory(fe)) {
            folders.push_back({name, true});
            continue;
        }
        std::string ext = e.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) files.push_back({name, false});
    }
    auto byName = [](const Entry& a, const Entry& b) { return a.name < b.name; };
    std::sort(folders.begin(), folders.end(), byName);
    std::sort(files.begin(), files.end(), byName);
    folders.insert(folders.end(), files.begin(), files.end());
    return folders;
}

std::optional<std::string> FileBrowser::draw(const char* id, const std::vector<std::string>& extensions) {
    if (requestOpen) {
        ImGui::OpenPopup(id);
        requestOpen = false;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowSize(ImVec2(std::min(560.0f, display.x * 0.8f), std::min(420.0f, display.y * 0.7f)), ImGuiCond_Appearing);
    std::optional<std::string> picked;
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_NoSavedSettings)) return picked;
    ImGui::TextWrapped("%s", folder.c_str());
    if (ImGui::SmallButton("up")) {
        const fs::path parent = fs::path(folder).parent_path();
        if (!parent.empty()) folder = parent.string();
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("working folder")) {
        std::error_code ec;
        folder = fs::current_path(ec).string();
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("cancel")) ImGui::CloseCurrentPopup();
    if (listed_ != folder) {
        entries_ = list(folder, extensions, error);
        listed_ = folder;
    }
    const std::vector<Entry> entries = entries_;
    if (!error.empty()) wrappedColored(kErrorColor, error);
    ImGui::BeginChild("##entries", ImVec2(0, 0), true);
    std::string enter;
    for (const Entry& e : entries) {
        const std::string label = e.folder ? e.name + "/" : e.name;
        if (ImGui::Selectable(label.c_str())) {
            if (e.folder) enter = (fs::path(folder) / e.name).string();
            else picked = (fs::path(folder) / e.name).string();
        }
    }
    if (entries.empty() && error.empty()) ImGui::TextDisabled("(no folders or scene files here)");
    ImGui::EndChild();
    if (!enter.empty()) folder = enter;
    if (picked) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return picked;
}

}  // namespace dw::ui

#pragma once
// A small file browser for opening scenes: a popup listing one folder's
// sub-folders and the files with the given extensions; a click on a folder
// enters it, a click on a file picks it. No state outside the struct.
#include <optional>
#include <string>
#include <vector>

namespace dw::ui {

struct FileBrowser {
    std::string folder;   // the folder listed (absolute)
    std::string error;    // why the folder could not be listed
    bool requestOpen = false;

    // Opens the popup next frame at `start`'s folder (a file's folder, or the
    // working directory when `start` is empty or names no folder).
    void open(const std::string& start);
    // Draws the popup `id` when open; the picked file's path, once.
    std::optional<std::string> draw(const char* id, const std::vector<std::string>& extensions);

    struct Entry {
        std::string name;
        bool folder = false;
    };
    // `folder`'s sub-folders, then its files with one of `extensions`
    // (lower case, with the dot), each group sorted by name; hidden entries left out.
    static std::vector<Entry> list(const std::string& folder, const std::vector<std::string>& extensions, std::string& error);

private:
    // The listing of `listed_`, read again when the folder changes or the popup opens.
    std::string listed_;
    std::vector<Entry> entries_;
};

}  // namespace dw::ui

#pragma once
// Reference renders kept on disk, keyed by a hash of everything that changes
// them (DESIGN.md "References are cached by a hash of everything that changes
// them"): the scene's content (meshes, instances, materials, images, lights,
// ambient, sky), the camera, the size, the model (ReferenceModel::canonical,
// which holds the AO ray count and seed) and the reference's version. A sweep
// then renders each reference once.
//
// Where: $DW_REFERENCE_CACHE, else $XDG_CACHE_HOME/deferred-workbench/reference,
// else ~/.cache/deferred-workbench/reference. Each entry is one EXR per
// buffer plus a JSON file of the statistics, written to temporary names and
// renamed, so an interrupted write leaves no entry.
#include <filesystem>
#include <optional>
#include <string>

#include "renderer/reference/ReferenceRenderer.h"

namespace dw::reference {

// Bumped whenever the reference's output changes for the same inputs.
// 2: one RayScene per scene, relative to the scene's centre, shared by every
// camera (issue 33; it was relative to each camera's position).
// 3: entries hold spp_error (samples per pixel, issue 35).
constexpr int kReferenceVersion = 3;

// 16 hex digits.
std::string referenceKey(const Scene& scene, const ReferenceModel& model, const ReferenceRequest& request);
// 16 hex digits over what a RayScene is built from and its queries read (the
// meshes, instances, materials and images): scenes with equal keys share one
// RayScene (RaySceneCache).
std::string sceneGeometryKey(const Scene& scene);

class ReferenceCache {
public:
    // `directory` empty: the default location above.
    explicit ReferenceCache(std::filesystem::path directory = {});
    const std::filesystem::path& directory() const { return directory_; }
    // The entry for `key`, or nothing (absent or unreadable: a damaged entry is a miss).
    std::optional<ReferenceImages> load(const std::string& key) const;
    // Throws FileError when the directory cannot be written.
    void store(const std::string& key, const ReferenceImages& images) const;

    static std::filesystem::path defaultDirectory();

private:
    std::filesystem::path directory_;
};

}  // namespace dw::reference

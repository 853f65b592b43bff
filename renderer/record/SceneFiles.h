#pragma once
// The files a scene reads, for the experiment records: the scene file; for a
// scene JSON every glTF its objects name and the sky's image files; for each
// glTF (.gltf) its external .bin buffers and images (data: URIs are inside
// the file already); and every image the loaded scene names. Each once, with
// the sha256 of its content; a built-in scene's content by its hash. Needs no GL.
// A glTF the scene's loader read is not parsed again: its parts come from the
// loader's parse (Scene::gltfExternalUris); only its bytes are read, to hash.
#include <string>
#include <vector>

#include "renderer/record/RecordedFile.h"
#include "renderer/scene/Scene.h"

namespace dw {


// Hex sha256 of bytes (OpenSSL's EVP).
std::string sha256Hex(const void* data, size_t size);
// "" when the file cannot be read (a device, or more than kBinaryFileLimit bytes).
std::string sha256OfFile(const std::string& path);

// The files `scene` read, each with its current sha256; for a built-in scene
// first an entry named by its source ("builtin:default") with the sha256 of
// its content (renderer/record/SceneContent), so a built-in that a new build
// generates differently replays as "scene file changed: builtin:default".
std::vector<RecordedFile> sceneFilesOf(const Scene& scene);
// A list entry that stands for a built-in scene's content ("builtin:NAME"), not a file.
bool isBuiltinSceneContent(const std::string& path);

// A difference between the files a record lists and those its scene reads now.
struct SceneFileChange {
    enum class Kind { Changed, Added, Removed };
    Kind kind = Kind::Changed;
    std::string path;                // the file now (Changed, Added), as recorded (Removed)
    std::string oldSha256, newSha256;  // empty where that side has none (or could not read it)
};

// `recorded`: a record's list, the files of the scene `recordedScene`;
// `now`: sceneFilesOf the scene loaded now from `nowScene`. Files match by
// their path relative to their scene file's folder (a scene folder moved with
// its record still matches). Reads no file: `now` holds the hashes, and a
// path only the record names is reported, never opened.
std::vector<SceneFileChange> compareSceneFiles(const std::vector<RecordedFile>& recorded, const std::string& recordedScene,
                                               const std::vector<RecordedFile>& now, const std::string& nowScene);

}  // namespace dw

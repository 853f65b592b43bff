#pragma once
// The files a scene reads, for the experiment records: the scene file; for a
// scene JSON every glTF its objects name and the sky's image files; for each
// glTF (.gltf) its external .bin buffers and images (data: URIs are inside
// the file already); and every image the loaded scene names. Each once, with
// the sha256 of its content. Needs no GL.
#include <string>
#include <vector>

#include "renderer/scene/Scene.h"

namespace dw {

struct RecordedFile;

// Hex sha256 of bytes (OpenSSL's EVP).
std::string sha256Hex(const void* data, size_t size);
// "" when the file cannot be read.
std::string sha256OfFile(const std::string& path);

// The files `scene` read, each with its current sha256.
std::vector<RecordedFile> sceneFilesOf(const Scene& scene);

}  // namespace dw

#pragma once
// An experiment record (issue 24): one JSON that holds what made a
// measurement, so `replay` can restore exactly that state, measure again and
// say what changed. Version 1 is written by `render --record FILE`:
//   scene    the spec (--scene), its source, and the sha256 of every file it
//            reads that the scene names (the scene file, image files, the
//            environment map; a glTF's .bin buffers are not listed yet)
//   camera   position, target, up, field of view, clip planes
//   knobs    every knob's value as --set takes it
//   size, frames, warmup, buffer
//   build    version, commit at configure time, compiler, build type
//   gl       vendor, renderer, version, EGL platform; host: CPU, threads, OS
//   results  per timing series the counted frames' GPU and CPU ms, and the
//            sha256 of the buffer's pixels as written (8-bit display values
//            for .png outputs, raw float32 otherwise) with its shape
// Read through the JSON nesting guard (readJsonFile). A record of a newer
// version than this build knows is refused with its version named.
#include <string>
#include <utility>
#include <vector>

#include "renderer/RenderSession.h"
#include "renderer/RunConfig.h"

namespace dw {

using RecordFields = std::vector<std::pair<std::string, std::string>>;

struct RecordedFile {
    std::string path, sha256;  // sha256 empty: the file could not be read
};

struct RecordedSeries {
    std::string name;  // a pass, a span ("lighting/shadow maps") or "frame"
    std::vector<double> gpuMs, cpuMs;  // one per counted frame
};

struct ExperimentRecord {
    static constexpr int kVersion = 1;
    int version = kVersion;
    std::string command = "render";
    std::string sceneSpec, sceneSource;
    std::vector<RecordedFile> sceneFiles;
    Camera camera;
    RecordFields knobs;
    int width = 0, height = 0, frames = 1, warmup = 0;
    std::string buffer = "final";
    RecordFields build, gl, host;
    std::vector<RecordedSeries> timings;
    std::string imageSha256;
    int imageWidth = 0, imageHeight = 0, imageChannels = 0;

    // After a run of `run` in `session` whose counted frames start at
    // `firstCounted` (waits for the timer's outstanding frames).
    static ExperimentRecord capture(RenderSession& session, const RunConfig& run, const std::string& buffer,
                                    std::uint64_t firstCounted, const std::string& glPlatform);
    std::string json() const;
    // Throws FileError naming the file and what is wrong (a newer version, a missing field).
    static ExperimentRecord read(const std::string& path);
    void write(const std::string& path) const;

    // The files a scene reads that it names, each with its current sha256.
    static std::vector<RecordedFile> hashSceneFiles(const Scene& scene);
    // sha256 of `buffer` as written: display bytes or raw floats; sets the shape.
    static std::string hashBuffer(RenderSession& session, const std::string& buffer, int& width, int& height,
                                  int& channels);
    static std::string sha256(const void* data, size_t size);
    static std::string sha256OfFile(const std::string& path);  // "" when unreadable
    static RecordFields buildFields();
};

}  // namespace dw

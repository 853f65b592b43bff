#pragma once
// The shader files a run compiled, for the experiment records: the renderer
// reads shaders/ at run time (F5 and hot reload), so those files are inputs
// of a measurement as the scene's are. The list comes from the shader layer
// itself (gl::ShaderLibrary::compiled(): every stage file and everything it
// #includes, params/ headers too), never from a glob of the folder; each
// file's sha256 is of the text it compiled. Paths are relative to the shader
// folder ("ssao/ssao.frag"); a file outside it keeps its absolute path.
// Needs no GL.
#include <string>
#include <vector>

#include "renderer/gl/CompiledShaders.h"
#include "renderer/record/RecordedFile.h"

namespace dw {

struct SceneFileChange;

struct RecordedShaders {
    bool present = false;  // false: a record written before shader hashes (no "shaders" field)
    std::string folder;    // the shader folder the run used (absolute)
    std::vector<RecordedFile> files;  // sorted by path
};

// The files `compiled` holds, each with the sha256 of the text it compiled.
RecordedShaders shaderFilesOf(const gl::CompiledShaders& compiled);

// `recorded`: a record's list; `now`: shaderFilesOf what the replay compiled
// from `nowFolder`. Files match by their path relative to their folder. A
// recorded file the replay did not compile (the window compiles programs a
// headless run does not) is looked up in `nowFolder`: a regular file there
// is hashed (changed when its sha256 differs), none there is Removed. A
// compiled file the record lacks is Added. Paths with ".." or absolute ones
// from the record are never opened: Removed unless compiled now.
std::vector<SceneFileChange> compareShaderFiles(const RecordedShaders& recorded, const RecordedShaders& now);

}  // namespace dw

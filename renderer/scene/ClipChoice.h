#pragma once
// Which animation clip plays (issue 36): --animation NAME|INDEX|none on
// render, bench, tradeoff and reference (RunConfig::animation), records'
// "animation", the window's timeline. Applied to a loaded scene before it is
// posed. Needs no GL.
//   ""    each glTF file plays its first animation (the default);
//   none  no clip plays: skins and morph targets at the nodes' own
//         transforms and weights;
//   INDEX a clip by its index over the scene's clips (0-based, in file order,
//         `list` of the window's timeline shows them);
//   NAME  the first clip of that glTF animation name.
// The chosen clip plays in place of its file's first; other files (a scene
// JSON importing several) keep theirs. Throws Error, one line naming the
// scene's clips, for an index out of range or a name none has (or any
// choice but none on a scene without clips).
#include <string>

namespace dw {

struct SceneAnimation;

void chooseClip(SceneAnimation& anim, const std::string& spec);

// The --animation that gives the first file's current choice (the window's
// timeline, for its records): "" when it plays its first clip (or the scene
// has none), "none" when it plays none, else the clip's index.
std::string clipChoiceOf(const SceneAnimation& anim);

// "0 'move', 1 'idle'" (or "none" without clips): what chooseClip's errors list.
std::string clipList(const SceneAnimation& anim);

}  // namespace dw

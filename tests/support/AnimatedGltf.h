#pragma once
// A small animated glTF for the animation tests (issue 36), written as JSON
// with a base64 buffer: a skinned quad and a morphed quad, animated.
//  - nodes: 0 the skinned quad (skin 0), 1 the root bone, 2 the tip bone
//    (child of 1 at (0, 1, 0)), 3 the morphed quad at (3, 0, 0);
//  - mesh 0: the unit quad (0,0,0) (1,0,0) (1,1,0) (0,1,0), normals +Z;
//    the bottom vertices weight joint 0 alone, the top ones joints 0 and 1
//    by 0.5 each; inverse bind matrices: identity, translate(0, -1, 0);
//  - mesh 1: the same quad with one morph target moving every vertex by
//    (0, 0, 1) and its normal by (1, 0, 0); default weight 0.25;
//  - animation 0 "move": node 1 translation LINEAR (0,0,0) at 0 s to
//    (2,0,0) at 1 s; node 2 rotation LINEAR identity at 0 s to 90 degrees
//    about +Z at 1 s; node 3 weights STEP 0 at 0 s, 1 at 0.25 s.
// At t = 0.5 the vertex (1,1,0) of the skinned quad is at
// 0.5 (2, 1, 0) + 0.5 (1 + cos 45, 1 + sin 45, 0) = (1.85355, 1.35355, 0).
#include <nlohmann/json.hpp>

namespace dw::test {

// `withAnimation` false: the same file without animations (default weights).
nlohmann::json animatedGltf(bool withAnimation = true);

}  // namespace dw::test

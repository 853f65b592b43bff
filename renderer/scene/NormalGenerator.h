#pragma once
// Vertex normals for glTF primitives that have none or whose normals are
// broken. glTF 2.0 (3.7.2.1): "When normals are not specified, client
// implementations MUST calculate flat normals", so a primitive without NORMAL
// is unwelded (one vertex per triangle corner) and every corner gets its
// triangle's face normal, cross(p1 - p0, p2 - p0) normalised (front faces are
// counter-clockwise). Normals that are present but non-finite or zero are
// repaired with the area-weighted average of the face normals around the
// vertex, which is what the rest of the (smooth) mesh looks like.
// Triangles wound against the normals the file gives (scanned meshes often
// have a few) are turned around by orientTrianglesToNormals, so culling and
// double-sided shading see the side the normals say is the front.
#include <cstddef>
#include <vector>

namespace dw {

struct Mesh;

// Triangle list in; every corner its own vertex, normal = face normal.
// Triangles of zero area get (0, 1, 0).
void generateFlatNormals(Mesh& mesh);

// Recomputes the normals of the vertices flagged in `repair` (one flag per
// vertex) from the faces around them; returns how many were repaired.
std::size_t repairNormals(Mesh& mesh, const std::vector<bool>& repair);

// Reverses the winding of every triangle whose face normal points against
// the sum of its three vertex normals, as long as those are a minority of the
// mesh (fewer than half its non-degenerate triangles; a mesh wound against
// its normals throughout is left as the author wrote it). Returns how many
// triangles were reversed.
std::size_t orientTrianglesToNormals(Mesh& mesh);

// Gives every triangle corner whose normal points away from its triangle's
// face normal (more than 90 degrees: a vertex normal averaged across a crease
// that folds back, as in scanned meshes) the face normal instead, on a vertex
// of its own. Otherwise such a triangle, facing the eye, shades as if it faced
// away: isolated dark specks in gbuffer.normal. Returns how many corners.
std::size_t splitCornersFacingAway(Mesh& mesh);

}  // namespace dw

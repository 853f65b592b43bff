#pragma once
// Per-vertex tangent frames from texture coordinates (Lengyel's method:
// per-triangle dP/du accumulated, Gram-Schmidt against the normal, bitangent
// sign in w). Used when a glTF primitive has a normal map but no TANGENT.
namespace dw {

struct Mesh;

void generateTangents(Mesh& mesh);
// Smooth vertex normals from triangle areas, for primitives without NORMAL.
void generateNormals(Mesh& mesh);

}  // namespace dw

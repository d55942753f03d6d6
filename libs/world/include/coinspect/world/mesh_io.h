// Reading meshes through Assimp (binary/ASCII STL, OBJ, PLY, DAE) and writing STL/PLY.
#pragma once

#include <filesystem>

#include "coinspect/world/mesh.h"

namespace coinspect::world {

// Loads every mesh of the file as one TriangleMesh (identical vertices joined), applies
// `transform` and validates the result. Collada files with Z_UP are returned in their authored
// Z-up frame (Assimp would rotate them to Y-up). Throws InputError naming the file on failure.
TriangleMesh loadMesh(const std::filesystem::path& path, const MeshTransform& transform = {});

// Binary STL (facet normals from the vertex order). Throws InputError when unwritable.
void writeStl(const TriangleMesh& mesh, const std::filesystem::path& path);
// Binary little-endian PLY with float vertices and uchar-counted int faces.
void writePly(const TriangleMesh& mesh, const std::filesystem::path& path);

}  // namespace coinspect::world

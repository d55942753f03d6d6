#include "coinspect/world/mesh_io.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cstring>
#include <string>
#include <system_error>
#include <unordered_map>

#include "coinspect/core/error.h"
#include "file_utils.h"
#include "ply_layout.h"

namespace coinspect::world {
namespace {

using detail::putF32;
using detail::putU32;

// A face of no corner (a damaged binary PLY whose face records slipped) passes Assimp's
// validation, and its Triangulate then aborts on an assertion: refuse it first.
void requireCornersOnEveryFace(const aiScene& scene, const std::string& source) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m)
    for (unsigned f = 0; f < scene.mMeshes[m]->mNumFaces; ++f)
      if (scene.mMeshes[m]->mFaces[f].mNumIndices == 0)
        throw InputError(source, "face " + std::to_string(f),
                         "a face with no corner (a damaged file?)");
}

Eigen::Matrix4d toEigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return out;
}

// Key for welding vertices by exact position. Assimp's JoinIdenticalVertices also compares
// normals and texture coordinates, so an STL (one normal per facet) would keep three private
// vertices per triangle; welding by position restores the shared edges that validateMesh checks.
struct PositionHash {
  size_t operator()(const Eigen::Vector3f& p) const {
    uint32_t bits[3];
    std::memcpy(bits, p.data(), sizeof bits);
    uint64_t h = 1469598103934665603ull;
    for (const uint32_t b : bits)
      h = (h ^ b) * 1099511628211ull;
    return static_cast<size_t>(h);
  }
};
struct PositionEqual {
  // Bitwise so that -0 and +0 stay apart like any other distinct bit pattern; both are rare and
  // keeping them separate only costs a vertex.
  bool operator()(const Eigen::Vector3f& a, const Eigen::Vector3f& b) const {
    return std::memcmp(a.data(), b.data(), sizeof(float) * 3) == 0;
  }
};

struct Flattener {
  const aiScene& scene;
  TriangleMesh& out;
  std::unordered_map<Eigen::Vector3f, uint32_t, PositionHash, PositionEqual> index;
  std::vector<uint32_t> remap;

  uint32_t weld(const Eigen::Vector3f& p) {
    const auto [it, inserted] = index.emplace(p, static_cast<uint32_t>(out.vertices.size()));
    if (inserted) out.vertices.push_back(p);
    return it->second;
  }

  void visit(const aiNode& node, const Eigen::Matrix4d& parent) {
    const Eigen::Matrix4d world = parent * toEigen(node.mTransformation);
    const Eigen::Matrix3d linear = world.topLeftCorner<3, 3>();
    const Eigen::Vector3d offset = world.topRightCorner<3, 1>();
    // A mirroring node transform turns counter-clockwise facets clockwise: swap two vertices so
    // that normals keep pointing outwards.
    const bool mirrored = linear.determinant() < 0.0;
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
      const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
      remap.assign(mesh.mNumVertices, 0);
      for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        const Eigen::Vector3d x = linear * Eigen::Vector3d(p.x, p.y, p.z) + offset;
        remap[v] = weld(x.cast<float>());
      }
      for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        // Points and lines survive triangulation; they are not surfaces.
        if (face.mNumIndices != 3) continue;
        std::array<uint32_t, 3> t{remap[face.mIndices[0]], remap[face.mIndices[1]],
                                  remap[face.mIndices[2]]};
        if (mirrored) std::swap(t[1], t[2]);
        out.triangles.push_back(t);
      }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c)
      visit(*node.mChildren[c], world);
  }
};

}  // namespace

TriangleMesh loadMesh(const std::filesystem::path& path, const MeshTransform& transform) {
  const std::string source = path.string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError(source, "", "no such mesh file");
  // Cut short, a PLY file makes Assimp's reader hang or pad what is missing (ply_layout.h).
  detail::checkPlyLayout(path, source);

  Assimp::Importer importer;
  // Return Collada Z_UP files in their authored frame: Assimp would otherwise rotate them to
  // Y-up, but every coinspect frame is Z-up.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  // Validation first, then the other steps: on a damaged file (a face index out of range)
  // Triangulate and JoinIdenticalVertices crash the process instead of failing.
  const aiScene* scene = importer.ReadFile(source, aiProcess_ValidateDataStructure);
  if (scene != nullptr && scene->mRootNode != nullptr) {
    requireCornersOnEveryFace(*scene, source);
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  }
  if (scene == nullptr || scene->mRootNode == nullptr) {
    const std::string reason = importer.GetErrorString();
    throw InputError(source, "",
                     "cannot read the mesh" + (reason.empty() ? std::string() : ": " + reason));
  }

  TriangleMesh mesh;
  mesh.name = path.stem().string();
  Flattener flattener{*scene, mesh, {}, {}};
  flattener.visit(*scene->mRootNode, Eigen::Matrix4d::Identity());
  if (mesh.triangles.empty()) throw InputError(source, "", "the file holds no triangles");

  mesh.transform(transform);
  validateMesh(mesh, source);
  return mesh;
}

void writeStl(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::string bytes;
  bytes.reserve(84 + 50 * mesh.triangles.size());
  std::string header = "binary STL written by coinspect: " + mesh.name;
  header.resize(80, ' ');
  // A header starting with "solid" makes some readers take the file for ASCII STL.
  if (header.compare(0, 5, "solid") == 0) header[0] = 'S';
  bytes += header;
  putU32(bytes, static_cast<uint32_t>(mesh.triangles.size()));
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Eigen::Vector3f normal = mesh.facetNormal(i).cast<float>();
    for (int k = 0; k < 3; ++k)
      putF32(bytes, normal[k]);
    for (const uint32_t v : mesh.triangles[i])
      for (int k = 0; k < 3; ++k)
        putF32(bytes, mesh.vertices[v][k]);
    bytes.push_back('\0');  // attribute byte count
    bytes.push_back('\0');
  }
  detail::writeWholeFile(path, bytes);
}

void writePly(const TriangleMesh& mesh, const std::filesystem::path& path) {
  std::string bytes =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment written by coinspect\n"
      "element vertex " +
      std::to_string(mesh.vertices.size()) +
      "\n"
      "property float x\n"
      "property float y\n"
      "property float z\n"
      "element face " +
      std::to_string(mesh.triangles.size()) +
      "\n"
      "property list uchar int vertex_indices\n"
      "end_header\n";
  bytes.reserve(bytes.size() + 12 * mesh.vertices.size() + 13 * mesh.triangles.size());
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k)
      putF32(bytes, v[k]);
  for (const auto& t : mesh.triangles) {
    bytes.push_back(3);
    for (const uint32_t v : t)
      putU32(bytes, v);
  }
  detail::writeWholeFile(path, bytes);
}

}  // namespace coinspect::world

// KHR_draco_mesh_compression: a compressed primitive loads as the same triangles as the plain one.
#include <doctest/doctest.h>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "load_scene.h"
#include "loaders/gltf_builder.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A bumpy 4 x 4 grid of quads (32 triangles) with per-corner unit normals.
std::unique_ptr<draco::Mesh> grid_mesh() {
  const int n = 4;
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2 * n * n);
  int position = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  auto point = [](int i, int j) { return std::array<float, 3>{float(i), float(j), 0.25f * float((i * j) % 3)}; };
  auto up = [](int i, int j) {  // unit, as octahedral quantization returns them
    vec3 n = normalize(vec3{0.1f * float(i), 0.1f * float(j), 1});
    return std::array<float, 3>{n.x, n.y, n.z};
  };
  int face = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (auto corners : {std::array<std::array<int, 2>, 3>{{{i, j}, {i + 1, j}, {i + 1, j + 1}}},
                           std::array<std::array<int, 2>, 3>{{{i, j}, {i + 1, j + 1}, {i, j + 1}}}}) {
        auto p0 = point(corners[0][0], corners[0][1]), p1 = point(corners[1][0], corners[1][1]),
             p2 = point(corners[2][0], corners[2][1]);
        auto n0 = up(corners[0][0], corners[0][1]), n1 = up(corners[1][0], corners[1][1]),
             n2 = up(corners[2][0], corners[2][1]);
        builder.SetAttributeValuesForFace(position, draco::FaceIndex(face), p0.data(), p1.data(), p2.data());
        builder.SetAttributeValuesForFace(normal, draco::FaceIndex(face), n0.data(), n1.data(), n2.data());
        ++face;
      }
  return builder.Finalize();
}

// The mesh's points and faces as plain accessors: the uncompressed twin of the Draco file.
std::string plain_gltf(const draco::Mesh& mesh) {
  GltfBuilder b;
  std::vector<float> positions, normals;
  for (uint32_t p = 0; p < mesh.num_points(); ++p) {
    float v[3];
    mesh.GetNamedAttribute(draco::GeometryAttribute::POSITION)->GetMappedValue(draco::PointIndex(p), v);
    positions.insert(positions.end(), v, v + 3);
    mesh.GetNamedAttribute(draco::GeometryAttribute::NORMAL)->GetMappedValue(draco::PointIndex(p), v);
    normals.insert(normals.end(), v, v + 3);
  }
  std::vector<uint16_t> indices;
  for (uint32_t f = 0; f < mesh.num_faces(); ++f)
    for (int c = 0; c < 3; ++c) indices.push_back(uint16_t(mesh.face(draco::FaceIndex(f))[c].value()));
  b.floats(positions, "VEC3", 3);
  b.floats(normals, "VEC3", 3);
  b.indices(indices);
  return b.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2}]}],"
                "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
}

// `mesh` Draco-encoded (edgebreaker, positions quantized to `bits` as exporters do; 0 = lossless
// sequential) in a glTF whose accessors declare `points` and `corners`.
std::string draco_gltf(const draco::Mesh& mesh, int bits, uint32_t points, uint32_t corners, std::string* payload = nullptr) {
  draco::Encoder encoder;
  if (bits > 0) {
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, bits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 12);
  } else {
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
  }
  draco::EncoderBuffer buffer;
  REQUIRE(encoder.EncodeMeshToBuffer(mesh, &buffer).ok());
  std::string bytes(buffer.data(), buffer.size());
  if (payload) bytes = *payload;
  GltfBuilder b;
  int view = b.view(bytes);
  b.accessor(-1, 5126, points, "VEC3");
  b.accessor(-1, 5126, points, "VEC3");
  b.accessor(-1, 5123, corners, "SCALAR");
  int position_id = mesh.GetNamedAttribute(draco::GeometryAttribute::POSITION)->unique_id();
  int normal_id = mesh.GetNamedAttribute(draco::GeometryAttribute::NORMAL)->unique_id();
  return b.gltf("\"extensionsUsed\":[\"KHR_draco_mesh_compression\"],"
                "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"],"
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2,"
                "\"extensions\":{\"KHR_draco_mesh_compression\":{\"bufferView\":" + std::to_string(view) +
                ",\"attributes\":{\"POSITION\":" + std::to_string(position_id) + ",\"NORMAL\":" +
                std::to_string(normal_id) + "}}}}]}],"
                "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"scene\":0");
}

// Each triangle as its three (position, normal) corners, starting at the smallest corner so
// that the winding is kept; the triangles sorted. Comparable whatever order a decoder chose.
using Corner = std::array<float, 6>;
std::vector<std::array<Corner, 3>> triangle_set(const MeshDesc& mesh) {
  std::vector<std::array<Corner, 3>> triangles;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    std::array<Corner, 3> corners;
    for (int c = 0; c < 3; ++c) {
      vec3 p = mesh.positions[mesh.indices[t + c]], n = mesh.normals[mesh.indices[t + c]];
      corners[c] = {p.x, p.y, p.z, n.x, n.y, n.z};
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    triangles.push_back(corners);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

}  // namespace

TEST_CASE("gltf draco: a compressed mesh loads as the same triangles as the uncompressed one") {
  ScratchDir dir("gltf-draco");
  std::unique_ptr<draco::Mesh> mesh = grid_mesh();
  uint32_t points = mesh->num_points(), corners = mesh->num_faces() * 3;
  SceneDesc plain = load_scene(dir.write("plain.gltf", plain_gltf(*mesh)).string());
  REQUIRE(plain.meshes.size() == 1);
  auto expected = triangle_set(plain.meshes[0]);
  REQUIRE(expected.size() == 32);
  // Lossless (sequential): exactly the same corners.
  SceneDesc lossless = load_scene(dir.write("lossless.gltf", draco_gltf(*mesh, 0, points, corners)).string());
  REQUIRE(lossless.meshes.size() == 1);
  CHECK(triangle_set(lossless.meshes[0]) == expected);
  CHECK(lossless.warnings.size() == plain.warnings.size());  // the extension is not "unsupported"
  // Edgebreaker with 14-bit positions (Blender's default): the same triangles within a step of
  // the quantization grid (the extent, 4, over 2^14 - 1), normals within 12-bit octahedral steps.
  SceneDesc quantized = load_scene(dir.write("quantized.gltf", draco_gltf(*mesh, 14, points, corners)).string());
  REQUIRE(quantized.meshes.size() == 1);
  auto decoded = triangle_set(quantized.meshes[0]);
  REQUIRE(decoded.size() == expected.size());
  for (size_t t = 0; t < decoded.size(); ++t)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 6; ++k) CHECK(std::abs(decoded[t][c][k] - expected[t][c][k]) <= (k < 3 ? 4.0f / 16383 : 2e-3f));
}

TEST_CASE("gltf draco: a corrupt stream or counts unlike the accessors' are errors naming the primitive") {
  ScratchDir dir("gltf-draco-errors");
  std::unique_ptr<draco::Mesh> mesh = grid_mesh();
  uint32_t points = mesh->num_points(), corners = mesh->num_faces() * 3;
  // A version 2.2 edgebreaker header declaring 25 vertices and 32 triangles, then garbage.
  std::string garbage = std::string("DRACO\x02\x02\x01\x01\x00\x00\x00\x19\x20", 14) + " not a mesh";
  std::string at = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: ";
  CHECK(load_error(dir, dir.write("corrupt.gltf", draco_gltf(*mesh, 0, points, corners, &garbage)))
            .rfind("corrupt.gltf: " + at + "cannot decode: ", 0) == 0);
  CHECK(load_error(dir, dir.write("points.gltf", draco_gltf(*mesh, 0, points + 1, corners))) ==
        "points.gltf: " + at + "decodes to " + std::to_string(points) + " points, but POSITION has " +
            std::to_string(points + 1));
  // The header's triangle count is checked before the decoder allocates by it.
  CHECK(load_error(dir, dir.write("faces.gltf", draco_gltf(*mesh, 14, points, corners - 3))) ==
        "faces.gltf: " + at + "declares 32 triangles, but the indices accessor has " + std::to_string(corners - 3) +
            " indices");
  CHECK(load_error(dir, dir.write("sequential.gltf", draco_gltf(*mesh, 0, points, corners + 3))) ==
        "sequential.gltf: " + at + "declares 32 triangles, but the indices accessor has " + std::to_string(corners + 3) +
            " indices");
  std::string old_version = std::string("DRACO\x01\x03\x01\x01\x00\x00", 11) + std::string(16, '\0');
  CHECK(load_error(dir, dir.write("version.gltf", draco_gltf(*mesh, 0, points, corners, &old_version))) ==
        "version.gltf: " + at + "Draco bitstream version 1.3 (only 2.2 is read)");
}

TEST_CASE("gltf draco: the header's vertex count is charged to the budget before the decoder allocates by it") {
  ScratchDir dir("gltf-draco-budget");
  std::unique_ptr<draco::Mesh> mesh = grid_mesh();
  uint32_t points = mesh->num_points(), corners = mesh->num_faces() * 3;
  LoadOptions limited;
  limited.max_memory_bytes = size_t(64) << 20;
  std::string at = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: ";
  // Sequential headers declaring 32 triangles and then 2^31 - 1 points (varint FF FF FF FF 07),
  // or edgebreaker ones declaring as many encoded vertices, then no mesh.
  std::string sequential = std::string("DRACO\x02\x02\x01\x00\x00\x00\x20\xFF\xFF\xFF\xFF\x07", 17) + " no mesh";
  std::string edgebreaker = std::string("DRACO\x02\x02\x01\x01\x00\x00\x00\xFF\xFF\xFF\xFF\x07\x20", 18) + " no mesh";
  for (std::string header : {sequential, edgebreaker}) {
    std::string message = load_error(dir, dir.write("huge.gltf", draco_gltf(*mesh, 0, points, corners, &header)), limited);
    CHECK(message.rfind("huge.gltf: " + at + "decoding 2147483647 points and 32 triangles", 0) == 0);
    CHECK(message.find("over the memory limit of 64.0 MiB") != std::string::npos);
  }
  // The same counts as the accessors' are within it: the garbage after the header is what fails.
  std::string honest = std::string("DRACO\x02\x02\x01\x00\x00\x00\x20", 12) + char(points) + " no mesh";
  CHECK(load_error(dir, dir.write("honest.gltf", draco_gltf(*mesh, 0, points, corners, &honest)), limited)
            .rfind("honest.gltf: " + at + "cannot decode: ", 0) == 0);
}

// Mesh repairs: degenerate triangles, area-weighted normals, tangents without NaN.
#include <doctest/doctest.h>

#include <cmath>

#include "scene/mesh_ops.h"

using namespace radiant;

TEST_CASE("mesh ops: degenerate triangles are dropped and counted") {
  MeshDesc mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  mesh.indices = {0, 1, 2, 1, 1, 2, 0, 1, 3};
  CHECK(drop_degenerate_triangles(mesh) == 2);
  CHECK(mesh.indices == std::vector<uint32_t>{0, 1, 2});
}

TEST_CASE("mesh ops: normals are weighted by triangle area") {
  // A big triangle facing +Z and a small one facing +X share vertex 0.
  MeshDesc mesh;
  mesh.positions = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  generate_normals(mesh);
  vec3 n = mesh.normals[0];
  CHECK(n.z / n.x == doctest::Approx(9.0));  // area ratio 4.5 : 0.5
  CHECK(length(n) == doctest::Approx(1));
}

TEST_CASE("mesh ops: repair replaces only the bad normals") {
  MeshDesc mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2};
  mesh.normals = {{0, 0, 2}, {0, 0, 0}, {NAN, 0, 0}};
  CHECK(repair_normals(mesh) == 2);
  CHECK(mesh.normals[0].z == 1);
  CHECK(mesh.normals[1].z == 1);
  CHECK(mesh.normals[2].z == 1);
}

TEST_CASE("mesh ops: tangents follow +u, carry handedness, and survive zero-area UVs") {
  MeshDesc mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 0}, {6, 5, 0}, {5, 6, 0}};
  mesh.texcoords0 = {{0, 0}, {1, 0}, {0, 1}, {0.5f, 0.5f}, {0.5f, 0.5f}, {0.5f, 0.5f}};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  generate_tangents(mesh);
  REQUIRE(mesh.tangents.size() == 6);
  CHECK(mesh.tangents[0].x == doctest::Approx(1));
  CHECK(mesh.tangents[0].w == 1);
  for (const vec4& t : mesh.tangents) {
    CHECK(std::isfinite(t.x));
    CHECK(std::abs(t.x * t.x + t.y * t.y + t.z * t.z - 1) < 1e-5f);
    CHECK(std::abs(t.z) < 1e-6f);  // orthogonal to the +Z normal
  }
  mesh.texcoords0 = {{0, 0}, {1, 0}, {0, -1}, {0, 0}, {1, 0}, {0, -1}};  // mirrored v
  generate_tangents(mesh);
  CHECK(mesh.tangents[0].w == -1);
}

// A triangle so large that the squared length of its edges' cross product overflows float (OBJ
// fuzzing found one 2e9 across): its hit still gets a unit normal, so a ray leaving it is offset
// off the surface. With a zero normal the offset was zero, every see-through step hit the same
// triangle again at t = 1e-7, and Whitted recursed until the stack ran out.
#include <doctest/doctest.h>

#include <cmath>

#include "accel/scene_accel.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// One triangle in z = 0 with legs of 2e10: Embree's Ng is (0, 0, 4e20), whose square overflows.
SceneDesc huge_triangle(const MaterialDesc& material) {
  SceneDesc scene;
  int m = add_material(scene, material);
  MeshDesc mesh;
  mesh.material = m;
  mesh.positions = {{0, 0, 0}, {2e10f, 0, 0}, {0, 2e10f, 0}};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  InstanceDesc instance;
  instance.mesh = 0;
  scene.instances.push_back(instance);
  return scene;
}

}  // namespace

TEST_CASE("huge triangle: a hit has a unit normal, and a ray spawned past it leaves it") {
  MaterialDesc grey;
  SceneDesc scene = huge_triangle(grey);
  auto accel = build_scene_accel(scene);
  Ray down = {{1e9f, 1e9f, 1e9f}, {0, 0, -1}};
  HitId id = intersect_nearest(*accel, down);
  REQUIRE(id.valid());
  SurfaceHit hit = make_surface_hit(*accel, down, id);
  CHECK(std::abs(length(hit.geometric_normal) - 1) < 1e-6f);
  CHECK(std::abs(hit.geometric_normal.z) == doctest::Approx(1));
  CHECK(std::abs(length(hit.shading_normal) - 1) < 1e-6f);
  // Nothing lies beyond the triangle: the spawned ray must not find it again.
  CHECK(!intersect_nearest(*accel, spawn_ray(hit, down.direction)).valid());
}

TEST_CASE("huge triangle: a half-transparent one is seen through at most once per camera ray, by both integrators") {
  MaterialDesc glass_like;
  glass_like.kd = {0.5f, 0.5f, 0.5f};
  glass_like.alpha_mode = AlphaMode::blend;
  glass_like.alpha = 0.5f;
  SceneDesc scene = huge_triangle(glass_like);
  scene.cameras.push_back(perspective_camera({1e9f, 1e9f, 1e9f}, {0, 0, -1}, {0, 1, 0}, 30));
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    RenderOptions o;
    o.width = o.height = 4;
    o.spp = 1;
    o.mode = mode;
    RenderResult result = render_scene(scene, o);
    CAPTURE(int(mode));
    // Every pixel sees the triangle: its camera ray and the one through it (Whitted always, the
    // path tracer where it draws see-through), not 256 steps.
    if (mode == RenderMode::whitted) CHECK(result.stats.rays.camera == 2 * 16);
    else CHECK(result.stats.rays.camera <= 2 * 16);
  }
}

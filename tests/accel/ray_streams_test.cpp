// Rays traced together as Embree streams (intersect_nearest_many, occluded_many), coherent or
// not, find exactly what each finds alone: the same surface, t, barycentrics and normal bits,
// the same occlusion answer, untraceable rays refused and counted alike, in flat and instanced
// layouts, with geometry Embree calls back for (analytic shapes, alpha masks) and in streams
// longer than one tile.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <random>

#include "accel/scene_accel.h"
#include "math/transform.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A box of quads seen from inside, and one mesh placed twice by transforms that keep it
// instanced (rotated and scaled), so rays meet both Embree levels.
SceneDesc room_with_instances() {
  SceneDesc scene;
  int m = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  add_quad(scene, {-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}, m);   // floor
  add_quad(scene, {-5, 0, -5}, {-5, 6, -5}, {5, 6, -5}, {5, 0, -5}, m);  // back wall
  add_quad(scene, {-5, 0, -5}, {-5, 0, 5}, {-5, 6, 5}, {-5, 6, -5}, m);  // left wall
  MeshDesc block;
  block.material = m;
  block.positions = {{-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 2, 1}, {-1, 2, 1}};
  block.indices = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
  scene.meshes.push_back(block);
  for (mat4 transform : {translation({-2, 0, -1}) * rotation_axis({0, 1, 0}, 30) * scaling({0.7f, 1.3f, 0.7f}),
                         translation({2.5f, 0.5f, 1}) * rotation_axis({1, 1, 0}, 17)}) {
    InstanceDesc instance;
    instance.mesh = int(scene.meshes.size()) - 1;
    instance.transform = transform;
    scene.instances.push_back(instance);
  }
  return scene;
}

// The same room with geometry whose hits radiant computes in Embree's callbacks, which then
// take Embree's packets: a sphere, a tilted cylinder, a tube, a plane for a ceiling, and a card
// whose vertex alpha an alpha mask cuts in half.
SceneDesc room_with_callbacks() {
  SceneDesc scene = room_with_instances();
  add_sphere(scene, {0.5f, 1, 1.5f}, 0.8f, 0);
  ShapeDesc cylinder;
  cylinder.kind = ShapeKind::cylinder, cylinder.center = {-3, 0.2f, 2}, cylinder.axis = normalize(vec3{0.3f, 1, 0.2f});
  cylinder.radius = 0.6f, cylinder.height = 2.5f, cylinder.material = 0;
  scene.shapes.push_back(cylinder);
  ShapeDesc tube = cylinder;
  tube.kind = ShapeKind::tube, tube.center = {3.5f, 0, -3.5f}, tube.axis = {0, 1, 0}, tube.radius = 0.4f;
  scene.shapes.push_back(tube);
  add_plane(scene, {0, 5.5f, 0}, {0.05f, -1, 0.02f}, 0);
  MaterialDesc cutout;
  cutout.kd = {0.8f, 0.2f, 0.2f};
  cutout.alpha_mode = AlphaMode::mask, cutout.alpha_cutoff = 0.5f;
  add_quad(scene, {-4, 0.5f, 0.5f}, {1, 0.5f, 0.5f}, {1, 4, 0.5f}, {-4, 4, 0.5f}, add_material(scene, cutout));
  scene.meshes.back().colors = {{1, 1, 1, 0}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 0}};
  return scene;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Tiles of camera rays (a 37 x 11 grid: several streams, the last one short), random rays from
// inside the room, and rays no traversal may take (NaN, origins beyond the traceable range).
std::vector<Ray> probe_rays() {
  std::vector<Ray> rays;
  vec3 eye = {0, 3, 4.5f};
  for (int y = 0; y < 11; ++y)
    for (int x = 0; x < 37; ++x)
      rays.push_back({eye, normalize(vec3{(x - 18) / 20.0f, (y - 5) / 12.0f, -1})});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1, 1), fraction(0, 1);
  for (int i = 0; i < 500; ++i) {
    vec3 d = normalize(vec3{unit(rng), unit(rng), unit(rng)});
    float tmax = i % 4 == 0 ? 6 * fraction(rng) : std::numeric_limits<float>::infinity();
    rays.push_back({{4 * unit(rng), 3 + 2 * unit(rng), 4 * unit(rng)}, d, tmax});
  }
  float nan = std::numeric_limits<float>::quiet_NaN();
  rays.insert(rays.begin() + 40, Ray{eye, {nan, 0, -1}});
  rays.insert(rays.begin() + 100, Ray{{1e30f, 0, 0}, {0, 0, -1}});
  return rays;
}

std::vector<const Ray*> pointers_to(const std::vector<Ray>& rays) {
  std::vector<const Ray*> pointers;
  for (const Ray& ray : rays) pointers.push_back(&ray);
  return pointers;
}

}  // namespace

TEST_CASE("ray streams: packets find bit for bit the hits each ray finds alone, coherent or not") {
  for (bool callbacks : {false, true}) {
    CAPTURE(callbacks);
    SceneDesc scene = callbacks ? room_with_callbacks() : room_with_instances();
    auto accel = build_scene_accel(scene);
    REQUIRE(traces_packets(*accel));
    REQUIRE(!accel->instanced.empty());  // the transformed blocks stay instanced
    std::vector<Ray> rays = probe_rays();
    for (RayCoherence coherence : {RayCoherence::coherent, RayCoherence::incoherent}) {
      CAPTURE(int(coherence));
      accel->untraceable_rays = 0;
      std::vector<HitId> together(rays.size());
      intersect_nearest_many(*accel, pointers_to(rays).data(), int(rays.size()), together.data(), coherence);
      uint64_t refused_together = accel->untraceable_rays.exchange(0);
      int hits = 0, instance_hits = 0;
      for (size_t r = 0; r < rays.size(); ++r) {
        HitId alone = intersect_nearest(*accel, rays[r]);
        const HitId& packed = together[r];
        CAPTURE(r);
        REQUIRE(packed.valid() == alone.valid());
        if (!alone.valid()) continue;
        ++hits;
        instance_hits += alone.instance >= 2;
        CHECK(packed.instance == alone.instance);
        CHECK(packed.shape == alone.shape);
        CHECK(packed.primitive == alone.primitive);
        CHECK(same_bits(packed.t, alone.t));
        CHECK((same_bits(packed.barycentric.x, alone.barycentric.x) &&
               same_bits(packed.barycentric.y, alone.barycentric.y)));
        vec3 a = packed.geometric_normal_raw, b = alone.geometric_normal_raw;
        CHECK((same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z)));
      }
      CHECK(refused_together == 2);
      CHECK(accel->untraceable_rays.load() == 2);  // the same two, refused again one by one
      CHECK(hits > int(rays.size()) / 2);
      CHECK(instance_hits > 20);
      if (callbacks) {
        // Each shape is hit, and the card both stops rays and lets them through its cut half.
        for (int shape = 0; shape < 4; ++shape) {
          CAPTURE(shape);
          auto on_shape = [&](const HitId& h) { return h.shape == shape; };
          CHECK(std::count_if(together.begin(), together.end(), on_shape) > 3);
        }
        int card = int(scene.instances.size()) - 1, card_hits = 0, through_card = 0;
        for (size_t r = 0; r < 37 * 11; ++r) {  // the camera rays, all of which cross the card's plane
          card_hits += together[r].instance == card;
          bool beyond = together[r].t * rays[r].direction.z < -4;  // past the card's plane (z = 0.5)
          through_card += together[r].valid() && together[r].instance != card && beyond;
        }
        CHECK(card_hits > 20);
        CHECK(through_card > 20);
      }
    }
  }
}

TEST_CASE("ray streams: occlusion of a stream is each ray's own answer, untraceable rays blocked") {
  for (bool callbacks : {false, true}) {
    CAPTURE(callbacks);
    SceneDesc scene = callbacks ? room_with_callbacks() : room_with_instances();
    auto accel = build_scene_accel(scene);
    std::vector<Ray> rays = probe_rays();
    // Short rays too, so that both answers are common.
    for (size_t r = 0; r < rays.size(); r += 3) rays[r].tmax = std::min(rays[r].tmax, 1.5f);
    for (RayCoherence coherence : {RayCoherence::coherent, RayCoherence::incoherent}) {
      CAPTURE(int(coherence));
      accel->untraceable_rays = 0;
      std::unique_ptr<bool[]> together(new bool[rays.size()]);
      occluded_many(*accel, pointers_to(rays).data(), int(rays.size()), together.get(), coherence);
      CHECK(accel->untraceable_rays.exchange(0) == 2);
      int blocked = 0, differ = 0;
      for (size_t r = 0; r < rays.size(); ++r) {
        bool alone = is_occluded(*accel, rays[r]);
        blocked += alone;
        differ += together[r] != alone;
      }
      CHECK(differ == 0);
      CHECK(together[40]);  // the NaN direction
      CHECK(blocked > 50);
      CHECK(blocked < int(rays.size()) - 50);
    }
  }
}

TEST_CASE("ray streams: a scene of a few shapes alone, traced without Embree, is traced ray by ray") {
  SceneDesc scene;
  add_sphere(scene, {0, 1, 0}, 0.5f, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  auto shapes_only = build_scene_accel(scene);
  REQUIRE(shapes_only->direct_shapes.enabled);
  CHECK(!traces_packets(*shapes_only));
  // The fallback still answers for every ray.
  Ray ray = {{0, 1, 4}, {0, 0, -1}};
  HitId hit;
  const Ray* one[] = {&ray};
  intersect_nearest_many(*shapes_only, one, 1, &hit, RayCoherence::incoherent);
  CHECK(hit.shape == 0);
  CHECK(hit.t == doctest::Approx(3.5f));
  bool blocked = false;
  occluded_many(*shapes_only, one, 1, &blocked, RayCoherence::incoherent);
  CHECK(blocked);
  // Beside a mesh, Embree traces the shapes, in packets.
  add_quad(scene, {-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}, 0);
  CHECK(traces_packets(*build_scene_accel(scene)));
}

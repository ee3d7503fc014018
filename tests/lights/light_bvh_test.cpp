// The light BVH: its choice probabilities are a distribution at every point, sampling follows
// them, the probability MIS asks for is the one sampling reported, and it prefers the lights
// that matter at a point.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <random>

#include "lights/light_selection.h"
#include "support/chi_square.h"
#include "support/scene_builders.h"

using namespace radiant;
using namespace radiant::test;

namespace {

int add_emitter(SceneDesc& scene, color3 emission, bool double_sided) {
  MaterialDesc m;
  m.emission = emission;
  m.double_sided = double_sided;
  return add_material(scene, m);
}

// A small square at height y facing down (normal -y), centred on (x, z).
void add_ceiling_lamp(SceneDesc& scene, float x, float y, float z, float half, int material) {
  add_quad(scene, {x - half, y, z - half}, {x + half, y, z - half}, {x + half, y, z + half}, {x - half, y, z + half},
           material);
}

// Every kind of light: one-sided lamps of three brightnesses, two-sided panels, emissive spheres,
// point lights, a glTF cone spot, a classic cos^n spot and a directional light.
SceneDesc mixed_light_scene() {
  SceneDesc scene;
  add_quad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  int lamps[3] = {add_emitter(scene, {1, 1, 1}, false), add_emitter(scene, {4, 2, 1}, false),
                  add_emitter(scene, {0.2f, 0.5f, 3}, false)};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) add_ceiling_lamp(scene, -3 + 2.0f * i, 2, -3 + 2.0f * j, 0.1f, lamps[(i + j) % 3]);
  int panel = add_emitter(scene, {2, 2, 2}, true);
  add_quad(scene, {3.5f, 0.5f, -1}, {3.5f, 1.5f, -1}, {3.5f, 1.5f, 1}, {3.5f, 0.5f, 1}, panel);
  add_sphere(scene, {-2, 0.5f, 2}, 0.2f, add_emitter(scene, {5, 5, 5}, true));
  add_sphere(scene, {1, 0.3f, -2}, 0.1f, add_emitter(scene, {1, 8, 1}, false));
  scene.lights.push_back(point_light({0, 1.5f, 0}, {3, 3, 3}));
  scene.lights.push_back(point_light({-3, 0.2f, -3}, {1, 0.5f, 0.2f}));
  LightDesc cone = point_light({2, 1.8f, 2}, {6, 6, 6});
  cone.kind = LightKind::spot;
  cone.direction = {0, -1, 0};
  cone.use_cone = true;
  cone.inner_cone = 0.3f, cone.outer_cone = 0.6f;
  scene.lights.push_back(cone);
  LightDesc beam = cone;
  beam.use_cone = false;
  beam.spot_exponent = 8;
  beam.position = {-2, 1.8f, -1};
  beam.direction = normalize(vec3{1, -1, 0});
  scene.lights.push_back(beam);
  LightDesc sun;
  sun.kind = LightKind::directional;
  sun.direction = normalize(vec3{0.3f, -1, 0.2f});
  sun.intensity = {0.5f, 0.5f, 0.5f};
  scene.lights.push_back(sun);
  return scene;
}

LightTable bvh_table(const SceneDesc& scene, color3 environment = {0.1f, 0.2f, 0.3f}) {
  return make_light_table(scene, environment, "", true, nullptr, LightSampler::bvh);
}

size_t slot_count(const LightTable& lights) {
  return lights.environment_slot() + (lights.has_environment() ? 1 : 0);
}

// Shading points in and around the scene, half on surfaces (a random normal), half in a medium.
struct ShadingPoint {
  vec3 p, n;
};
std::vector<ShadingPoint> random_points(int count, unsigned seed) {
  std::mt19937 engine(seed);
  std::uniform_real_distribution<float> x(-5, 5), y(-1, 3), unit(-1, 1);
  std::vector<ShadingPoint> points;
  for (int i = 0; i < count; ++i) {
    ShadingPoint s{{x(engine), y(engine), x(engine)}, {0, 0, 0}};
    if (i % 2 == 0) s.n = normalize(vec3{unit(engine), unit(engine), unit(engine)});
    points.push_back(s);
  }
  return points;
}

double probability_sum(const LightTable& lights, vec3 p, vec3 n) {
  double sum = 0;
  for (size_t slot = 0; slot < slot_count(lights); ++slot) sum += light_choice_probability(lights, p, n, slot);
  return sum;
}

}  // namespace

TEST_CASE("light BVH: one leaf per light with a position, the sun and the sky at infinity") {
  SceneDesc scene = mixed_light_scene();
  LightTable lights = bvh_table(scene);
  REQUIRE(lights.sampler == LightSampler::bvh);
  // 32 lamp triangles, 2 panel triangles, 2 spheres, 4 point and spot lights.
  size_t in_tree = 32 + 2 + 2 + 4;
  CHECK(lights.bvh.nodes.size() < in_tree);  // eight-wide: fewer nodes than lights
  size_t leaves = 0;
  for (LightBvhLeaf leaf : lights.bvh.leaf_of_light) leaves += leaf.node >= 0;
  CHECK(leaves == in_tree);
  CHECK(lights.infinite_lights == std::vector<int>{4, int(lights.environment_slot())});
}

TEST_CASE("light BVH: the choice probabilities of all lights sum to one at random points") {
  SceneDesc scene = mixed_light_scene();
  for (color3 environment : {color3{0.1f, 0.2f, 0.3f}, color3{0, 0, 0}}) {
    LightTable lights = bvh_table(scene, environment);
    for (const ShadingPoint& s : random_points(300, 7)) {
      INFO("p = ", s.p.x, ", ", s.p.y, ", ", s.p.z, "; n = ", s.n.x, ", ", s.n.y, ", ", s.n.z);
      CHECK(probability_sum(lights, s.p, s.n) == doctest::Approx(1).epsilon(1e-5));
    }
  }
}

TEST_CASE("light BVH: sampled lights follow the choice probabilities (chi-square), which sampling reports") {
  SceneDesc scene = mixed_light_scene();
  LightTable lights = bvh_table(scene);
  constexpr int samples = 100000;
  std::vector<ShadingPoint> points = random_points(6, 11);
  double corrected = 1 - std::pow(1 - 0.01, 1.0 / double(points.size()));  // Sidak
  std::mt19937 engine(3);
  for (const ShadingPoint& s : points) {
    std::vector<double> observed(slot_count(lights), 0), expected(slot_count(lights), 0);
    for (size_t slot = 0; slot < expected.size(); ++slot)
      expected[slot] = samples * double(light_choice_probability(lights, s.p, s.n, slot));
    int mismatched = 0;
    for (int k = 0; k < samples; ++k) {
      float u = float(engine() >> 8) * 0x1p-24f;
      LightChoice choice;
      REQUIRE(choose_light(lights, s.p, s.n, [u] { return u; }, choice));
      observed[choice.slot] += 1;
      float evaluated = light_choice_probability(lights, s.p, s.n, choice.slot);
      mismatched += std::abs(choice.probability - evaluated) > 1e-6f * evaluated;
    }
    double p_value = 0;
    std::string failure = chi_square_test(observed, expected, samples, 5, p_value);
    INFO("p = ", s.p.x, ", ", s.p.y, ", ", s.p.z, "; p-value ", p_value);
    CHECK(failure == "");
    CHECK(p_value > corrected);
    CHECK(mismatched == 0);
  }
}

TEST_CASE("light BVH: choices made together (interleaved descents) are the single choices, to the bit") {
  SceneDesc scene = mixed_light_scene();
  // With the sun and the sky at infinity (chosen before the tree), and the sun alone.
  for (color3 environment : {color3{0.1f, 0.2f, 0.3f}, color3{0, 0, 0}}) {
    LightTable lights = bvh_table(scene, environment);
    // Random points, and points behind every one-sided lamp, where the choice falls back to
    // intensity; a count that is no multiple of the groups the descents run in.
    std::vector<ShadingPoint> points = random_points(997, 21);
    for (int i = 0; i < 40; ++i) points.push_back({{-3 + 0.15f * float(i), 2.5f, 0.3f}, {0, 1, 0}});
    std::mt19937 engine(5);
    std::vector<vec3> p, n;
    std::vector<float> u;
    for (const ShadingPoint& s : points) {
      p.push_back(s.p), n.push_back(s.n);
      u.push_back(float(engine() >> 8) * 0x1p-24f);
    }
    u[3] = 0, u[4] = 0x1p-24f * float((1 << 24) - 1);  // both ends of [0, 1)
    std::vector<LightChoice> together(points.size());
    std::unique_ptr<bool[]> found(new bool[points.size()]);
    choose_lights_by_bvh_many(lights, p.data(), n.data(), u.data(), int(points.size()), together.data(), found.get());
    int chosen_at_infinity = 0, chosen_in_tree = 0;
    for (size_t k = 0; k < points.size(); ++k) {
      LightChoice alone;
      bool found_alone = choose_light_by_bvh(lights, p[k], n[k], u[k], alone);
      INFO("point ", k);
      REQUIRE(found[k] == found_alone);
      if (!found_alone) continue;
      CHECK(together[k].slot == alone.slot);
      CHECK(std::bit_cast<uint32_t>(together[k].probability) == std::bit_cast<uint32_t>(alone.probability));
      bool at_infinity = std::find(lights.infinite_lights.begin(), lights.infinite_lights.end(), int(alone.slot)) !=
                         lights.infinite_lights.end();
      (at_infinity ? chosen_at_infinity : chosen_in_tree) += 1;
    }
    CHECK(chosen_in_tree > int(points.size()) / 2);  // most choices descend the tree
    CHECK(chosen_at_infinity > 0);  // the sun (and the sky where there is one)
  }
}

TEST_CASE("light BVH: every instruction set chooses the same lights with the same probabilities, to the bit") {
  if (!lane_isa_available(LaneIsa::avx2)) return;  // nothing to compare on this CPU
  LightTable lights = bvh_table(mixed_light_scene(), {0, 0, 0});
  std::vector<ShadingPoint> points = random_points(1001, 33);
  std::mt19937 engine(8);
  std::vector<vec3> p, n;
  std::vector<float> u;
  for (const ShadingPoint& s : points) {
    p.push_back(s.p), n.push_back(s.n);
    u.push_back(float(engine() >> 8) * 0x1p-24f);
  }
  const int count = int(points.size());
  std::vector<int> slot[2] = {std::vector<int>(points.size()), std::vector<int>(points.size())};
  std::vector<float> probability[2] = {std::vector<float>(points.size()), std::vector<float>(points.size())};
  const LaneIsa isas[2] = {LaneIsa::baseline, LaneIsa::avx2};
  for (int i = 0; i < 2; ++i)
    sample_light_bvh_many(lights.bvh, p.data(), n.data(), u.data(), count, slot[i].data(), probability[i].data(), isas[i]);
  int chosen = 0;
  for (size_t k = 0; k < points.size(); ++k) {
    INFO("point ", k);
    REQUIRE(std::bit_cast<uint32_t>(probability[0][k]) == std::bit_cast<uint32_t>(probability[1][k]));
    if (!(probability[0][k] > 0)) continue;
    ++chosen;
    CHECK(slot[0][k] == slot[1][k]);
    int single_slot = -1;
    float single_probability = 0;
    REQUIRE(sample_light_bvh(lights.bvh, p[k], n[k], u[k], single_slot, single_probability, LaneIsa::avx2));
    CHECK(single_slot == slot[0][k]);
    CHECK(std::bit_cast<uint32_t>(single_probability) == std::bit_cast<uint32_t>(probability[0][k]));
    float walked[2] = {light_bvh_probability(lights.bvh, p[k], n[k], slot[0][k], LaneIsa::baseline),
                       light_bvh_probability(lights.bvh, p[k], n[k], slot[0][k], LaneIsa::avx2)};
    CHECK(std::bit_cast<uint32_t>(walked[0]) == std::bit_cast<uint32_t>(walked[1]));
    CHECK(walked[0] == doctest::Approx(probability[0][k]).epsilon(1e-6));
  }
  CHECK(chosen > count * 9 / 10);
}

TEST_CASE("light BVH: eight-wide nodes, as few as the build reserves, and a shallow tree") {
  std::mt19937 engine(12);
  std::uniform_real_distribution<float> coordinate(-10, 10);
  for (int lights : {1, 2, 3, 7, 8, 9, 15, 16, 17, 63, 64, 65, 100, 513, 800, 2000}) {
    CAPTURE(lights);
    std::vector<BoundedLight> bounded;
    for (int i = 0; i < lights; ++i)
      bounded.push_back({i, point_light_bounds({coordinate(engine), 2, coordinate(engine)}, {0, -1, 0}, 1, 0, 1)});
    LightBvh bvh = build_light_bvh(bounded, size_t(lights));
    REQUIRE(bvh.nodes.size() <= light_bvh_nodes_at_most(uint64_t(lights)));
    CHECK(bvh.nodes.capacity() == light_bvh_nodes_at_most(uint64_t(lights)));  // reserved once, never grown
    // Every light in one leaf; the depth of each, in steps from the root.
    double depth_sum = 0;
    int deepest = 0;
    for (int i = 0; i < lights; ++i) {
      LightBvhLeaf leaf = bvh.leaf_of_light[size_t(i)];
      REQUIRE(leaf.node >= 0);
      CHECK(bvh.nodes[size_t(leaf.node)].child[size_t(leaf.lane)] == ~i);
      int depth = 1;
      for (int node = leaf.node; bvh.nodes[size_t(node)].parent >= 0; node = bvh.nodes[size_t(node)].parent) ++depth;
      depth_sum += depth, deepest = std::max(deepest, depth);
    }
    // A full eight-wide tree needs log8(lights) steps; the build's splits are by cost, not by
    // count, so allow some slack, but far less than a four-wide tree's log4.
    double full = std::max(1.0, std::ceil(std::log(double(lights)) / std::log(8.0)));
    CHECK(depth_sum / lights <= full + 0.5);
    CHECK(deepest <= full + 2);
  }
}

TEST_CASE("light BVH: behind every one-sided light, where none reaches, the choice falls back to intensity") {
  SceneDesc scene;
  int dim = add_emitter(scene, {1, 1, 1}, false), bright = add_emitter(scene, {3, 3, 3}, false);
  for (int i = 0; i < 4; ++i) add_ceiling_lamp(scene, float(i), 2, 0, 0.2f, i == 0 ? bright : dim);
  LightTable lights = bvh_table(scene, {0, 0, 0});
  vec3 above = {1.5f, 5, 0}, up = {0, 1, 0};
  CHECK(probability_sum(lights, above, up) == doctest::Approx(1).epsilon(1e-5));
  // The bright lamp's two triangles have half the intensity of the whole (3 of 3 + 1 + 1 + 1).
  CHECK(light_choice_probability(lights, above, up, 0) + light_choice_probability(lights, above, up, 1) ==
        doctest::Approx(0.5).epsilon(1e-4));
  // Below the lamps importance rules: the lamp overhead outweighs the bright one far away.
  vec3 below = {3, 1.5f, 0};
  CHECK(light_choice_probability(lights, below, up, 6) + light_choice_probability(lights, below, up, 7) > 0.5);
}

TEST_CASE("light BVH: a point beside one cluster of lights chooses that cluster, power sampling cannot") {
  SceneDesc scene;
  int lamp = add_emitter(scene, {1, 1, 1}, false);
  for (int i = 0; i < 8; ++i) add_ceiling_lamp(scene, -10 + 0.5f * float(i), 1, 0, 0.1f, lamp);
  for (int i = 0; i < 8; ++i) add_ceiling_lamp(scene, 10 + 0.5f * float(i), 1, 0, 0.1f, lamp);
  LightTable bvh = bvh_table(scene, {0, 0, 0});
  LightTable power = make_light_table(scene, {0, 0, 0}, "", true, nullptr, LightSampler::power);
  vec3 p = {-8, 0, 0}, n = {0, 1, 0};
  double near_bvh = 0, near_power = 0;
  for (size_t slot = 0; slot < 16; ++slot) {  // the first 8 lamps, two triangles each
    near_bvh += light_choice_probability(bvh, p, n, slot);
    near_power += light_choice_probability(power, p, n, slot);
  }
  CHECK(near_power == doctest::Approx(0.5));
  CHECK(near_bvh > 0.97);
}

TEST_CASE("light bounds: inside a group's bounding sphere, nearness to its centre still counts") {
  vec3 down = {0, -1, 0};
  LightBounds group = merge(point_light_bounds({-5, 2, 0}, down, 1, 0, 1), point_light_bounds({5, 2, 0}, down, 1, 0, 1));
  ImportanceBounds bounds = importance_bounds(group);
  REQUIRE(bounds.radius2 == doctest::Approx(25));
  vec3 up = {0, 1, 0};
  float near = importance(bounds, {0, 1, 0}, up), far = importance(bounds, {0, -2, 0}, up);  // distances^2 1 and 16
  // The near point is clamped at half the radius (6.25): 16 / 6.25 times the far one.
  CHECK(near == doctest::Approx(far * 16 / 6.25f));
  CHECK(std::isfinite(importance(bounds, bounds.center, up)));
  CHECK(importance(bounds, bounds.center, up) == near);
}

TEST_CASE("light sampler auto: power below light_bvh_min_lights lights with a position, the BVH from there") {
  SceneDesc scene;
  int lamp = add_emitter(scene, {1, 1, 1}, true);
  scene.lights.push_back(point_light({0, 3, 0}, {1, 1, 1}));
  auto automatic = [&] { return make_light_table(scene, {0, 0, 0}, "", true, nullptr).sampler; };
  CHECK(automatic() == LightSampler::power);  // one light pays nothing
  for (size_t i = 1; i + 2 < light_bvh_min_lights; i += 2) add_ceiling_lamp(scene, float(i), 2, 0, 0.1f, lamp);
  REQUIRE(scene.lights.size() + 2 * scene.instances.size() == light_bvh_min_lights - 1);
  CHECK(automatic() == LightSampler::power);
  scene.lights.push_back(point_light({0, 3, 1}, {1, 1, 1}));
  CHECK(automatic() == LightSampler::bvh);
  // Directional lights and the environment lie outside the tree and do not count.
  scene.lights.pop_back();
  LightDesc sun;
  sun.kind = LightKind::directional;
  scene.lights.push_back(sun);
  CHECK(automatic() == LightSampler::power);
  CHECK(make_light_table(scene, {0, 0, 0}, "", true, nullptr, LightSampler::bvh).sampler == LightSampler::bvh);
}

TEST_CASE("light BVH: a tree of one light chooses it with probability one where it can reach") {
  SceneDesc scene;
  scene.lights.push_back(point_light({0, 3, 0}, {1, 1, 1}));
  LightTable lights = bvh_table(scene, {0, 0, 0});
  LightChoice choice;
  REQUIRE(choose_light(lights, {1, 0, 0}, {0, 1, 0}, [] { return 0.7f; }, choice));
  CHECK(choice.slot == 0);
  CHECK(choice.probability == 1);
  CHECK(light_choice_probability(lights, {1, 0, 0}, {0, 1, 0}, 0) == 1);
}

TEST_CASE("light BVH: charged to the memory budget before it is built, refused with one line naming it") {
  SceneDesc scene = mixed_light_scene();
  scene.source_path = "lamps.scene";
  MemoryBudget power_budget(uint64_t(1) << 30);
  LightTable power = make_light_table(scene, {0, 0, 0}, "", true, &power_budget, LightSampler::power);
  MemoryBudget bvh_budget(uint64_t(1) << 30);
  LightTable bvh = make_light_table(scene, {0, 0, 0}, "", true, &bvh_budget, LightSampler::bvh);
  uint64_t tree_bytes = light_bvh_bytes(40, 41);  // 40 lights with a position among 41 slots
  CHECK(bvh_budget.used() - power_budget.used() == tree_bytes);

  MemoryBudget tight(power_budget.used() + tree_bytes - 1);
  try {
    make_light_table(scene, {0, 0, 0}, "", true, &tight, LightSampler::bvh);
    FAIL("the budget should refuse the tree");
  } catch (const MemoryLimitError& e) {
    CHECK(std::string(e.what()).find("lamps.scene: the light BVH") != std::string::npos);
  }
}

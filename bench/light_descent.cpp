// The light BVH's descent alone: choices at random points on a scene's floor (y = 0, normal +y,
// within its bounds), one descent after another against sample_light_bvh_many's interleaved
// descents, alternating R rounds; checks that both choose the same lights to the bit.
//   bench_light_descent SCENE [--points N] [--rounds R]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "lights/light_table.h"
#include "load_scene.h"
#include "sampling/hash.h"
#include "scene/scene_summary.h"

using namespace radiant;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE [--points N] [--rounds R]\n", argv[0]);
    return 2;
  }
  int points = 1'000'000, rounds = 5;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--points")) points = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--rounds")) rounds = std::atoi(argv[i + 1]);
  }
  LoadOptions options;
  options.allow_external_files = true;
  SceneDesc scene = load_scene(argv[1], options);
  SceneSummary summary = summarize_scene(scene);
  LightTable lights = make_light_table(scene, {0, 0, 0}, "", true, nullptr, LightSampler::bvh);
  if (lights.bvh.empty()) {
    std::fprintf(stderr, "%s: no light BVH\n", argv[1]);
    return 1;
  }
  const size_t count = size_t(points);
  std::vector<vec3> p(count), n(count, vec3{0, 1, 0});
  std::vector<float> u(count);
  vec3 lower = summary.bounds_lower, extent = summary.bounds_upper - summary.bounds_lower;
  for (int i = 0; i < points; ++i) {
    uint32_t h = uint32_t(i);
    p[size_t(i)] = {lower.x + extent.x * bits_to_unit_float(hash3(h, 1, 9)), 0,
                    lower.z + extent.z * bits_to_unit_float(hash3(h, 2, 9))};
    u[size_t(i)] = bits_to_unit_float(hash3(h, 3, 9));
  }
  std::vector<int> slot_one(count), slot_many(count);
  std::vector<float> probability_one(count), probability_many(count);
  using clock = std::chrono::steady_clock;
  for (int round = 0; round < rounds; ++round) {
    auto start = clock::now();
    for (int i = 0; i < points; ++i)
      if (!sample_light_bvh(lights.bvh, p[size_t(i)], n[size_t(i)], u[size_t(i)], slot_one[size_t(i)],
                            probability_one[size_t(i)]))
        probability_one[size_t(i)] = 0;
    double one = std::chrono::duration<double>(clock::now() - start).count();
    start = clock::now();
    sample_light_bvh_many(lights.bvh, p.data(), n.data(), u.data(), points, slot_many.data(), probability_many.data());
    double many = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("one %.1f ns  many %.1f ns  many/one %.3f\n", one / points * 1e9, many / points * 1e9, many / one);
  }
  for (int i = 0; i < points; ++i)
    if (probability_one[size_t(i)] != probability_many[size_t(i)] ||
        (probability_one[size_t(i)] > 0 && slot_one[size_t(i)] != slot_many[size_t(i)])) {
      std::fprintf(stderr, "point %d: one chose %d (%g), many %d (%g)\n", i, slot_one[size_t(i)],
                   double(probability_one[size_t(i)]), slot_many[size_t(i)], double(probability_many[size_t(i)]));
      return 1;
    }
  std::printf("same choices at all %d points\n", points);
  return 0;
}

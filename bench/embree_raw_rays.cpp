// Raw Embree traversal speed on a scene: random rays from inside its bounds in random
// directions, traced through radiant's own acceleration structure on T threads, a fraction F of
// them as occlusion rays to a random point in the bounds (rtcOccluded1, as shadow rays), the
// rest as closest-hit rays (rtcIntersect1). Given the occlusion share of a render, it is the
// traversal rate of that ray mix on incoherent rays: a reference point for radiant's rays per
// second, not a ceiling (a render's rays are more coherent, and its shadow rays shorter).
//   bench_embree_raw_rays SCENE [--rays N] [--threads T] [--occlusion-fraction F]
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "accel/scene_accel.h"
#include "load_scene.h"
#include "sampling/hash.h"
#include "sampling/warp.h"
#include "scene/scene_summary.h"

using namespace radiant;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s SCENE [--rays N] [--threads T]\n", argv[0]);
    return 2;
  }
  size_t rays = 20'000'000;
  int threads = 2;
  double occlusion_fraction = 0;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--rays")) rays = std::strtoull(argv[i + 1], nullptr, 10);
    if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--occlusion-fraction")) occlusion_fraction = std::atof(argv[i + 1]);
  }
  LoadOptions options;
  options.allow_external_files = true;
  SceneDesc scene = load_scene(argv[1], options);
  SceneSummary summary = summarize_scene(scene);
  auto accel = build_scene_accel(scene);
  vec3 lower = summary.bounds_lower, extent = summary.bounds_upper - summary.bounds_lower;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);

  auto start = std::chrono::steady_clock::now();
  std::atomic<size_t> hits{0};
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays, 4096), [&](const tbb::blocked_range<size_t>& r) {
    size_t local_hits = 0;
    for (size_t i = r.begin(); i < r.end(); ++i) {
      uint32_t h = uint32_t(i);
      vec3 u = {bits_to_unit_float(hash3(h, 1, 7)), bits_to_unit_float(hash3(h, 2, 7)), bits_to_unit_float(hash3(h, 3, 7))};
      vec3 origin = lower + extent * u;
      if (bits_to_unit_float(hash3(h, 6, 7)) < occlusion_fraction) {
        vec3 v = {bits_to_unit_float(hash3(h, 8, 7)), bits_to_unit_float(hash3(h, 9, 7)), bits_to_unit_float(hash3(h, 10, 7))};
        local_hits += is_occluded(*accel, {origin, lower + extent * v - origin, 1 - 1e-4f});
        continue;
      }
      vec3 direction = sample_uniform_sphere({bits_to_unit_float(hash3(h, 4, 7)), bits_to_unit_float(hash3(h, 5, 7))});
      local_hits += intersect_nearest(*accel, {origin, direction}).valid();
    }
    hits += local_hits;
  });
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("rays %zu\nseconds %.4f\nrays_per_second %.0f\nhit_fraction %.3f\n", rays, seconds, rays / seconds,
              double(hits) / double(rays));
  return 0;
}

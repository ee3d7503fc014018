// Eight groups rated at once give, lane by lane, exactly what importance() gives for each group,
// with every instruction set the CPU has: the light BVH's eight-wide descent must not choose
// differently from the formula it documents, nor from one machine to the next.
#include <doctest/doctest.h>

#include <cstring>
#include <random>

#include "lights/importance8.h"

using namespace radiant;

namespace {

// A group of random extent, orientation, spread and falloff; some two-sided, some points.
LightBounds random_group(std::mt19937& engine) {
  std::uniform_real_distribution<float> coordinate(-4, 4), unit(-1, 1), size(0, 2), cosine(-1, 1);
  vec3 lower = {coordinate(engine), coordinate(engine), coordinate(engine)};
  vec3 extent = engine() % 4 == 0 ? vec3{0, 0, 0} : vec3{size(engine), size(engine), size(engine)};
  vec3 axis = normalize(vec3{unit(engine), unit(engine), unit(engine)});
  LightBounds group = point_light_bounds(lower, axis, cosine(engine), cosine(engine), size(engine) + 0.01f);
  group.upper = lower + extent;
  group.two_sided = engine() % 3 == 0;
  return group;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("light bounds: importance8 rates each lane exactly as importance() rates its group") {
  for (LaneIsa isa : {LaneIsa::baseline, LaneIsa::avx2}) {
    if (!lane_isa_available(isa)) continue;
    CAPTURE(int(isa));
    std::mt19937 engine(7);
    std::uniform_real_distribution<float> coordinate(-6, 6), unit(-1, 1);
    int inside = 0, zero = 0, positive = 0;
    for (int round = 0; round < 2000; ++round) {
      ImportanceBounds8 eight;
      ImportanceBounds one[light_node_width];
      int lanes = 1 + round % light_node_width;  // the rest stay empty
      for (int lane = 0; lane < lanes; ++lane) {
        one[lane] = importance_bounds(random_group(engine));
        set_lane(eight, lane, one[lane]);
      }
      vec3 p = {coordinate(engine), coordinate(engine), coordinate(engine)};
      if (round % 3 == 0) p = one[0].center + vec3{unit(engine), unit(engine), unit(engine)} * 0.5f;  // often inside
      vec3 n = round % 5 == 0 ? vec3{0, 0, 0} : normalize(vec3{unit(engine), unit(engine), unit(engine)});
      float rated[light_node_width];
      importance8_on(eight, p, n, rated, isa);
      for (int lane = 0; lane < light_node_width; ++lane) {
        float expected = lane < lanes ? importance(one[lane], p, n) : 0.0f;
        CHECK(same_bits(rated[lane], expected));
        if (lane >= lanes) continue;
        inside += length_squared(p - one[lane].center) <= one[lane].radius2;
        zero += expected == 0;
        positive += expected > 0;
      }
    }
    // Every branch of importance() was taken: inside the sphere, ruled out, rated.
    CHECK(inside > 50);
    CHECK(zero > 50);
    CHECK(positive > 1000);
  }
}

TEST_CASE("light bounds: a lane round-trips through set_lane and lane_of") {
  std::mt19937 engine(3);
  ImportanceBounds8 eight;
  ImportanceBounds one = importance_bounds(random_group(engine));
  set_lane(eight, 5, one);
  ImportanceBounds back = lane_of(eight, 5);
  CHECK(back.center.x == one.center.x);
  CHECK(back.radius == one.radius);
  CHECK(back.sin_spread == one.sin_spread);
  CHECK(back.two_sided == one.two_sided);
  CHECK(eight.intensity[0] == 0);  // untouched lanes stay empty
}

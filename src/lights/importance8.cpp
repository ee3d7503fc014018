// Putting a group's bounds into a lane of an eight-wide node and reading one back, and the rating
// out of line, for the tests.
#include "lights/importance8.h"

namespace radiant {

void set_lane(ImportanceBounds8& bounds, int lane, const ImportanceBounds& one) {
  bounds.center_x[lane] = one.center.x, bounds.center_y[lane] = one.center.y, bounds.center_z[lane] = one.center.z;
  bounds.radius[lane] = one.radius, bounds.radius2[lane] = one.radius2;
  bounds.axis_x[lane] = one.axis.x, bounds.axis_y[lane] = one.axis.y, bounds.axis_z[lane] = one.axis.z;
  bounds.cos_spread[lane] = one.cos_spread, bounds.sin_spread[lane] = one.sin_spread;
  bounds.cos_falloff[lane] = one.cos_falloff;
  bounds.intensity[lane] = one.intensity;
  bounds.two_sided[lane] = one.two_sided ? 1.0f : 0.0f;
}

ImportanceBounds lane_of(const ImportanceBounds8& bounds, int lane) {
  ImportanceBounds one;
  one.center = {bounds.center_x[lane], bounds.center_y[lane], bounds.center_z[lane]};
  one.radius = bounds.radius[lane], one.radius2 = bounds.radius2[lane];
  one.axis = {bounds.axis_x[lane], bounds.axis_y[lane], bounds.axis_z[lane]};
  one.cos_spread = bounds.cos_spread[lane], one.sin_spread = bounds.sin_spread[lane];
  one.cos_falloff = bounds.cos_falloff[lane];
  one.intensity = bounds.intensity[lane];
  one.two_sided = bounds.two_sided[lane] != 0;
  return one;
}

namespace {
void importance8_baseline(const ImportanceBounds8& bounds, vec3 p, vec3 n, float* out) { importance8(bounds, p, n, out); }
[[gnu::target("avx2")]] void importance8_avx2(const ImportanceBounds8& bounds, vec3 p, vec3 n, float* out) {
  importance8(bounds, p, n, out);
}
}  // namespace

void importance8_on(const ImportanceBounds8& bounds, vec3 p, vec3 n, float* out, LaneIsa isa) {
  resolve_lane_isa(isa) == LaneIsa::avx2 ? importance8_avx2(bounds, p, n, out) : importance8_baseline(bounds, p, n, out);
}

}  // namespace radiant

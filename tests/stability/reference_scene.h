// The exact answer for a grey plane y = 0 with spheres and boxes on it, one point light (1/d^2)
// and an ambient light, in Whitted mode: per camera ray, whether it sees the plane lit, in shadow,
// or too close to an edge to say, and the pixel value it must have.
#pragma once

#include <cmath>
#include <vector>

#include "accel/ray.h"

namespace radiant::test {

struct ReferenceSphere {
  vec3 center;
  float radius = 1;
};
struct ReferenceBox {
  vec3 lower, upper;
};

struct ReferenceScene {
  std::vector<ReferenceSphere> spheres;
  std::vector<ReferenceBox> boxes;
  vec3 light;
  float intensity = 1;  // point light, kq = 1
  float kd = 0.5f;      // the plane's diffuse reflectance
  float ambient = 0;    // the plane's ka times the ambient light
};

enum class ReferenceKind { lit_plane, shadowed_plane, other };

struct ReferencePixel {
  ReferenceKind kind = ReferenceKind::other;
  float value = 0;  // the exact pixel value for the two plane kinds
};

namespace reference_detail {

// Whether the segment a + t (b - a), t in [0, 1], meets the sphere grown by `margin`.
inline bool segment_meets_sphere(vec3 a, vec3 b, const ReferenceSphere& s, float margin) {
  vec3 d = b - a;
  float t = std::clamp(dot(s.center - a, d) / dot(d, d), 0.0f, 1.0f);
  return length(a + d * t - s.center) < s.radius + margin;
}

// Slab test of the segment against the box grown by `margin` (negative shrinks it).
inline bool segment_meets_box(vec3 a, vec3 b, const ReferenceBox& box, float margin) {
  float t0 = 0, t1 = 1;
  for (int i = 0; i < 3; ++i) {
    float lo = box.lower[i] - margin, hi = box.upper[i] + margin, d = b[i] - a[i];
    if (d == 0) {
      if (a[i] < lo || a[i] > hi) return false;
      continue;
    }
    float ta = (lo - a[i]) / d, tb = (hi - a[i]) / d;
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  return t0 <= t1;
}

inline bool segment_meets_anything(const ReferenceScene& scene, vec3 a, vec3 b, float margin) {
  for (const ReferenceSphere& s : scene.spheres)
    if (segment_meets_sphere(a, b, s, margin)) return true;
  for (const ReferenceBox& box : scene.boxes)
    if (segment_meets_box(a, b, box, margin)) return true;
  return false;
}

}  // namespace reference_detail

// Classifies one camera ray; `margin` (world units) keeps clear of every silhouette and shadow edge.
inline ReferencePixel reference_pixel(const ReferenceScene& scene, const Ray& ray, float margin) {
  using namespace reference_detail;
  ReferencePixel pixel;
  if (!(ray.direction.y < 0)) return pixel;
  vec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
  p.y = 0;
  // The camera must see the plane with room to spare around every object.
  if (segment_meets_anything(scene, ray.origin, p, margin)) return pixel;
  if (!segment_meets_anything(scene, p, scene.light, margin)) {
    vec3 to_light = scene.light - p;
    float d2 = dot(to_light, to_light);
    pixel.kind = ReferenceKind::lit_plane;
    pixel.value = scene.ambient + scene.kd * inv_pi * scene.intensity * (to_light.y / std::sqrt(d2)) / d2;
  } else if (segment_meets_anything(scene, p, scene.light, -margin)) {
    pixel.kind = ReferenceKind::shadowed_plane;
    pixel.value = scene.ambient;
  }
  return pixel;
}

}  // namespace radiant::test

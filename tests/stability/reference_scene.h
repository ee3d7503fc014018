// The exact Whitted answer for grey spheres and boxes (on an optional plane y = 0) lit by one
// point light (1/d^2) and an ambient light: per camera ray, whether it sees a lit or a shadowed
// surface, or passes too close to an edge to say, and the pixel value it must have.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "accel/ray.h"
#include "film/film.h"
#include "render/camera.h"

namespace radiant::test {

struct ReferenceSphere {
  vec3 center;
  float radius = 1;
};
struct ReferenceBox {
  vec3 lower, upper;
};

struct ReferenceScene {
  bool has_plane = true;  // the plane y = 0, normal +y
  std::vector<ReferenceSphere> spheres;
  std::vector<ReferenceBox> boxes;
  vec3 light;
  float intensity = 1;  // point light, kq = 1
  float kd = 0.5f;      // every surface's diffuse reflectance
  float ambient = 0;    // every surface's ka times the ambient light
};

enum class ReferenceKind { lit, shadowed, other };

struct ReferencePixel {
  ReferenceKind kind = ReferenceKind::other;
  float value = 0;  // the exact pixel value when lit or shadowed
};

namespace reference_detail {

// Whether the segment a + t (b - a), t in [0, 1], meets the sphere grown by `margin`.
inline bool segment_meets_sphere(vec3 a, vec3 b, const ReferenceSphere& s, float margin) {
  vec3 d = b - a;
  float t = std::clamp(dot(s.center - a, d) / dot(d, d), 0.0f, 1.0f);
  return length(a + d * t - s.center) < s.radius + margin;
}

// Slab test of the segment against the box grown by `margin` (negative shrinks it); the entry
// parameter goes to `entry`.
inline bool segment_meets_box(vec3 a, vec3 b, const ReferenceBox& box, float margin, float& entry) {
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
  entry = t0;
  return t0 <= t1;
}

// Whether the segment meets any object other than `skip` (spheres first, then boxes, in order)
// grown by `margin`.
inline bool segment_meets_others(const ReferenceScene& scene, vec3 a, vec3 b, float margin, int skip) {
  int index = 0;
  for (const ReferenceSphere& s : scene.spheres)
    if (index++ != skip && segment_meets_sphere(a, b, s, margin)) return true;
  float entry;
  for (const ReferenceBox& box : scene.boxes)
    if (index++ != skip && segment_meets_box(a, b, box, margin, entry)) return true;
  return false;
}

struct Nearest {
  float t = std::numeric_limits<float>::infinity();
  int object = -1;  // -1 the plane, then spheres, then boxes
  vec3 normal;
  bool near_edge = false;  // the ray passes within the margin of a silhouette or box edge
};

inline void nearest_sphere(const ReferenceScene& scene, vec3 o, vec3 d, float margin, Nearest& n) {
  for (size_t i = 0; i < scene.spheres.size(); ++i) {
    const ReferenceSphere& s = scene.spheres[i];
    float along = dot(s.center - o, d) / dot(d, d);
    float miss_distance = length(o + d * along - s.center);
    if (std::abs(miss_distance - s.radius) < margin) n.near_edge = true;
    if (miss_distance >= s.radius) continue;
    float t = along - std::sqrt(s.radius * s.radius - miss_distance * miss_distance) / length(d);
    if (t > 0 && t < n.t) n = {t, int(i), normalize(o + d * t - s.center), n.near_edge};
  }
}

inline void nearest_box(const ReferenceScene& scene, vec3 o, vec3 d, float margin, Nearest& n) {
  float far = 1e6f;
  for (size_t i = 0; i < scene.boxes.size(); ++i) {
    const ReferenceBox& box = scene.boxes[i];
    float entry, shrunk_entry;
    bool grown = segment_meets_box(o, o + d * far, box, margin, entry);
    bool shrunk = segment_meets_box(o, o + d * far, box, -margin, shrunk_entry);
    if (grown != shrunk) n.near_edge = true;
    if (!segment_meets_box(o, o + d * far, box, 0, entry) || entry * far >= n.t) continue;
    vec3 p = o + d * (entry * far), center = (box.lower + box.upper) * 0.5f, half = (box.upper - box.lower) * 0.5f;
    vec3 normal;
    int axis = 0, close_faces = 0;
    for (int k = 0; k < 3; ++k) {
      close_faces += std::abs(std::abs(p[k] - center[k]) - half[k]) < margin;
      if (std::abs(p[k] - center[k]) / half[k] > std::abs(p[axis] - center[axis]) / half[axis]) axis = k;
    }
    normal[axis] = p[axis] > center[axis] ? 1.0f : -1.0f;
    n = {entry * far, int(scene.spheres.size() + i), normal, n.near_edge || close_faces > 1};
  }
}

}  // namespace reference_detail

// Classifies one camera ray; `margin` (world units) keeps clear of silhouettes, box edges and
// shadow edges, where a float's worth of difference decides the answer.
inline ReferencePixel reference_pixel(const ReferenceScene& scene, const Ray& ray, float margin) {
  using namespace reference_detail;
  Nearest n;
  if (scene.has_plane && ray.direction.y < 0) n = {-ray.origin.y / ray.direction.y, -1, {0, 1, 0}, false};
  nearest_sphere(scene, ray.origin, ray.direction, margin, n);
  nearest_box(scene, ray.origin, ray.direction, margin, n);
  ReferencePixel pixel;
  if (n.near_edge || !std::isfinite(n.t)) return pixel;
  vec3 p = ray.origin + ray.direction * n.t;
  if (n.object < 0) p.y = 0;
  vec3 to_light = scene.light - p;
  float d2 = dot(to_light, to_light);
  float cos_theta = dot(n.normal, to_light) / std::sqrt(d2);
  if (std::abs(cos_theta) < 0.02f) return pixel;  // at the terminator
  if (cos_theta > 0 && !segment_meets_others(scene, p, scene.light, margin, n.object)) {
    pixel.kind = ReferenceKind::lit;
    pixel.value = scene.ambient + scene.kd * inv_pi * scene.intensity * cos_theta / d2;
  } else if (cos_theta < 0 || segment_meets_others(scene, p, scene.light, -margin, n.object)) {
    pixel.kind = ReferenceKind::shadowed;
    pixel.value = scene.ambient;
  }
  return pixel;
}

struct ReferenceCheck {
  int lit = 0, shadowed = 0;
  int dark_speckles = 0;  // lit pixels below half their analytic value (shadow acne)
  int light_leaks = 0;    // shadowed pixels not exactly the ambient term
  float max_lit_relative_error = 0;
};

// Compares a one-sample-per-pixel Whitted film (samples through pixel centres) taken with
// `camera` against the reference, pixel by pixel.
inline ReferenceCheck check_against_reference(const Film& film, const CameraDesc& camera,
                                              const ReferenceScene& reference, float margin) {
  CameraFrame frame = make_camera_frame(camera, film.width, film.height);
  ReferenceCheck check;
  for (int y = 0; y < film.height; ++y)
    for (int x = 0; x < film.width; ++x) {
      ReferencePixel expected = reference_pixel(reference, *generate_camera_ray(frame, x + 0.5f, y + 0.5f), margin);
      float got = pixel_mean(film.at(x, y)).x;
      if (expected.kind == ReferenceKind::lit) {
        ++check.lit;
        check.dark_speckles += got < 0.5f * expected.value;
        check.max_lit_relative_error = std::max(check.max_lit_relative_error, std::abs(got - expected.value) / expected.value);
      } else if (expected.kind == ReferenceKind::shadowed) {
        ++check.shadowed;
        check.light_leaks += std::abs(got - expected.value) > 1e-6f;
      }
    }
  return check;
}

}  // namespace radiant::test

// What the light BVH knows of a group of lights: where they are, which way they emit and how
// bright they are, and from that an estimate of how much they light a given point (pbrt-v4's
// LightBounds, after Conty Estevez and Kulla's many-light cones).
#pragma once

#include "math/vec.h"

namespace radiant {

struct LightBounds {
  vec3 lower, upper;         // box around every emitting point
  vec3 axis = {0, 0, 1};     // unit centre of the cone of emitting normals
  float cos_spread = 1;      // cos theta_o: every emitting normal lies within theta_o of `axis`
  float cos_falloff = 0;     // cos theta_e: how far past its normal a point still emits (pi/2: Lambertian)
  float intensity = 0;       // radiant intensity along the normal, up to a common factor; 0 = emits nothing
  bool two_sided = false;    // emits along -normal too
};

// Bounds of a point emitting `intensity` within `cos_falloff` of `axis` (all directions: -1).
LightBounds point_light_bounds(vec3 position, vec3 axis, float cos_spread, float cos_falloff, float intensity);

// Bounds covering both (a group of lights); a side of intensity 0 is ignored.
LightBounds merge(const LightBounds& a, const LightBounds& b);

// Estimated light from the group at point `p` of a surface with unit normal `n` (zero vector for a
// point in a medium): intensity x the largest emitter cosine any light of the group can have
// towards p x the largest receiver cosine / squared distance; 0 only when no light of the group
// can reach p. Conservative: never 0 for a group that lights p.
float importance(const LightBounds& bounds, vec3 p, vec3 n);

// The directional measure of pbrt-v4's split cost: the solid angle the group's cone of normals
// widened by its falloff covers, weighted by cosine.
float orientation_measure(const LightBounds& bounds);

}  // namespace radiant

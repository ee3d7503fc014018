// Small fixed-size vectors for geometry and color: plain structs, free functions.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace radiant {

struct vec2 {
  float x = 0, y = 0;
};

struct vec3 {
  float x = 0, y = 0, z = 0;
  constexpr float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

struct vec4 {
  float x = 0, y = 0, z = 0, w = 0;
};

// Linear RGB radiance, reflectance or intensity; the same arithmetic as vec3.
using color3 = vec3;

// ---------------------------------------------------------------- vec2
constexpr vec2 operator+(vec2 a, vec2 b) { return {a.x + b.x, a.y + b.y}; }
constexpr vec2 operator-(vec2 a, vec2 b) { return {a.x - b.x, a.y - b.y}; }
constexpr vec2 operator*(vec2 a, float s) { return {a.x * s, a.y * s}; }
constexpr vec2 operator*(float s, vec2 a) { return {a.x * s, a.y * s}; }

// ---------------------------------------------------------------- vec3
constexpr vec3 operator+(vec3 a, vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr vec3 operator-(vec3 a, vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr vec3 operator-(vec3 a) { return {-a.x, -a.y, -a.z}; }
constexpr vec3 operator*(vec3 a, vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr vec3 operator/(vec3 a, vec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
constexpr vec3 operator*(vec3 a, float s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr vec3 operator*(float s, vec3 a) { return {a.x * s, a.y * s, a.z * s}; }
constexpr vec3 operator/(vec3 a, float s) { return {a.x / s, a.y / s, a.z / s}; }
constexpr vec3& operator+=(vec3& a, vec3 b) { return a = a + b; }
constexpr vec3& operator-=(vec3& a, vec3 b) { return a = a - b; }
constexpr vec3& operator*=(vec3& a, vec3 b) { return a = a * b; }
constexpr vec3& operator*=(vec3& a, float s) { return a = a * s; }
constexpr vec3& operator/=(vec3& a, float s) { return a = a / s; }
constexpr bool operator==(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

constexpr float dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr vec3 cross(vec3 a, vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(vec3 a) { return std::sqrt(dot(a, a)); }
constexpr float length_squared(vec3 a) { return dot(a, a); }
vec3 normalize_rescaled(vec3 a);
// One division and three products: the compiler may not turn a / l into that itself, and three
// divisions cost more than the rest of a normalization (the result differs by at most an ulp).
// A vector whose squared length leaves float's normal range (the cross product of a huge
// triangle's edges overflows it, a tiny one's underflows) is scaled down or up first; the zero
// vector, infinities and NaN come back unchanged.
inline vec3 normalize(vec3 a) {
  float l2 = dot(a, a);
  if (!(l2 >= std::numeric_limits<float>::min() && l2 <= std::numeric_limits<float>::max())) [[unlikely]]
    return normalize_rescaled(a);
  return a * (1 / std::sqrt(l2));
}
inline vec3 abs(vec3 a) { return {std::abs(a.x), std::abs(a.y), std::abs(a.z)}; }
inline vec3 exp(vec3 a) { return {std::exp(a.x), std::exp(a.y), std::exp(a.z)}; }
inline vec3 min(vec3 a, vec3 b) { return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)}; }
inline vec3 max(vec3 a, vec3 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)}; }
constexpr float max_component(vec3 a) { return std::max(a.x, std::max(a.y, a.z)); }
constexpr float min_component(vec3 a) { return std::min(a.x, std::min(a.y, a.z)); }
constexpr float mean(vec3 a) { return (a.x + a.y + a.z) / 3.0f; }
// Rec. 709 luminance of a linear RGB color.
constexpr float luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }
inline bool is_finite(vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
constexpr bool is_black(vec3 a) { return a.x == 0 && a.y == 0 && a.z == 0; }
constexpr vec3 lerp(vec3 a, vec3 b, float t) { return a * (1 - t) + b * t; }

// Mirror direction `d` (pointing away from the surface) about normal `n`.
constexpr vec3 reflect(vec3 d, vec3 n) { return 2.0f * dot(d, n) * n - d; }

// Refract `d` (pointing away from the surface, on the side of `n`) through a surface with relative
// index eta = n_transmitted / n_incident. Returns false on total internal reflection.
inline bool refract(vec3 d, vec3 n, float eta, vec3& out) {
  float cos_i = dot(n, d);
  float sin2_i = std::max(0.0f, 1.0f - cos_i * cos_i);
  float sin2_t = sin2_i / (eta * eta);
  if (sin2_t >= 1.0f) return false;
  float cos_t = std::sqrt(1.0f - sin2_t);
  out = -d / eta + (cos_i / eta - cos_t) * n;
  return true;
}

// An orthonormal basis around unit vector n (Duff et al. 2017, branchless and stable).
inline void orthonormal_basis(vec3 n, vec3& t, vec3& b) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float c = n.x * n.y * a;
  t = {1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

constexpr float pi = 3.14159265358979323846f;
constexpr float inv_pi = 1.0f / pi;

}  // namespace radiant

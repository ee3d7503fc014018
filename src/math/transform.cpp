#include "math/transform.h"

#include <cmath>
#include <limits>

namespace radiant {

mat4 operator*(const mat4& a, const mat4& b) {
  mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      float s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

mat4 translation(vec3 t) {
  mat4 r;
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

mat4 scaling(vec3 s) {
  mat4 r;
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

mat4 rotation_quaternion(vec4 q) {
  float x = q.x, y = q.y, z = q.z, w = q.w;
  mat4 r;
  r.m[0][0] = 1 - 2 * (y * y + z * z);
  r.m[0][1] = 2 * (x * y - z * w);
  r.m[0][2] = 2 * (x * z + y * w);
  r.m[1][0] = 2 * (x * y + z * w);
  r.m[1][1] = 1 - 2 * (x * x + z * z);
  r.m[1][2] = 2 * (y * z - x * w);
  r.m[2][0] = 2 * (x * z - y * w);
  r.m[2][1] = 2 * (y * z + x * w);
  r.m[2][2] = 1 - 2 * (x * x + y * y);
  return r;
}

mat4 rotation_axis(vec3 axis, float degrees) {
  float half = degrees * pi / 360.0f;
  vec3 a = normalize(axis) * std::sin(half);
  return rotation_quaternion({a.x, a.y, a.z, std::cos(half)});
}

float determinant3(const mat4& a) {
  const auto& m = a.m;
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool inverse_affine(const mat4& a, mat4& out) {
  // Computed in double: instance transforms far from the origin lose digits in float.
  const auto& m = a.m;
  double det = double(m[0][0]) * (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) -
               double(m[0][1]) * (double(m[1][0]) * m[2][2] - double(m[1][2]) * m[2][0]) +
               double(m[0][2]) * (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]);
  if (det == 0 || !std::isfinite(det)) return false;
  double inv[3][3];
  inv[0][0] = (double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1]) / det;
  inv[0][1] = (double(m[0][2]) * m[2][1] - double(m[0][1]) * m[2][2]) / det;
  inv[0][2] = (double(m[0][1]) * m[1][2] - double(m[0][2]) * m[1][1]) / det;
  inv[1][0] = (double(m[1][2]) * m[2][0] - double(m[1][0]) * m[2][2]) / det;
  inv[1][1] = (double(m[0][0]) * m[2][2] - double(m[0][2]) * m[2][0]) / det;
  inv[1][2] = (double(m[0][2]) * m[1][0] - double(m[0][0]) * m[1][2]) / det;
  inv[2][0] = (double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0]) / det;
  inv[2][1] = (double(m[0][1]) * m[2][0] - double(m[0][0]) * m[2][1]) / det;
  inv[2][2] = (double(m[0][0]) * m[1][1] - double(m[0][1]) * m[1][0]) / det;
  out = mat4{};
  for (int i = 0; i < 3; ++i) {
    double t = 0;
    for (int j = 0; j < 3; ++j) {
      out.m[i][j] = float(inv[i][j]);
      t -= inv[i][j] * m[j][3];
    }
    out.m[i][3] = float(t);
  }
  return true;
}

bool inverse_survives_float(const mat4& a) {
  mat4 exact;
  if (!inverse_affine(a, exact)) return false;
  // Embree's arithmetic: the columns' cross products over their triple product, all in float.
  vec3 c0 = {a.m[0][0], a.m[1][0], a.m[2][0]}, c1 = {a.m[0][1], a.m[1][1], a.m[2][1]},
       c2 = {a.m[0][2], a.m[1][2], a.m[2][2]};
  vec3 adjoint_rows[3] = {cross(c1, c2), cross(c2, c0), cross(c0, c1)};
  float det = dot(c0, adjoint_rows[0]);
  if (!(std::abs(det) >= std::numeric_limits<float>::min() && std::abs(det) <= std::numeric_limits<float>::max()))
    return false;
  for (int r = 0; r < 3; ++r) {
    vec3 in_float = adjoint_rows[r] * (1 / det);
    vec3 want = {exact.m[r][0], exact.m[r][1], exact.m[r][2]};
    vec3 error = abs(in_float - want);
    float bound = 1e-4f * max_component(abs(want));
    if (!(error.x <= bound && error.y <= bound && error.z <= bound)) return false;  // NaN fails too
  }
  return true;
}

bool is_finite(const mat4& a) {
  for (const auto& row : a.m)
    for (float v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

bool is_identity(const mat4& a) {
  mat4 id;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (a.m[i][j] != id.m[i][j]) return false;
  return true;
}

mat4 compose_trs(vec3 t, vec4 q, vec3 s) {
  float length = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return translation(t) * rotation_quaternion({q.x / length, q.y / length, q.z / length, q.w / length}) * scaling(s);
}

}  // namespace radiant

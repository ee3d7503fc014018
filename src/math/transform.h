// Affine transforms as 4x4 row-major matrices (last row 0 0 0 1 for affine ones).
#pragma once

#include <cmath>

#include "math/vec.h"

namespace radiant {

struct mat4 {
  float m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
};

mat4 operator*(const mat4& a, const mat4& b);
mat4 translation(vec3 t);
mat4 scaling(vec3 s);
// Rotation by unit quaternion (x, y, z, w), the glTF convention.
mat4 rotation_quaternion(vec4 q);
// T * R * S, glTF's composition of a translation, a rotation by quaternion q (normalized here;
// it must have a non-zero length) and a scale.
mat4 compose_trs(vec3 t, vec4 q, vec3 s);
// Rotation by `degrees` around unit `axis`.
mat4 rotation_axis(vec3 axis, float degrees);
// Inverse of an affine matrix; returns false when singular.
bool inverse_affine(const mat4& a, mat4& out);
float determinant3(const mat4& a);
// Whether the inverse of `a` survives single precision. Embree inverts an instance's transform
// itself, in float (the adjoint over the determinant), and aborts on the non-finite rays a failed
// inverse makes. False for a singular transform; for one so close to singular that the float
// inverse strays from the exact one by more than 1e-4 of a row's size; and for a scale whose
// determinant leaves float's normal range (a uniform scale below about 2.3e-13).
bool inverse_survives_float(const mat4& a);
bool is_finite(const mat4& a);
bool is_identity(const mat4& a);

inline vec3 transform_point(const mat4& a, vec3 p) {
  return {a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2] * p.z + a.m[0][3],
          a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2] * p.z + a.m[1][3],
          a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2] * p.z + a.m[2][3]};
}
inline vec3 transform_vector(const mat4& a, vec3 v) {
  return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
          a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
          a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
}
// transform_vector by the matrix of |a|'s entries: how far errors in v's coordinates can move the
// result (hit positions' error bounds).
inline vec3 abs_transform_vector(const mat4& a, vec3 v) {
  return {std::abs(a.m[0][0]) * v.x + std::abs(a.m[0][1]) * v.y + std::abs(a.m[0][2]) * v.z,
          std::abs(a.m[1][0]) * v.x + std::abs(a.m[1][1]) * v.y + std::abs(a.m[1][2]) * v.z,
          std::abs(a.m[2][0]) * v.x + std::abs(a.m[2][1]) * v.y + std::abs(a.m[2][2]) * v.z};
}
// Normals transform by the inverse transpose; pass the inverse matrix.
inline vec3 transform_normal(const mat4& inverse, vec3 n) {
  return {inverse.m[0][0] * n.x + inverse.m[1][0] * n.y + inverse.m[2][0] * n.z,
          inverse.m[0][1] * n.x + inverse.m[1][1] * n.y + inverse.m[2][1] * n.z,
          inverse.m[0][2] * n.x + inverse.m[1][2] * n.y + inverse.m[2][2] * n.z};
}

}  // namespace radiant

// A double-precision 3-vector for the few computations that need it (analytic shapes far from
// the origin, exact reference geometry in tests).
#pragma once

#include "math/vec.h"

namespace radiant {

struct dvec3 {
  double x, y, z;
};
inline dvec3 to_double(vec3 v) { return {v.x, v.y, v.z}; }
inline vec3 to_float(dvec3 v) { return {float(v.x), float(v.y), float(v.z)}; }
inline dvec3 operator-(dvec3 a, dvec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline dvec3 operator+(dvec3 a, dvec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline dvec3 operator*(dvec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline dvec3 cross(dvec3 a, dvec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace radiant

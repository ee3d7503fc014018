#include "math/vec.h"

namespace radiant {

// Out of line and rarely taken: dividing by the largest magnitude first brings the squared
// length near 1, whatever the scale. Only a vector with a zero, infinite or NaN largest
// magnitude has no direction to give.
vec3 normalize_rescaled(vec3 a) {
  float largest = max_component(abs(a));
  if (!(largest > 0) || !std::isfinite(largest)) return a;
  vec3 scaled = {a.x / largest, a.y / largest, a.z / largest};  // 1 / largest may overflow
  return scaled * (1 / length(scaled));
}

}  // namespace radiant

#include "accel/motion_geometry.h"

namespace radiant {

void set_transform_motion(RTCGeometry instance, const std::vector<mat4>& steps) {
  rtcSetGeometryTimeStepCount(instance, unsigned(steps.size()));
  for (size_t k = 0; k < steps.size(); ++k) {
    float rows[12];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) rows[r * 4 + c] = steps[k].m[r][c];
    rtcSetGeometryTransform(instance, unsigned(k), RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
  }
}

void set_vertex_motion(RTCGeometry triangles, const std::vector<std::vector<vec3>>& steps) {
  rtcSetGeometryTimeStepCount(triangles, unsigned(steps.size()));
  for (size_t k = 0; k < steps.size(); ++k) {
    const std::vector<vec3>& positions = steps[k];
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(triangles, RTC_BUFFER_TYPE_VERTEX, unsigned(k),
                                                                 RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
    for (size_t i = 0; i < positions.size(); ++i)
      vertices[3 * i + 0] = positions[i].x, vertices[3 * i + 1] = positions[i].y, vertices[3 * i + 2] = positions[i].z;
  }
}

}  // namespace radiant

#include "accel/stroke_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace radiant {

float stroke_radius(const StrokeDesc& stroke, size_t i, const StrokeSizing& sizing) {
  if (stroke.width > 0) return stroke.width / 2;
  const LineWidth& w = sizing.line_width;
  if (!w.in_pixels) return w.value / 2;
  vec3 p = stroke.center + stroke.positions[i];
  float pixel = sizing.footprint.per_unit_distance * length(p - sizing.footprint.camera) + sizing.footprint.constant;
  return std::max(w.value * pixel / 2, 0.0f);
}

namespace {

// Which neighbours each segment of `stroke` joins: Embree rounds a polyline's inner joints
// only where the segments say so (RTCCurveFlags).
void write_segment_flags(uint8_t* flags, const StrokeDesc& stroke) {
  const std::vector<uint32_t>& s = stroke.segments;
  for (size_t k = 0; k < s.size(); ++k) {
    bool left = k > 0 && s[k - 1] + 1 == s[k];
    bool right = k + 1 < s.size() && s[k] + 1 == s[k + 1];
    flags[k] = uint8_t((left ? RTC_CURVE_FLAG_NEIGHBOR_LEFT : 0) | (right ? RTC_CURVE_FLAG_NEIGHBOR_RIGHT : 0));
  }
}

}  // namespace

RTCGeometry new_stroke_geometry(RTCDevice device, const StrokeDesc& stroke, const StrokeSizing& sizing,
                                float& max_radius) {
  bool lines = stroke.kind == StrokeKind::lines;
  RTCGeometry geometry =
      rtcNewGeometry(device, lines ? RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE : RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                               4 * sizeof(float), stroke.positions.size()));
  max_radius = 0;
  for (size_t i = 0; i < stroke.positions.size(); ++i) {
    vec3 p = stroke.center + stroke.positions[i];
    float radius = stroke_radius(stroke, i, sizing);
    max_radius = std::max(max_radius, radius);
    vertices[4 * i + 0] = p.x, vertices[4 * i + 1] = p.y, vertices[4 * i + 2] = p.z, vertices[4 * i + 3] = radius;
  }
  if (lines) {
    auto* starts = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT,
                                                                  sizeof(uint32_t), stroke.segments.size()));
    std::copy(stroke.segments.begin(), stroke.segments.end(), starts);
    auto* flags = static_cast<uint8_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_FLAGS, 0, RTC_FORMAT_UCHAR,
                                                                sizeof(uint8_t), stroke.segments.size()));
    write_segment_flags(flags, stroke);
  }
  rtcCommitGeometry(geometry);
  return geometry;
}

}  // namespace radiant

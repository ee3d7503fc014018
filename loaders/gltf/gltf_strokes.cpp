#include "gltf/gltf_strokes.h"

#include "math/dvec3.h"
#include "scene/scene_memory.h"

namespace radiant {

namespace {

// The vertices a line mode draws through, in order, with the first vertex of each segment:
// LINES pairs them, LINE_STRIP chains them, LINE_LOOP chains them back to the first.
void line_vertices(int mode, const std::vector<uint32_t>& order, std::vector<uint32_t>& drawn,
                   std::vector<uint32_t>& segments) {
  size_t n = order.size();
  if (mode == TINYGLTF_MODE_LINE) {
    for (size_t i = 0; i + 1 < n; i += 2) {
      segments.push_back(uint32_t(drawn.size()));
      drawn.insert(drawn.end(), {order[i], order[i + 1]});
    }
    return;
  }
  if (n < 2) return;
  drawn = order;
  if (mode == TINYGLTF_MODE_LINE_LOOP) drawn.push_back(order[0]);
  for (size_t i = 0; i + 1 < drawn.size(); ++i) segments.push_back(uint32_t(i));
}

}  // namespace

void add_primitive_stroke(GltfContext& context, int mode, const MeshDesc& vertices, const std::vector<uint32_t>& order,
                          int material, const std::string& where, std::vector<StrokeDesc>& strokes) {
  StrokeDesc stroke;
  stroke.name = vertices.name;
  stroke.material = material;
  std::vector<uint32_t> drawn;
  if (mode == TINYGLTF_MODE_POINTS) {
    stroke.kind = StrokeKind::points;
    drawn = order;
  } else {
    context.charge(saturating_multiply(order.size(), 3 * sizeof(uint32_t)), where);
    line_vertices(mode, order, drawn, stroke.segments);
  }
  if (drawn.empty()) {
    context.warn(where + ": no " + (mode == TINYGLTF_MODE_POINTS ? "points" : "line segments") + "; primitive skipped");
    return;
  }
  bool colored = !vertices.colors.empty();
  context.charge(saturating_multiply(drawn.size(), sizeof(vec3) + (colored ? sizeof(vec4) : 0)), where);
  stroke.positions.reserve(drawn.size());
  for (uint32_t v : drawn) stroke.positions.push_back(vertices.positions[v]);
  if (colored)
    for (uint32_t v : drawn) stroke.colors.push_back(vertices.colors[v]);
  strokes.push_back(std::move(stroke));
}

void place_strokes(GltfContext& context, const std::vector<StrokeDesc>& strokes, const mat4& world) {
  for (const StrokeDesc& source : strokes) {
    context.charge(stroke_bytes(source), source.name + " (placed lines or points)");
    StrokeDesc stroke = source;
    // Around the node's origin, placed in double: far from the world's origin the vertices keep
    // their precision relative to each other, as a mesh under an instance does.
    dvec3 origin = {world.m[0][3], world.m[1][3], world.m[2][3]};
    stroke.center = to_float(origin);
    for (vec3& p : stroke.positions) {
      auto row = [&](int r) { return double(world.m[r][0]) * p.x + double(world.m[r][1]) * p.y + double(world.m[r][2]) * p.z; };
      dvec3 placed = origin + dvec3{row(0), row(1), row(2)};
      p = to_float(placed - to_double(stroke.center));
    }
    context.scene.strokes.push_back(std::move(stroke));
  }
}

}  // namespace radiant

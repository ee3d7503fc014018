#include "scene/scene_memory.h"

#include "memory/memory_budget.h"

namespace radiant {

namespace {

template <typename T>
uint64_t array_bytes(const std::vector<T>& values) {
  return uint64_t(values.capacity()) * sizeof(T);
}

uint64_t string_bytes(const std::string& text) { return text.capacity() + 1; }

}  // namespace

uint64_t vertex_bytes(const MeshDesc& mesh) {
  uint64_t bytes = sizeof(vec3);  // the position
  if (!mesh.normals.empty()) bytes += sizeof(vec3);
  if (!mesh.tangents.empty()) bytes += sizeof(vec4);
  if (!mesh.texcoords0.empty()) bytes += sizeof(vec2);
  if (!mesh.texcoords1.empty()) bytes += sizeof(vec2);
  if (!mesh.colors.empty()) bytes += sizeof(vec4);
  return bytes;
}

uint64_t mesh_bytes(const MeshDesc& mesh) {
  return sizeof(MeshDesc) + string_bytes(mesh.name) + array_bytes(mesh.positions) + array_bytes(mesh.normals) +
         array_bytes(mesh.tangents) + array_bytes(mesh.texcoords0) + array_bytes(mesh.texcoords1) +
         array_bytes(mesh.colors) + array_bytes(mesh.indices) +
         saturating_multiply(mesh.motion_positions.size(), sizeof(std::vector<vec3>) + array_bytes(mesh.positions));
}

uint64_t stroke_bytes(const StrokeDesc& stroke) {
  return sizeof(StrokeDesc) + string_bytes(stroke.name) + array_bytes(stroke.positions) + array_bytes(stroke.colors) +
         array_bytes(stroke.segments);
}

uint64_t instance_bytes(const InstanceDesc& instance) {
  return sizeof(InstanceDesc) + string_bytes(instance.name) + array_bytes(instance.motion);
}

uint64_t scene_memory_bytes(const SceneDesc& scene) {
  uint64_t bytes = sizeof(SceneDesc);
  for (const MeshDesc& mesh : scene.meshes) bytes += mesh_bytes(mesh);
  for (const ImageDesc& image : scene.images)
    bytes += sizeof(ImageDesc) + string_bytes(image.name) + array_bytes(image.texels8) + array_bytes(image.texels_float);
  for (const MaterialDesc& material : scene.materials) bytes += sizeof(MaterialDesc) + string_bytes(material.name);
  for (const InstanceDesc& instance : scene.instances) bytes += instance_bytes(instance);
  for (const ShapeDesc& shape : scene.shapes) bytes += sizeof(ShapeDesc) + string_bytes(shape.name);
  for (const StrokeDesc& stroke : scene.strokes) bytes += stroke_bytes(stroke);
  for (const CameraDesc& camera : scene.cameras)
    bytes += sizeof(CameraDesc) + string_bytes(camera.name) + array_bytes(camera.motion);
  for (const LightDesc& light : scene.lights) bytes += sizeof(LightDesc) + string_bytes(light.name);
  for (const std::string& warning : scene.warnings) bytes += sizeof(std::string) + string_bytes(warning);
  return bytes + array_bytes(scene.textures);
}

uint64_t shading_frame_bytes(const MeshDesc& mesh, bool normal_mapped) {
  // Unwelded, each corner is a vertex; normals and tangents join it, and generating them needs
  // one vec3 sum per vertex (normals) or two (tangents and bitangents) on the side.
  uint64_t vertices = normal_mapped ? mesh.indices.size() : mesh.positions.size();
  uint64_t per_vertex = (normal_mapped ? vertex_bytes(mesh) : 0) + sizeof(vec3) + sizeof(vec4) + 2 * sizeof(vec3);
  return vertices * per_vertex;
}

}  // namespace radiant

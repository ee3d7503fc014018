#include "scene/validate.h"

#include <cmath>
#include <cstdio>

#include "scene/load_error.h"
#include "scene/coordinate_range.h"

namespace radiant {

namespace {

struct Checker {
  const SceneDesc& scene;

  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw LoadError(scene.source_path + ": " + where + ": " + message);
  }
  static std::string at(const std::string& name, size_t index) { return name + "[" + std::to_string(index) + "]"; }

  void index(int value, size_t size, bool optional, const std::string& where, const std::string& what) const {
    if (optional && value == -1) return;
    if (value < 0 || size_t(value) >= size)
      fail(where, what + " " + std::to_string(value) + " out of range (" + std::to_string(size) + " " + what + (what.back() == 'h' ? "es)" : "s)"));
  }
  void finite(float value, const std::string& where) const {
    if (!std::isfinite(value)) fail(where, "non-finite value");
  }
  void finite(vec3 value, const std::string& where) const {
    if (!is_finite(value)) fail(where, "non-finite value");
  }
  // Positions and sizes radiant can trace (scene/coordinate_range.h).
  void in_range(double value, const std::string& where) const {
    if (!std::isfinite(value)) fail(where, "non-finite value");
    if (std::abs(value) > max_scene_coordinate) {
      char text[32];
      std::snprintf(text, sizeof text, "%g", value);
      fail(where, std::string(text) + " is beyond the supported range of coordinates and sizes (magnitude up to " +
                      max_scene_coordinate_text + ")");
    }
  }
  void in_range(vec3 value, const std::string& where) const {
    for (int i = 0; i < 3; ++i) in_range(value[i], where);
  }
  // Radiance, reflectance and intensity: finite and not negative (negative light has no meaning).
  void non_negative(vec3 value, const std::string& where) const {
    finite(value, where);
    if (min_component(value) < 0) fail(where, "negative value");
  }
  void unit(vec3 value, const std::string& where) const {
    finite(value, where);
    if (!(length(value) > 0)) fail(where, "zero-length direction");
  }
  template <typename T>
  void sized(const std::vector<T>& values, size_t vertices, const std::string& where) const {
    if (!values.empty() && values.size() != vertices)
      fail(where, std::to_string(values.size()) + " values for " + std::to_string(vertices) + " vertices");
  }

  void texture_ref(const TextureRef& ref, const std::string& where) const {
    index(ref.texture, scene.textures.size(), true, where + ".texture", "texture");
    finite({ref.offset.x, ref.offset.y, ref.rotation}, where + ".transform");
    finite({ref.scale.x, ref.scale.y, 0}, where + ".transform");
  }

  void material(const MaterialDesc& m, const std::string& where) const {
    const std::pair<const char*, vec3> colors[] = {{"ka", m.ka}, {"kd", m.kd}, {"ks", m.ks}, {"kr", m.kr},
                                                   {"kt", m.kt}, {"base_color", m.base_color}, {"emission", m.emission},
                                                   {"specular_color", m.specular_color}, {"sheen_color", m.sheen_color},
                                                   {"attenuation_color", m.attenuation_color},
                                                   {"diffuse_transmission_color", m.diffuse_transmission_color}};
    for (const auto& [name, color] : colors) non_negative(color, where + "." + name);
    for (float f : {m.shininess, m.ior, m.alpha, m.metallic, m.roughness, m.transmission, m.normal_scale,
                    m.alpha_cutoff, m.specular, m.clearcoat, m.clearcoat_roughness,
                    m.sheen_roughness, m.thickness, m.attenuation_distance, m.iridescence, m.iridescence_thickness_min,
                    m.iridescence_thickness_max, m.anisotropy_strength, m.anisotropy_rotation, m.bump_scale,
                    m.clearcoat_normal_scale, m.diffuse_transmission})
      finite(f, where);
    // Beyond these, refraction's eta^2 overflows float and directions stop being numbers.
    constexpr float min_ior = 1e-3f, max_ior = 1e3f;
    if (!(m.ior >= min_ior && m.ior <= max_ior)) {
      char text[64];
      std::snprintf(text, sizeof text, "%g is out of range (%g to %g)", m.ior, min_ior, max_ior);
      fail(where + ".ior", text);
    }
    texture_ref(m.base_color_texture, where + ".base_color_texture");
    texture_ref(m.metallic_roughness_texture, where + ".metallic_roughness_texture");
    texture_ref(m.normal_texture, where + ".normal_texture");
    texture_ref(m.bump_texture, where + ".bump_texture");
    texture_ref(m.transmission_texture, where + ".transmission_texture");
    texture_ref(m.specular_texture, where + ".specular_texture");
    texture_ref(m.alpha_texture, where + ".alpha_texture");
    texture_ref(m.specular_strength_texture, where + ".specular_strength_texture");
    texture_ref(m.specular_color_texture, where + ".specular_color_texture");
    texture_ref(m.clearcoat_texture, where + ".clearcoat_texture");
    texture_ref(m.clearcoat_roughness_texture, where + ".clearcoat_roughness_texture");
    texture_ref(m.clearcoat_normal_texture, where + ".clearcoat_normal_texture");
    texture_ref(m.sheen_color_texture, where + ".sheen_color_texture");
    texture_ref(m.sheen_roughness_texture, where + ".sheen_roughness_texture");
    texture_ref(m.iridescence_texture, where + ".iridescence_texture");
    texture_ref(m.anisotropy_texture, where + ".anisotropy_texture");
    texture_ref(m.iridescence_thickness_texture, where + ".iridescence_thickness_texture");
    texture_ref(m.diffuse_transmission_texture, where + ".diffuse_transmission_texture");
    texture_ref(m.diffuse_transmission_color_texture, where + ".diffuse_transmission_color_texture");
    if (!(m.iridescence_ior >= min_ior && m.iridescence_ior <= max_ior)) {
      char text[64];
      std::snprintf(text, sizeof text, "%g is out of range (%g to %g)", m.iridescence_ior, min_ior, max_ior);
      fail(where + ".iridescence_ior", text);
    }
    texture_ref(m.emission_texture, where + ".emission_texture");
  }

  void mesh(const MeshDesc& m, const std::string& where) const {
    index(m.material, scene.materials.size(), false, where + ".material", "material");
    size_t vertices = m.positions.size();
    sized(m.normals, vertices, where + ".normals");
    sized(m.tangents, vertices, where + ".tangents");
    sized(m.texcoords0, vertices, where + ".texcoords0");
    sized(m.texcoords1, vertices, where + ".texcoords1");
    sized(m.colors, vertices, where + ".colors");
    if (m.indices.size() % 3 != 0) fail(where + ".indices", "not a multiple of 3");
    for (size_t i = 0; i < m.indices.size(); ++i)
      if (m.indices[i] >= vertices)
        fail(at(where + ".indices", i), "index " + std::to_string(m.indices[i]) + " out of range (" +
                                           std::to_string(vertices) + " vertices)");
    for (size_t i = 0; i < vertices; ++i) in_range(m.positions[i], at(where + ".positions", i));
    for (size_t i = 0; i < m.normals.size(); ++i) unit(m.normals[i], at(where + ".normals", i));
  }

  void image(const ImageDesc& image, const std::string& where) const {
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0 || image.channels > 4)
      fail(where, "invalid size " + std::to_string(image.width) + "x" + std::to_string(image.height) + "x" +
                      std::to_string(image.channels));
    size_t texels = size_t(image.width) * size_t(image.height) * size_t(image.channels);
    if (image.texels8.size() != texels && image.texels_float.size() != texels)
      fail(where, "texel count does not match the size");
  }

  void camera(const CameraDesc& c, const std::string& where) const {
    in_range(c.position, where + ".position");
    unit(c.forward, where + ".forward");
    unit(c.up, where + ".up");
    if (!(c.vertical_fov_degrees > 0 && c.vertical_fov_degrees < 180)) fail(where, "field of view out of (0, 180)");
    if (!(c.ortho_height > 0) || !std::isfinite(c.ortho_height)) fail(where, "orthographic height must be positive");
    in_range(c.ortho_height, where + ".orthographic_height");
    if (!(c.aspect >= 0) || !std::isfinite(c.aspect)) fail(where, "aspect must be positive");
    if (!(c.fisheye_fov_degrees > 0 && c.fisheye_fov_degrees <= 360)) fail(where, "fisheye field of view out of (0, 360]");
    if (!(c.lens_radius >= 0)) fail(where + ".lens_radius", "must not be negative");
    in_range(c.lens_radius, where + ".lens_radius");
    if (!(c.focus_distance >= 0)) fail(where + ".focus_distance", "must not be negative");
    in_range(c.focus_distance, where + ".focus_distance");
  }

  void light(const LightDesc& l, const std::string& where) const {
    non_negative(l.intensity, where + ".intensity");
    in_range(l.position, where + ".position");
    if (l.kind == LightKind::directional || l.kind == LightKind::spot) unit(l.direction, where + ".direction");
    for (float f : {l.kc, l.kl, l.kq, l.spot_exponent, l.inner_cone, l.outer_cone, l.range})
      finite(f, where);
  }

  void shape(const ShapeDesc& s, const std::string& where) const {
    index(s.material, scene.materials.size(), false, where + ".material", "material");
    in_range(s.center, where + ".center");
    if (s.kind != ShapeKind::sphere) unit(s.axis, where + ".axis");
    if (!(s.radius > 0) || !std::isfinite(s.radius)) fail(where + ".radius", "must be positive");
    in_range(s.radius, where + ".radius");
    if (s.kind == ShapeKind::cylinder && (!(s.height > 0) || !std::isfinite(s.height)))
      fail(where + ".height", "must be positive");
    if (s.kind == ShapeKind::cylinder) in_range(s.height, where + ".height");
  }

  void stroke(const StrokeDesc& s, const std::string& where) const {
    index(s.material, scene.materials.size(), false, where + ".material", "material");
    in_range(s.center, where + ".center");
    for (vec3 p : s.positions) in_range(s.center + p, where + ".positions");
    sized(s.colors, s.positions.size(), where + ".colors");
    for (uint32_t first : s.segments)
      if (size_t(first) + 1 >= s.positions.size())
        fail(where + ".segments", "segment from vertex " + std::to_string(first) + " has no next vertex (" +
                                      std::to_string(s.positions.size()) + " vertices)");
    if (!(s.width >= 0) || !std::isfinite(s.width)) fail(where + ".width", "must be positive, or 0 for --line-width");
    in_range(s.width, where + ".width");
  }

  // The corners of the mesh's bounding box, placed by the instance, computed in double: the
  // placed vertices then lie within range too (an affine map keeps them inside the placed box).
  struct Box {
    vec3 lower, upper;
    bool empty = true;
  };
  static Box mesh_box(const MeshDesc& m) {
    Box box;
    for (vec3 p : m.positions) {
      box.lower = box.empty ? p : min(box.lower, p);
      box.upper = box.empty ? p : max(box.upper, p);
      box.empty = false;
    }
    return box;
  }
  void placed_in_range(const InstanceDesc& instance, const Box& box, const std::string& where) const {
    if (box.empty) return;
    vec3 lower = box.lower, upper = box.upper;
    for (int corner = 0; corner < 8; ++corner) {
      vec3 p = {corner & 1 ? upper.x : lower.x, corner & 2 ? upper.y : lower.y, corner & 4 ? upper.z : lower.z};
      for (int r = 0; r < 3; ++r) {
        const float* row = instance.transform.m[r];
        in_range(double(row[0]) * p.x + double(row[1]) * p.y + double(row[2]) * p.z + double(row[3]),
                 where + ".placed_vertices");
      }
    }
  }

  // Motion over the shutter: none, or between 2 and max_motion_steps time steps.
  void motion_steps(size_t steps, const std::string& where) const {
    if (steps == 1 || steps > size_t(max_motion_steps))
      fail(where, "needs 2 to " + std::to_string(max_motion_steps) + " time steps, not " + std::to_string(steps));
  }

  void run() const {
    for (size_t i = 0; i < scene.images.size(); ++i) image(scene.images[i], at("images", i));
    for (size_t i = 0; i < scene.textures.size(); ++i)
      index(scene.textures[i].image, scene.images.size(), false, at("textures", i) + ".image", "image");
    for (size_t i = 0; i < scene.materials.size(); ++i) material(scene.materials[i], at("materials", i));
    for (size_t i = 0; i < scene.meshes.size(); ++i) mesh(scene.meshes[i], at("meshes", i));
    std::vector<Box> mesh_boxes;
    mesh_boxes.reserve(scene.meshes.size());
    for (const MeshDesc& m : scene.meshes) mesh_boxes.push_back(mesh_box(m));
    for (size_t i = 0; i < scene.instances.size(); ++i) {
      std::string where = at("instances", i);
      index(scene.instances[i].mesh, scene.meshes.size(), false, where + ".mesh", "mesh");
      if (!is_finite(scene.instances[i].transform)) fail(where + ".transform", "non-finite value");
      mat4 inverse;
      if (!inverse_affine(scene.instances[i].transform, inverse)) fail(where + ".transform", "singular transform");
      if (!inverse_survives_float(scene.instances[i].transform))
        fail(where + ".transform", "too close to singular to invert in single precision, as ray tracing must");
      placed_in_range(scene.instances[i], mesh_boxes[scene.instances[i].mesh], where);
      motion_steps(scene.instances[i].motion.size(), where + ".motion");
      for (const mat4& step : scene.instances[i].motion)
        if (!is_finite(step) || !inverse_survives_float(step)) fail(where + ".motion", "a step's transform is not invertible");
    }
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
      const MeshDesc& m = scene.meshes[i];
      motion_steps(m.motion_positions.size(), at("meshes", i) + ".motion_positions");
      for (const std::vector<vec3>& step : m.motion_positions)
        if (step.size() != m.positions.size()) fail(at("meshes", i) + ".motion_positions", "a step's vertex count differs");
    }
    for (size_t i = 0; i < scene.cameras.size(); ++i) motion_steps(scene.cameras[i].motion.size(), at("cameras", i) + ".motion");
    for (size_t i = 0; i < scene.shapes.size(); ++i) shape(scene.shapes[i], at("shapes", i));
    for (size_t i = 0; i < scene.strokes.size(); ++i) stroke(scene.strokes[i], at("strokes", i));
    for (size_t i = 0; i < scene.cameras.size(); ++i) camera(scene.cameras[i], at("cameras", i));
    for (size_t i = 0; i < scene.lights.size(); ++i) light(scene.lights[i], at("lights", i));
    non_negative(scene.environment.color, "environment.color");
    finite(scene.environment.map_scale, "environment.map_scale");
    if (scene.instances.empty() && scene.shapes.empty() && scene.strokes.empty())
      fail("scene", "nothing to render (no meshes placed, no shapes, no lines or points)");
  }
};

}  // namespace

void validate_scene(const SceneDesc& scene) { Checker{scene}.run(); }

}  // namespace radiant

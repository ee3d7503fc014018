#include "lights/light_table.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "lights/emission_estimate.h"
#include "lights/light_bounds.h"
#include "scene/scene_bounds.h"

namespace radiant {

namespace {

void scene_bounding_sphere(const SceneDesc& scene, vec3& center, float& radius) {
  vec3 lower, upper;
  if (!scene_bounds(scene, lower, upper)) {
    center = {0, 0, 0};
    radius = 1;
    return;
  }
  center = (lower + upper) * 0.5f;
  radius = std::max(length(upper - lower) * 0.5f, 1e-3f);
}

// `estimates`: null when the render reads no emission texture (each triangle then emits its factor).
void add_emissive_triangles(const SceneDesc& scene, LightTable& table, const EmissionEstimates* estimates) {
  table.instance_light_base.assign(scene.instances.size(), -1);
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const InstanceDesc& instance = scene.instances[i];
    const MeshDesc& mesh = scene.meshes[instance.mesh];
    if (mesh.material < 0 || is_black(scene.materials[mesh.material].emission)) continue;
    table.instance_light_base[i] = int(table.area_lights.size());
    mat4 inverse;
    inverse_affine(instance.transform, inverse);
    const MaterialDesc& material = scene.materials[mesh.material];
    // The emission texture's coordinates, as area_light_emission reads them (zero without any).
    const std::vector<vec2>& uvs = material.emission_texture.texcoord == 1 ? mesh.texcoords1 : mesh.texcoords0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      AreaLight light;
      light.p0 = transform_point(instance.transform, mesh.positions[mesh.indices[3 * t]]);
      light.p1 = transform_point(instance.transform, mesh.positions[mesh.indices[3 * t + 1]]);
      light.p2 = transform_point(instance.transform, mesh.positions[mesh.indices[3 * t + 2]]);
      vec3 object_normal = cross(mesh.positions[mesh.indices[3 * t + 1]] - mesh.positions[mesh.indices[3 * t]],
                                 mesh.positions[mesh.indices[3 * t + 2]] - mesh.positions[mesh.indices[3 * t]]);
      // World-space winding decides the front side, as in make_surface_hit.
      light.normal = normalize(transform_normal(inverse, object_normal)) *
                     (determinant3(instance.transform) < 0 ? -1.0f : 1.0f);
      light.area = 0.5f * length(cross(light.p1 - light.p0, light.p2 - light.p0));
      light.material = mesh.material;
      vec2 uv[3] = {};
      if (!uvs.empty())
        for (int k = 0; k < 3; ++k) uv[k] = uvs[mesh.indices[3 * t + k]];
      light.radiance = estimates ? estimates->triangle_luminance(material, uv) : luminance(material.emission);
      light.two_sided = material.double_sided;
      light.instance = int(i);
      light.primitive = uint32_t(t);
      table.area_lights.push_back(light);
    }
  }
}

void add_emissive_spheres(const SceneDesc& scene, LightTable& table) {
  table.shape_light.assign(scene.shapes.size(), -1);
  for (size_t s = 0; s < scene.shapes.size(); ++s) {
    const ShapeDesc& shape = scene.shapes[s];
    if (shape.kind != ShapeKind::sphere || shape.material < 0 || is_black(scene.materials[shape.material].emission))
      continue;
    AreaLight light;
    light.shape = AreaLightShape::sphere;
    light.center = shape.center;
    light.radius = shape.radius;
    light.area = 4 * pi * shape.radius * shape.radius;
    light.material = shape.material;
    // A sphere's light samples read no texture (area_light_emission): neither does its weight.
    light.radiance = luminance(scene.materials[shape.material].emission);
    light.two_sided = scene.materials[shape.material].double_sided;  // emits inward too
    light.shape_index = int(s);
    table.shape_light[s] = int(table.area_lights.size());
    table.area_lights.push_back(light);
  }
}

// The area lights add_emissive_triangles and add_emissive_spheres will make, and their weights.
uint64_t area_light_bytes(const SceneDesc& scene) {
  uint64_t lights = scene.shapes.size();
  for (const InstanceDesc& instance : scene.instances) {
    const MeshDesc& mesh = scene.meshes[instance.mesh];
    if (mesh.material >= 0 && !is_black(scene.materials[mesh.material].emission)) lights += mesh.triangle_count();
  }
  return saturating_multiply(lights, 2 * sizeof(AreaLight) + 3 * sizeof(float));
}

// Weights as floats with the same ratios: scaled down together when their sum nears float's
// range (make_distribution keeps the total as a float).
std::vector<float> float_weights(const std::vector<double>& weights) {
  double total = 0;
  for (double w : weights) total += w;
  double scale = total > 1e30 ? 1e30 / total : 1;
  std::vector<float> scaled;
  for (double w : weights) scaled.push_back(float(w * scale));
  return scaled;
}

// The bounds of a light with a position (intensity not yet normalised), or false for a light at
// infinity. Intensities are W/sr along the normal: I for point and spot lights, L x area for a
// triangle, L x pi r^2 (its projected area) for a sphere.
bool light_bounds_of(const SceneDesc& scene, const LightTable& table, size_t slot, LightBounds& bounds) {
  if (slot < table.delta_lights.size()) {
    const LightDesc& l = scene.lights[size_t(table.delta_lights[slot])];
    if (l.kind == LightKind::directional) return false;
    float intensity = luminance(l.intensity);
    if (l.kind == LightKind::point) bounds = point_light_bounds(l.position, {0, 0, 1}, -1, 0, intensity);
    else if (l.use_cone)  // glTF: full intensity inside the inner cone, falling to 0 at the outer one
      bounds = point_light_bounds(l.position, l.direction, std::cos(l.inner_cone),
                                  std::cos(std::max(0.0f, l.outer_cone - l.inner_cone)), intensity);
    else  // cos^exponent in front of the light, nothing behind it
      bounds = point_light_bounds(l.position, l.direction, 1, 0, intensity);
    return true;
  }
  const AreaLight& l = table.area_lights[slot - table.delta_lights.size()];
  float radiance = l.radiance;
  if (l.shape == AreaLightShape::sphere) {
    vec3 r = {l.radius, l.radius, l.radius};
    bounds = point_light_bounds(l.center, {0, 0, 1}, -1, 0, radiance * pi * l.radius * l.radius);
    bounds.lower = l.center - r, bounds.upper = l.center + r;
  } else {
    bounds = point_light_bounds(l.p0, l.normal, 1, 0, radiance * l.area);
    bounds.lower = min(l.p0, min(l.p1, l.p2)), bounds.upper = max(l.p0, max(l.p1, l.p2));
  }
  bounds.two_sided = l.two_sided;
  return true;
}

// Sets the table's sampler and, for the BVH, builds the tree over the lights with a position and
// the power selection among the lights at infinity and the tree. `power` holds each slot's
// selection weight.
void choose_light_sampler(const SceneDesc& scene, LightTable& table, const std::vector<double>& power,
                          LightSampler requested, MemoryBudget* budget) {
  size_t slots = table.delta_lights.size() + table.area_lights.size(), directional = 0;
  for (int index : table.delta_lights) directional += scene.lights[size_t(index)].kind == LightKind::directional;
  size_t bounded = slots - directional;
  bool use_bvh = requested == LightSampler::bvh ||
                 (requested == LightSampler::automatic && bounded >= light_bvh_min_lights);
  table.sampler = use_bvh ? LightSampler::bvh : LightSampler::power;
  if (!use_bvh) return;
  table.bvh_memory = MemoryCharge(budget, light_bvh_bytes(bounded, slots), scene.source_path + ": the light BVH");
  std::vector<BoundedLight> lights;
  lights.reserve(bounded);
  double total_intensity = 0, tree_power = 0;
  for (size_t slot = 0; slot < slots; ++slot) {
    BoundedLight light{int(slot), {}};
    if (!light_bounds_of(scene, table, slot, light.bounds)) continue;
    total_intensity += light.bounds.intensity;
    tree_power += power[slot];
    lights.push_back(light);
  }
  // Intensities as fractions of the whole: sums up the tree cannot overflow a float.
  for (BoundedLight& l : lights) l.bounds.intensity = float(l.bounds.intensity / std::max(total_intensity, 1e-300));
  table.bvh = build_light_bvh(std::move(lights), slots);

  std::vector<double> weights;
  for (size_t slot = 0; slot < table.delta_lights.size(); ++slot)
    if (scene.lights[size_t(table.delta_lights[slot])].kind == LightKind::directional) {
      table.infinite_lights.push_back(int(slot));
      weights.push_back(power[slot]);
    }
  if (table.has_environment()) {
    table.infinite_lights.push_back(int(table.environment_slot()));
    weights.push_back(power[table.environment_slot()]);
  }
  weights.push_back(table.bvh.empty() ? 0 : tree_power);
  table.infinite_selection = make_distribution(float_weights(weights));
}

}  // namespace

LightTable make_light_table(const SceneDesc& scene, const EnvironmentSpec& environment, bool use_area_lights,
                            MemoryBudget* budget, LightSampler sampler, bool emission_textures) {
  LightTable table;
  if (use_area_lights)
    table.area_light_memory = MemoryCharge(budget, area_light_bytes(scene), scene.source_path + ": the area lights");
  scene_bounding_sphere(scene, table.scene_center, table.scene_radius);
  for (size_t i = 0; i < scene.lights.size(); ++i)
    if (scene.lights[i].kind != LightKind::ambient) table.delta_lights.push_back(int(i));
  if (use_area_lights) {
    std::optional<EmissionEstimates> estimates;  // only while the triangles are made
    if (emission_textures) estimates.emplace(scene, budget);
    add_emissive_triangles(scene, table, estimates ? &*estimates : nullptr);
    add_emissive_spheres(scene, table);
  }
  table.environment_color = environment.color;
  if (environment.studio) table.environment_map = make_studio_environment(budget);
  else if (!environment.map_path.empty()) table.environment_map = load_environment_map(environment.map_path, budget);
  table.environment_scale = environment.map_scale;
  table.environment_frame = environment.frame;

  // Selection weights: each light's emitted power (up to a common factor), in double: a light of
  // 1e38 has a power beyond float's range, which make_distribution would read as zero.
  double disk = pi * double(table.scene_radius) * table.scene_radius;
  std::vector<double> weights;
  for (int index : table.delta_lights) {
    const LightDesc& l = scene.lights[index];
    double power = luminance(l.intensity);
    if (l.kind == LightKind::directional) weights.push_back(power * disk);
    else weights.push_back(power * 4 * pi / std::max(l.kc + l.kl + l.kq, 1e-6f));
  }
  for (const AreaLight& l : table.area_lights)
    weights.push_back(double(l.radiance) * l.area * pi * (l.two_sided ? 2 : 1));
  if (table.has_environment()) {
    double average = luminance(table.environment_color);
    if (table.environment_map.width > 0)
      average += double(table.environment_map.distribution.marginal.total) * table.environment_scale * pi / 2;
    weights.push_back(std::max(average, 1e-6) * disk * 4);
  }
  table.selection = make_distribution(float_weights(weights));
  // Whitted (no area lights) lights every point with every light: it chooses none.
  choose_light_sampler(scene, table, weights, use_area_lights ? sampler : LightSampler::power, budget);
  return table;
}

}  // namespace radiant

#include "lights/light_table.h"

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "image/image_io.h"
#include "lights/emission_estimate.h"
#include "lights/light_bounds.h"
#include "memory/input_file.h"
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

// A texel must be radiance: finite and not negative. Throws naming the file, pixel and channel.
void check_environment_texel(const std::string& path, const ImageHeader& spec, int x, int y, color3 c) {
  for (int k = 0; k < 3; ++k) {
    if (std::isfinite(c[k]) && c[k] >= 0) continue;
    std::string channel = spec.channels >= 3 ? spec.channel_names[size_t(k)] : spec.channel_names[0];
    std::ostringstream value;
    value << c[k];
    throw std::runtime_error(path + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): " + channel +
                             " is " + value.str() + ": environment radiance must " +
                             (std::isfinite(c[k]) ? "not be negative" : "be finite"));
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

EnvironmentMap load_environment_map(const std::string& path, MemoryBudget* budget) {
  std::unique_ptr<ImageSource> input = open_environment_map(path, budget);
  const ImageHeader& spec = input->header();
  // The float pixels read (OpenImageIO's copy is the source's charge), then texels, weights and
  // the sampling tables.
  uint64_t texels = uint64_t(spec.width) * uint64_t(spec.height);
  uint64_t per_texel = 4 * uint64_t(spec.channels) + sizeof(color3) + 5 * sizeof(float);
  MemoryCharge memory(budget, saturating_multiply(texels, per_texel),
                      path + ": a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                          " environment map");
  std::vector<float> pixels(size_t(spec.width) * spec.height * spec.channels);
  if (!input->read(spec.channels, PixelType::float32, pixels.data()))
    throw std::runtime_error(path + ": cannot read environment map: " + input->error());
  EnvironmentMap map;
  map.memory = std::move(memory);
  map.width = spec.width;
  map.height = spec.height;
  map.texels.resize(size_t(map.width) * map.height);
  std::vector<float> weights(map.texels.size());
  for (int y = 0; y < map.height; ++y) {
    float sin_theta = std::sin(pi * (float(y) + 0.5f) / float(map.height));
    for (int x = 0; x < map.width; ++x) {
      size_t i = size_t(y) * map.width + x;
      const float* p = &pixels[i * spec.channels];
      color3 c = spec.channels >= 3 ? color3{p[0], p[1], p[2]} : color3{p[0], p[0], p[0]};
      check_environment_texel(path, spec, x, y, c);
      map.texels[i] = c;
      // Divided by the texel count, so that the weights' sum (the distribution's total, a float)
      // is the map's mean and cannot overflow however bright its texels are.
      weights[i] = float(double(luminance(map.texels[i])) * sin_theta / double(map.texels.size()));
    }
  }
  map.distribution = make_distribution_2d(weights, map.width, map.height);
  return map;
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

std::unique_ptr<ImageSource> open_environment_map(const std::string& path, MemoryBudget* budget) {
  uint64_t file_size = 0;
  std::string problem = input_file_problem(path, file_size);
  if (!problem.empty()) throw std::runtime_error(path + ": cannot read environment map: " + problem);
  std::string error;
  auto input = open_image_file(path, error, budget);
  if (!input) throw std::runtime_error(path + ": cannot read environment map: " + error);
  const ImageHeader& spec = input->header();
  if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0 ||
      size_t(spec.width) * spec.height > (size_t(1) << 28))
    throw std::runtime_error(path + ": environment map has an unusable size");
  return input;
}

LightTable make_light_table(const SceneDesc& scene, color3 environment_color, const std::string& environment_map_path,
                            bool use_area_lights, MemoryBudget* budget, LightSampler sampler,
                            bool emission_textures) {
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
  table.environment_color = environment_color;
  if (!environment_map_path.empty()) table.environment_map = load_environment_map(environment_map_path, budget);

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
      average += double(table.environment_map.distribution.marginal.total) * pi / 2;
    weights.push_back(std::max(average, 1e-6) * disk * 4);
  }
  table.selection = make_distribution(float_weights(weights));
  // Whitted (no area lights) lights every point with every light: it chooses none.
  choose_light_sampler(scene, table, weights, use_area_lights ? sampler : LightSampler::power, budget);
  return table;
}

color3 eval_environment(const LightTable& lights, vec3 d) {
  color3 radiance = lights.environment_color;
  const EnvironmentMap& map = lights.environment_map;
  if (map.width > 0) {
    // Equirectangular, +y up; u = 0.5 looks down -z.
    float u = 0.5f + std::atan2(d.x, -d.z) / (2 * pi);
    float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / pi;
    int x = std::clamp(int(u * map.width), 0, map.width - 1);
    int y = std::clamp(int(v * map.height), 0, map.height - 1);
    radiance += map.texels[size_t(y) * map.width + x] * lights.environment_scale;
  }
  return radiance;
}

}  // namespace radiant

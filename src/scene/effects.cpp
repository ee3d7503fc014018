#include "scene/effects.h"

#include <sstream>
#include <stdexcept>

#include "scene/scene_motion.h"
#include "scene/volume_absorption.h"

namespace radiant {

const std::vector<EffectInfo>& effect_catalog() {
  static const std::vector<EffectInfo> catalog = {
      {effect_direct_delta, "direct"},       {effect_ambient, "ambient"},
      {effect_shadows, "shadows"},           {effect_transparent_shadows, "transparent-shadows"},
      {effect_reflection, "reflection"},     {effect_refraction, "refraction"},
      {effect_emission, "emission"},         {effect_environment, "environment"},
      {effect_textures, "textures"},         {effect_normal_maps, "normal-maps"},
      {effect_alpha, "alpha"},               {effect_indirect, "indirect"},
      {effect_absorption, "absorption"},     {effect_single_sided, "single-sided"},
      {effect_motion_blur, "motion-blur"},
  };
  return catalog;
}

namespace {

bool is_transmissive(const MaterialDesc& m) {
  return max_component(m.kt) > 0 || (m.model == MaterialModel::metallic_roughness && m.transmission > 0);
}
bool is_reflective(const MaterialDesc& m) {
  if (m.model == MaterialModel::phong) return max_component(m.kr) > 0;
  return m.metallic > 0 || m.roughness < 1 || (m.clearcoat > 0 && m.clearcoat_roughness < 1);
}
bool has_texture(const MaterialDesc& m) {
  return m.base_color_texture.valid() || m.metallic_roughness_texture.valid() || m.emission_texture.valid() ||
         m.transmission_texture.valid() || m.specular_texture.valid() || m.alpha_texture.valid() ||
         m.specular_strength_texture.valid() || m.specular_color_texture.valid() || m.clearcoat_texture.valid() ||
         m.clearcoat_roughness_texture.valid() || m.sheen_color_texture.valid() || m.sheen_roughness_texture.valid() ||
         m.iridescence_texture.valid() || m.iridescence_thickness_texture.valid() || m.anisotropy_texture.valid() ||
         m.diffuse_transmission_texture.valid() || m.diffuse_transmission_color_texture.valid();
}

// Materials actually used by some placed mesh, and by the shapes when `with_shapes`.
std::vector<bool> used_materials(const SceneDesc& scene, bool with_shapes) {
  std::vector<bool> used(scene.materials.size(), false);
  auto mark = [&](int m) {
    if (m >= 0 && m < int(used.size())) used[m] = true;
  };
  for (const InstanceDesc& i : scene.instances)
    if (i.mesh >= 0 && i.mesh < int(scene.meshes.size())) mark(scene.meshes[i.mesh].material);
  if (with_shapes) {
    for (const ShapeDesc& s : scene.shapes) mark(s.material);
    for (const StrokeDesc& s : scene.strokes) mark(s.material);
  }
  return used;
}

}  // namespace

EffectSet analyze_effects(const SceneDesc& scene) {
  EffectSet set;
  int delta_lights = 0, ambient_lights = 0;
  for (const LightDesc& l : scene.lights) {
    if (l.kind == LightKind::ambient) ++ambient_lights;
    else if (!is_black(l.intensity)) ++delta_lights;
  }
  std::vector<bool> used = used_materials(scene, true), used_by_meshes = used_materials(scene, false);
  int transmissive = 0, reflective = 0, emissive = 0, textured = 0, normal_mapped = 0, alpha = 0, absorbing = 0;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (!used[i]) continue;
    const MaterialDesc& m = scene.materials[i];
    transmissive += is_transmissive(m);
    reflective += is_reflective(m);
    emissive += !is_black(m.emission);
    textured += has_texture(m);
    normal_mapped += m.normal_texture.valid() || m.bump_texture.valid() || m.clearcoat_normal_texture.valid();
    alpha += m.alpha_mode != AlphaMode::opaque;
    absorbing += !is_black(volume_absorption(m));
  }
  int single_sided = 0;  // only triangles have a back face: shapes are seen from every side
  for (size_t i = 0; i < scene.materials.size(); ++i) single_sided += used_by_meshes[i] && !scene.materials[i].double_sided;
  for (const InstanceDesc& i : scene.instances)
    if (!scene.meshes[i.mesh].colors.empty()) {
      ++textured;  // vertex colors are read per hit like a texture
      break;
    }
  bool environment = !is_black(scene.environment.color) || !scene.environment.map_path.empty();
  auto add = [&](Effect e, const std::string& reason) {
    set.mask |= e;
    set.reasons.push_back(reason);
  };
  auto count = [](int n, const char* what) { return std::to_string(n) + " " + what; };
  // Reasons are added in catalog order.
  if (delta_lights) add(effect_direct_delta, count(delta_lights, "point, spot or directional light(s)"));
  if (ambient_lights) add(effect_ambient, count(ambient_lights, "ambient light(s)"));
  if (delta_lights || emissive || environment)
    add(effect_shadows, "light sources can be blocked by geometry");
  if (transmissive && (delta_lights || emissive || environment))
    add(effect_transparent_shadows, count(transmissive, "transmissive material(s) let light through"));
  if (reflective) add(effect_reflection, count(reflective, "reflective material(s)"));
  if (transmissive) add(effect_refraction, count(transmissive, "transmissive material(s)"));
  if (emissive) add(effect_emission, count(emissive, "emissive material(s)"));
  if (environment)
    add(effect_environment, scene.environment.map_path.empty() ? "a uniform background color" : "an environment map");
  if (textured) add(effect_textures, count(textured, "textured material(s) or vertex-colored mesh(es)"));
  if (normal_mapped) add(effect_normal_maps, count(normal_mapped, "normal- or bump-mapped material(s)"));
  if (alpha) add(effect_alpha, count(alpha, "material(s) with alpha mask or blend"));
  if (delta_lights || emissive || environment)
    add(effect_indirect, "light bounces between surfaces (path tracer)");
  if (absorbing) add(effect_absorption, count(absorbing, "material(s) with an absorbing volume (KHR_materials_volume)"));
  if (single_sided)
    add(effect_single_sided, count(single_sided, "single-sided material(s): camera rays pass through their back faces"));
  if (MotionCounts motion = count_motion(scene); motion.any()) add(effect_motion_blur, describe_motion(motion));
  return set;
}

uint32_t apply_effects_override(uint32_t mask, const std::string& list) {
  std::stringstream in(list);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (item.empty()) continue;
    if (item == "all") {
      mask = effect_all;
      continue;
    }
    if (item == "none") {
      mask = 0;
      continue;
    }
    bool remove = item[0] == '-';
    std::string name = (item[0] == '-' || item[0] == '+') ? item.substr(1) : item;
    bool found = false;
    for (const EffectInfo& info : effect_catalog()) {
      if (name != info.name) continue;
      found = true;
      mask = remove ? (mask & ~uint32_t(info.effect)) : (mask | info.effect);
    }
    if (!found) throw std::invalid_argument("unknown effect '" + name + "' (known: " + effect_names(effect_all) + ")");
  }
  return mask;
}

std::string effect_names(uint32_t mask) {
  std::string out;
  for (const EffectInfo& info : effect_catalog()) {
    if (!(mask & info.effect)) continue;
    if (!out.empty()) out += ",";
    out += info.name;
  }
  return out;
}

}  // namespace radiant

// A material resolved at one surface point (textures applied), as both integrators read it:
// the Phong/Whitted model and the physically based BSDF of the path tracer (docs/materials.md).
#pragma once

#include "math/vec.h"
#include "scene/scene_desc.h"

namespace radiant {

struct TexturePyramids;

// How a render's lookups filter: the mode of --texture-filter and, for trilinear, the pyramids.
struct TextureLookup {
  TextureFilterMode mode = TextureFilterMode::bilinear;
  const TexturePyramids* pyramids = nullptr;
};

// Per-hit geometric attributes a material needs for its texture lookups.
struct SurfaceAttributes {
  vec2 uv[2] = {{0, 0}, {0, 0}};
  vec4 vertex_color = {1, 1, 1, 1};
  // The change of each uv set across one pixel in x and in y (zero: no footprint, full resolution).
  vec2 duv_dx[2] = {{0, 0}, {0, 0}}, duv_dy[2] = {{0, 0}, {0, 0}};
  // The render's filtering; null: each texture's own filter at full resolution.
  const TextureLookup* lookup = nullptr;
};

// A material's texture slot and whether resolve_material decodes it as sRGB colour.
struct TextureSlot {
  const TextureRef* ref;
  bool srgb;
};
// Every texture slot of `material` (valid or not), with the decoding resolve_material reads it with.
std::vector<TextureSlot> texture_slots(const MaterialDesc& material);

// A material's parameters at one point: MaterialDesc with every texture applied.
struct SurfaceMaterial {
  MaterialModel model = MaterialModel::phong;
  // Phong (also filled for metallic-roughness through the documented mapping; see
  // `phong_from_metallic_roughness`), used by the Whitted integrator for every material.
  color3 ka, kd, ks, kr, kt;
  float shininess = 1;
  float ior = 1.5f;
  float dispersion = 0;  // KHR_materials_dispersion: 20 / Abbe number (metallic-roughness transmission)
  // Metallic-roughness, valid when model == metallic_roughness.
  color3 base_color = {1, 1, 1};
  float metallic = 0, roughness = 1, transmission = 0;
  float specular = 1;                 // KHR_materials_specular: strength of the dielectric's Fresnel layer
  color3 specular_color = {1, 1, 1};  // and the tint of its F0
  float clearcoat = 0, clearcoat_roughness = 0;  // KHR_materials_clearcoat
  color3 sheen_color = {0, 0, 0};                 // KHR_materials_sheen
  float sheen_roughness = 0;
  float diffuse_transmission = 0;                    // KHR_materials_diffuse_transmission
  color3 diffuse_transmission_color = {1, 1, 1};
  float iridescence = 0, iridescence_ior = 1.3f, iridescence_thickness = 400;  // KHR_materials_iridescence (nm)
  float anisotropy = 0;                         // KHR_materials_anisotropy: strength
  vec2 anisotropy_direction = {1, 0};           // in the tangent frame (x along the tangent)
  // Shared.
  color3 emission;
  float opacity = 1;  // alpha after the alpha mode (1 for opaque; 0 or 1 for mask)
  bool unlit = false;
  vec3 normal_map_sample = {0, 0, 1};  // tangent-space normal (scaled), when the material has one
  bool has_normal_map = false;
  vec3 clearcoat_normal_sample = {0, 0, 1};  // the coat's (KHR_materials_clearcoat), in the same frame
  bool has_clearcoat_normal_map = false;
  // Height map: the displacement's change per unit of u and of v (world units), when it has one.
  vec2 height_slope = {0, 0};
  bool has_bump_map = false;
};

// The image behind `ref`, or nullptr when any link is missing or its texels are inconsistent.
const ImageDesc* texture_image(const SceneDesc& scene, const TextureRef& ref);
// KHR_texture_transform: uv' = T * R * S * uv (the extension's matrix order).
vec2 transform_uv(const TextureRef& ref, vec2 uv);
// Maps a texel index that may lie outside [0, size) onto the image by the wrap mode.
int wrap_index(int i, int size, TextureWrap wrap);

// Texel fetch with wrap, filter and KHR_texture_transform; `srgb` decodes color textures.
// Returns RGBA (missing channels: RGB repeat the first, A = 1).
vec4 sample_texture(const SceneDesc& scene, const TextureRef& ref, const SurfaceAttributes& attributes,
                    bool srgb);

// Resolves `material` at a point.
SurfaceMaterial resolve_material(const SceneDesc& scene, const MaterialDesc& material,
                                 const SurfaceAttributes& attributes);

// The Whitted mapping of metallic-roughness parameters onto kd/ks/shininess/kr/kt (fills the
// Phong fields of `m` from its metallic-roughness fields).
void phong_from_metallic_roughness(SurfaceMaterial& m);

// Perturbs shading normal `n` by a tangent-space normal-map sample, given the tangent (xyz, w sign).
vec3 apply_normal_map(vec3 n, vec4 tangent, vec3 tangent_space_normal);

// The slope (dh/du, dh/dv) of texture `ref`'s first channel at the hit, by central differences
// half a texel apart in u and in v.
vec2 sample_texture_slope(const SceneDesc& scene, const TextureRef& ref, const SurfaceAttributes& attributes);

// Shading normal `n` of a surface with position derivatives dpdu, dpdv (world units per unit of
// u and v) displaced along n by a height whose slope is `height_slope` (pbrt's bump mapping,
// without the term of the normal's own change).
vec3 apply_bump_map(vec3 n, vec3 dpdu, vec3 dpdv, vec2 height_slope);

// A direction chosen by the path tracer's BSDF (materials/bsdf.h).
struct BsdfSample {
  vec3 wi;
  color3 weight;    // f * |cos(wi)| / pdf (for delta lobes: the lobe's reflectance / selection prob)
  float pdf = 0;    // solid-angle pdf of choosing wi (selection probability for delta lobes)
  bool delta = false;
  bool transmitted = false;
};

}  // namespace radiant

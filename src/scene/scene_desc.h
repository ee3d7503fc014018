// The plain scene description every loader produces and the core builds from.
// Plain structs linked by integer indices (-1 = none); no rendering types, no Embree.
// Units are the internal ones of docs/units.md: linear RGB, radiometric, metres-agnostic.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "math/transform.h"
#include "math/vec.h"
#include "scene/motion_steps.h"

namespace radiant {

// ---------------------------------------------------------------- cameras

// Equirectangular: longitude across the image (the view direction at its centre), latitude
// down it. Fisheye: equidistant, the field of view across the circle inscribed in the image.
enum class Projection { perspective, orthographic, equirectangular, fisheye };

struct CameraDesc {
  std::string name;
  Projection projection = Projection::perspective;
  vec3 position = {0, 0, 0};
  vec3 forward = {0, 0, -1};  // unit view direction
  vec3 up = {0, 1, 0};        // unit, orthogonal to forward
  float vertical_fov_degrees = 45;  // perspective
  float ortho_height = 2;           // orthographic: full height of the view volume
  float fisheye_fov_degrees = 180;  // fisheye
  // Thin lens (perspective and orthographic, as pbrt's lensradius and focaldistance): 0 = pinhole.
  float lens_radius = 0;
  float focus_distance = 0;  // along the view direction; 0 = unset
  int aperture_blades = 0;   // 0 = a round aperture, 3 or more a regular polygon
  float aspect = 0;                 // width / height; 0 = take it from the image size
  int width = 0, height = 0;        // image size the file asks for; 0 = unset
  // Empty, or the pose at each time step of the shutter (scene/motion_steps.h) when the camera
  // moves while it is open; position, forward and up above are its pose at the rendered time.
  std::vector<CameraPose> motion;
};

// ---------------------------------------------------------------- images and textures

// Texels as loaded: 8-bit (LDR files) or float (HDR/EXR). Color space is chosen by the user of
// the texture (base color and emission decode sRGB, the others are linear data).
struct ImageDesc {
  std::string name;  // file path or glTF image name, for messages
  int width = 0, height = 0, channels = 0;
  std::vector<uint8_t> texels8;
  std::vector<float> texels_float;
};

enum class TextureWrap { repeat, clamp_to_edge, mirrored_repeat };
enum class TextureFilter { linear, nearest };
// How every lookup of a render filters (--texture-filter): the nearest texel or the texture's own
// filter at full resolution, or mip-mapped by the pixel's footprint (docs/materials.md).
enum class TextureFilterMode { point, bilinear, trilinear };

struct TextureDesc {
  int image = -1;
  TextureWrap wrap_s = TextureWrap::repeat, wrap_t = TextureWrap::repeat;
  TextureFilter filter = TextureFilter::linear;
};

// A material slot's texture: which texture, which UV set, and KHR_texture_transform.
struct TextureRef {
  int texture = -1;
  int texcoord = 0;
  vec2 offset = {0, 0};
  vec2 scale = {1, 1};
  float rotation = 0;  // radians
  bool valid() const { return texture >= 0; }
};

// ---------------------------------------------------------------- materials

// Which reflection model the author wrote; both integrators evaluate both (docs/materials.md).
enum class MaterialModel { phong, metallic_roughness };
enum class AlphaMode { opaque, mask, blend };

struct MaterialDesc {
  std::string name;
  MaterialModel model = MaterialModel::phong;

  // Phong/Whitted parameters (the `.scene` model, and OBJ/MTL).
  color3 ka = {0, 0, 0};  // ambient reflectance
  color3 kd = {0, 0, 0};  // diffuse reflectance (albedo)
  color3 ks = {0, 0, 0};  // specular highlight weight
  float shininess = 1;
  color3 kr = {0, 0, 0};  // mirror reflection weight
  color3 kt = {0, 0, 0};  // transmission weight
  float ior = 1.5f;

  // glTF metallic-roughness parameters.
  color3 base_color = {1, 1, 1};
  float alpha = 1;
  float metallic = 1;
  float roughness = 1;
  float transmission = 0;  // KHR_materials_transmission
  TextureRef base_color_texture;  // sRGB; alpha in channel 4
  TextureRef metallic_roughness_texture;  // linear: G roughness, B metallic
  TextureRef normal_texture;
  float normal_scale = 1;
  // Height map (OBJ bump/map_bump): the surface seen as displaced along its normal by
  // bump_scale x the texel's first channel (linear), in world units; the shading normal follows.
  TextureRef bump_texture;
  float bump_scale = 1;
  TextureRef transmission_texture;  // linear, R channel
  // KHR_materials_specular: a dielectric's Fresnel layer is specular × F, with F0 tinted by
  // specular_color; specular 0 leaves an exactly Lambertian base.
  float specular = 1;
  color3 specular_color = {1, 1, 1};
  TextureRef specular_strength_texture;  // linear, A channel (the extension's specularTexture)
  TextureRef specular_color_texture;     // sRGB, RGB
  // KHR_materials_clearcoat: a clear GGX layer over the whole material.
  float clearcoat = 0, clearcoat_roughness = 0;
  TextureRef clearcoat_texture;            // linear, R channel
  TextureRef clearcoat_roughness_texture;  // linear, G channel
  // The coat's own normal map, in the base normal map's tangent frame; without it the coat
  // keeps the vertex normal even where the base is normal-mapped (the extension's rule).
  TextureRef clearcoat_normal_texture;
  float clearcoat_normal_scale = 1;
  // KHR_materials_sheen: a Charlie sheen (cloth, velvet) between the coat and the base.
  color3 sheen_color = {0, 0, 0};
  float sheen_roughness = 0;
  TextureRef sheen_color_texture;      // sRGB, RGB
  TextureRef sheen_roughness_texture;  // linear, A channel
  // KHR_materials_diffuse_transmission: this share of the diffuse base leaves on the other side
  // of the surface (Lambertian, tinted by diffuse_transmission_color), as in leaves and paper.
  float diffuse_transmission = 0;
  TextureRef diffuse_transmission_texture;  // linear, A channel
  color3 diffuse_transmission_color = {1, 1, 1};
  TextureRef diffuse_transmission_color_texture;  // sRGB, RGB
  // KHR_materials_anisotropy: GGX rougher along a direction of the tangent frame (brushed metal).
  float anisotropy_strength = 0;
  float anisotropy_rotation = 0;  // radians, counter-clockwise from the tangent
  TextureRef anisotropy_texture;  // linear: RG the direction in [-1, 1]^2, B the strength
  // KHR_materials_iridescence: a thin dielectric film over the base (soap bubbles, oil, beetles).
  float iridescence = 0;
  TextureRef iridescence_texture;  // linear, R channel
  float iridescence_ior = 1.3f;
  float iridescence_thickness_min = 100, iridescence_thickness_max = 400;  // nanometres
  TextureRef iridescence_thickness_texture;  // linear, G: from min to max (max without it)
  // KHR_materials_volume: light inside a closed transmissive mesh is absorbed (Beer-Lambert),
  // keeping attenuation_color after attenuation_distance. Thickness 0 is a thin wall (no volume);
  // a ray tracer measures the real path length, so only whether it is 0 matters.
  float thickness = 0;
  float attenuation_distance = 0;  // 0 = infinite: no absorption
  color3 attenuation_color = {1, 1, 1};
  // KHR_materials_dispersion: 20 / the Abbe number (0 = none); the IOR varies with wavelength.
  float dispersion = 0;
  TextureRef specular_texture;      // linear RGB weight for ks (OBJ map_Ks)
  TextureRef alpha_texture;         // linear, R channel (OBJ map_d)

  // Shared.
  color3 emission = {0, 0, 0};  // emitted radiance (already × strength)
  TextureRef emission_texture;  // sRGB, multiplies `emission`
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = true;
  bool unlit = false;  // KHR_materials_unlit: base color is shown as radiance
};

// ---------------------------------------------------------------- geometry

// A triangle mesh with one material, in its own object space; placed by instances.
struct MeshDesc {
  std::string name;
  int material = -1;
  std::vector<vec3> positions;
  std::vector<vec3> normals;     // empty or one per vertex
  std::vector<vec4> tangents;    // empty or one per vertex (w = handedness)
  std::vector<vec2> texcoords0;  // empty or one per vertex
  std::vector<vec2> texcoords1;
  std::vector<vec4> colors;      // empty or one per vertex (COLOR_0, linear RGBA)
  std::vector<uint32_t> indices; // three per triangle
  // Empty, or the vertex positions at each time step of the shutter (scene/motion_steps.h) when
  // skinning or morphing moves them while it is open; `positions` are those at the rendered time.
  std::vector<std::vector<vec3>> motion_positions;
  size_t triangle_count() const { return indices.size() / 3; }
};

struct InstanceDesc {
  int mesh = -1;
  mat4 transform;  // object to world, at the rendered time
  std::string name;
  // Empty, or the transform at each time step of the shutter (scene/motion_steps.h) when the
  // instance moves while it is open.
  std::vector<mat4> motion;
};

enum class ShapeKind { sphere, plane, cylinder, tube };

// Analytic shapes, in world space.
//  sphere:   center, radius
//  plane:    center = a point on it, axis = unit normal (infinite)
//  cylinder: center = centre of the base cap, axis = unit axis, radius, height (capped)
//  tube:     center = a point on the axis, axis = unit axis, radius (infinite, no caps)
struct ShapeDesc {
  ShapeKind kind = ShapeKind::sphere;
  int material = -1;
  vec3 center = {0, 0, 0};
  vec3 axis = {0, 0, 1};
  float radius = 1;
  float height = 1;
  std::string name;
};

// Lines and points (glTF POINTS, LINES, LINE_STRIP, LINE_LOOP; `.scene` line and points blocks),
// in world space like the shapes: vertex i lies at center + positions[i], so that moving them
// into render space moves one point. Lines are round linear curves, each segment from vertex
// segments[k] to the next; points are spheres at every vertex.
enum class StrokeKind { lines, points };
struct StrokeDesc {
  std::string name;
  StrokeKind kind = StrokeKind::lines;
  int material = -1;
  vec3 center = {0, 0, 0};
  std::vector<vec3> positions;
  std::vector<vec4> colors;        // empty or one per vertex (COLOR_0, linear RGBA)
  std::vector<uint32_t> segments;  // lines: each segment's first vertex
  float width = 0;                 // world units across; 0: the render's --line-width
  size_t primitive_count() const { return kind == StrokeKind::lines ? segments.size() : positions.size(); }
};

// ---------------------------------------------------------------- lights

enum class LightKind { ambient, directional, point, spot };

// Intensity units (internal): point/spot W/sr, directional W/m^2, ambient radiance.
// Attenuation divides by (kc + kl*d + kq*d^2); glTF lights use kc = kl = 0, kq = 1.
struct LightDesc {
  std::string name;
  LightKind kind = LightKind::point;
  color3 intensity = {1, 1, 1};
  vec3 position = {0, 0, 0};
  vec3 direction = {0, 0, -1};  // unit; the direction light travels (directional, spot axis)
  float kc = 0, kl = 0, kq = 1;
  // Spot falloff: cos(angle)^exponent (the classic narrow beam) when use_cone is false, the
  // glTF smooth step between outer and inner cone angles (radians) when it is true.
  float spot_exponent = 1;
  bool use_cone = false;
  float inner_cone = 0, outer_cone = 0.785398f;
  float range = 0;  // glTF range; 0 = infinite
};

// ---------------------------------------------------------------- environment and settings

struct EnvironmentDesc {
  color3 color = {0, 0, 0};  // uniform radiance seen by rays that escape (the background)
  std::string map_path;      // equirectangular EXR/HDR; empty = none
  float map_scale = 1;
};

enum class RenderMode { auto_select, whitted, path, naive };
enum class SamplerKind { grid, random, jittered, sobol };
// How radiance becomes a displayed value in 8- and 16-bit images (src/image/view_transform.h).
enum class ViewTransform { standard, linear, filmic, agx, neutral, aces };
// The pixel reconstruction filter (src/sampling/pixel_filter.h), and the widest one accepted, in
// pixels (a radius of 32).
enum class PixelFilterKind { box, triangle, gaussian, mitchell, blackman_harris };
constexpr float max_filter_width = 64;
// How the path tracer chooses the light to sample at a point: in proportion to power, by a light
// BVH's estimate of each light's contribution there, or the BVH when there are many lights.
enum class LightSampler { automatic, power, bvh };

// Render settings a scene file may carry; command-line flags override each one that is set.
struct SceneSettings {
  std::optional<int> width, height, spp, max_depth;
  std::optional<RenderMode> mode;
  std::optional<SamplerKind> sampler;
  std::optional<ViewTransform> view;
  std::optional<bool> transparent;  // RGBA output, the background not seen (RenderOptions::transparent)
  std::optional<PixelFilterKind> filter;
  std::optional<float> filter_width;  // pixels; default per filter
};

// ---------------------------------------------------------------- the scene

struct SceneDesc {
  std::string name;
  std::string source_path;  // file it was loaded from ("-" for stdin)
  std::vector<std::string> input_files;  // every file loading read: the scene, buffers, images, includes
  std::vector<CameraDesc> cameras;
  std::vector<MeshDesc> meshes;
  std::vector<InstanceDesc> instances;
  std::vector<ShapeDesc> shapes;
  std::vector<StrokeDesc> strokes;
  std::vector<MaterialDesc> materials;
  std::vector<TextureDesc> textures;
  std::vector<ImageDesc> images;
  std::vector<LightDesc> lights;
  EnvironmentDesc environment;
  SceneSettings settings;
  std::vector<std::string> warnings;  // shown by `render` (unless quiet) and `info`
  size_t degenerate_triangles_dropped = 0;
};

}  // namespace radiant

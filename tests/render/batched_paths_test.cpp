// A render whose camera rays are traced a tile at a time as Embree packets, and one whose paths
// also advance together with their bounces and shadow rays traced as streams, are the render
// that traces each path alone, one ray at a time (PathBatching::none, the reference), bit for
// bit: radiance, AOVs, coverage and ray counts, for every integrator, with a lens, a filter with
// negative lobes and a window, and with every effect the path tracer has on triangles.
#include <doctest/doctest.h>

#include "accel/scene_accel.h"
#include "integrators/effect_variants.h"
#include "math/transform.h"
#include "load_scene.h"
#include "support/film_measures.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

bool films_identical(const Film& a, const Film& b) {
  if (a.pixels.size() != b.pixels.size() || a.aovs.size() != b.aovs.size() || a.alpha.size() != b.alpha.size())
    return false;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const FilmPixel &p = a.pixels[i], &q = b.pixels[i];
    if (p.samples != q.samples || p.negative_samples != q.negative_samples) return false;
    for (int c = 0; c < 3; ++c)
      if (!(p.sum[c] == q.sum[c]) || !(p.sum_squares[c] == q.sum_squares[c])) return false;
  }
  for (size_t i = 0; i < a.aovs.size(); ++i) {
    const FilmAovs &p = a.aovs[i], &q = b.aovs[i];
    if (!(p.depth == q.depth)) return false;
    for (int c = 0; c < 3; ++c)
      if (!(p.albedo[c] == q.albedo[c]) || !(p.normal[c] == q.normal[c])) return false;
  }
  for (size_t i = 0; i < a.alpha.size(); ++i)
    if (!(a.alpha[i] == b.alpha[i])) return false;
  return true;
}

// A closed box of six quads between corners `lo` and `hi`, facing out.
void add_box(SceneDesc& scene, vec3 lo, vec3 hi, int material) {
  vec3 a = lo, g = hi;
  add_quad(scene, {a.x, a.y, a.z}, {a.x, g.y, a.z}, {g.x, g.y, a.z}, {g.x, a.y, a.z}, material);  // -z
  add_quad(scene, {a.x, a.y, g.z}, {g.x, a.y, g.z}, {g.x, g.y, g.z}, {a.x, g.y, g.z}, material);  // +z
  add_quad(scene, {a.x, a.y, a.z}, {a.x, a.y, g.z}, {a.x, g.y, g.z}, {a.x, g.y, a.z}, material);  // -x
  add_quad(scene, {g.x, a.y, a.z}, {g.x, g.y, a.z}, {g.x, g.y, g.z}, {g.x, a.y, g.z}, material);  // +x
  add_quad(scene, {a.x, a.y, a.z}, {g.x, a.y, a.z}, {g.x, a.y, g.z}, {a.x, a.y, g.z}, material);  // -y
  add_quad(scene, {a.x, g.y, a.z}, {a.x, g.y, g.z}, {g.x, g.y, g.z}, {g.x, g.y, a.z}, material);  // +y
}

// Triangles only (shapes would make the batches trace their rays one at a time): an open room under a sky,
// a dispersive absorbing glass block, a rough metal, a mirror, an emitting panel, a point and a
// spot light; with `cutout`, a half-transparent card as well (see-through steps, and shadows
// that walk through occluders instead of one occlusion query each).
SceneDesc effects_room(bool cutout) {
  SceneDesc scene;
  int wall = add_diffuse(scene, {0.6f, 0.55f, 0.5f});
  add_quad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, wall);   // floor, facing up
  add_quad(scene, {-4, 0, -4}, {4, 0, -4}, {4, 5, -4}, {-4, 5, -4}, wall);  // back wall
  MaterialDesc glass;
  glass.model = MaterialModel::metallic_roughness;
  glass.metallic = 0, glass.roughness = 0, glass.transmission = 1, glass.dispersion = 2;
  glass.thickness = 1, glass.attenuation_distance = 1.5f, glass.attenuation_color = {0.9f, 0.6f, 0.3f};
  add_box(scene, {-1.5f, 0, -1}, {0, 1.5f, 0.5f}, add_material(scene, glass));
  MaterialDesc metal;
  metal.model = MaterialModel::metallic_roughness;
  metal.base_color = {0.9f, 0.7f, 0.4f}, metal.metallic = 1, metal.roughness = 0.3f;
  add_box(scene, {0.5f, 0, -2}, {1.8f, 2, -0.8f}, add_material(scene, metal));
  MaterialDesc mirror;
  mirror.kd = {0.05f, 0.05f, 0.05f}, mirror.kr = {0.8f, 0.8f, 0.8f};
  add_quad(scene, {-3.9f, 0.2f, -3}, {-3.9f, 0.2f, 1}, {-3.9f, 3, 1}, {-3.9f, 3, -3}, add_material(scene, mirror));
  MaterialDesc panel;
  panel.kd = {0, 0, 0}, panel.emission = {6, 5, 4}, panel.double_sided = false;
  add_quad(scene, {-1, 4, -1}, {1, 4, -1}, {1, 4, 1}, {-1, 4, 1}, add_material(scene, panel));  // facing down
  if (cutout) {
    MaterialDesc card;
    card.model = MaterialModel::metallic_roughness;
    card.base_color = {0.2f, 0.8f, 0.3f}, card.metallic = 0, card.alpha = 0.5f, card.alpha_mode = AlphaMode::blend;
    add_quad(scene, {1, 0, 1}, {3, 0, 1}, {3, 2, 1}, {1, 2, 1}, add_material(scene, card));
  }
  scene.lights.push_back(point_light({2, 3, 2}, {8, 8, 8}));
  LightDesc spot = point_light({-2, 3.5f, 2}, {10, 9, 8});
  spot.kind = LightKind::spot;
  spot.direction = normalize(vec3{1, -2, -1.5f});
  spot.use_cone = true, spot.inner_cone = 0.3f, spot.outer_cone = 0.5f;
  scene.lights.push_back(spot);
  scene.environment.color = {0.2f, 0.3f, 0.5f};
  scene.cameras.push_back(perspective_camera({0, 2, 6}, normalize(vec3{0, -0.2f, -1}), {0, 1, 0}, 50));
  return scene;
}

// Every way of tracing; checks that the scene traces its rays as Embree packets and streams
// (analytic shapes and alpha masks through callbacks that take them) and that the images agree.
void require_same_render(const SceneDesc& scene, RenderOptions o) {
  REQUIRE(traces_packets(*build_scene_accel(scene)));
  o.path_batching = PathBatching::none;
  RenderResult alone = render_scene(scene, o);
  for (PathBatching batching : {PathBatching::camera_rays, PathBatching::all_rays}) {
    CAPTURE(int(batching));
    o.path_batching = batching;
    RenderResult together = render_scene(scene, o);
    CHECK(together.stats.rays.camera == alone.stats.rays.camera);
    CHECK(together.stats.rays.shadow == alone.stats.rays.shadow);
    CHECK(together.stats.rays.total() == alone.stats.rays.total());
    CHECK(films_identical(together.film, alone.film));
  }
}

}  // namespace

// A room of matte walls, a glTF plastic box, a rough metal panel and Phong's glossy lobe (a box
// with a mirror lobe too, and a panel) lit by point lights (one with a range), a glTF spot, a
// classic spot (a power of the cosine), the sun, the sky (at full size) and an emitting panel,
// whose vertices the batch shades in its surface lanes (integrators/surface_lanes.h), one wall
// with vertex normals, a rotated and a mirrored instance, and with `shapes` a matte, a plastic
// and an emitting sphere and a plane for a ceiling, beside every vertex the lanes must leave to
// the one-path code: vertex normals that are all zero, a smooth metal, the emitting panel itself.
// Scaled down by `scale`, every triangle's
// normal gets a squared length below float's normal range, and every lane falls back. Nothing in
// it is seen through or textured (see_through_occluders and textured_lanes_room add those).
SceneDesc surface_lanes_room(float scale, bool shapes = false) {
  SceneDesc scene;
  int wall = add_diffuse(scene, {0.7f, 0.6f, 0.5f});
  add_quad(scene, {-4, 0, -4}, {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, wall);    // floor, facing up
  add_quad(scene, {-4, 0, -4}, {4, 0, -4}, {4, 5, -4}, {-4, 5, -4}, wall);  // back wall
  add_quad(scene, {-4, 0, -4}, {-4, 5, -4}, {-4, 5, 4}, {-4, 0, 4}, wall);  // left wall
  MaterialDesc matte;  // glTF's exactly Lambertian material
  matte.model = MaterialModel::metallic_roughness;
  matte.base_color = {0.3f, 0.6f, 0.8f}, matte.metallic = 0, matte.roughness = 1, matte.specular = 0;
  add_box(scene, {-2, 0, -2}, {-0.5f, 1.5f, -0.5f}, add_material(scene, matte));
  MaterialDesc plastic = matte;  // the glossy lanes' commonest material: glTF's default coating
  plastic.base_color = {0.8f, 0.3f, 0.2f}, plastic.roughness = 0.5f, plastic.specular = 1;
  add_box(scene, {-3.5f, 0, 0.5f}, {-2.5f, 2, 1.5f}, add_material(scene, plastic));
  MaterialDesc metal = matte;  // a rough metal, half the back wall
  metal.base_color = {0.9f, 0.8f, 0.5f}, metal.metallic = 1, metal.roughness = 0.3f;
  add_quad(scene, {0, 0.1f, -3.9f}, {3.5f, 0.1f, -3.9f}, {3.5f, 3, -3.9f}, {0, 3, -3.9f}, add_material(scene, metal));
  MaterialDesc mirror = metal;  // a smooth one: delta lobes, one path at a time
  mirror.roughness = 0;
  add_quad(scene, {-3.5f, 0.1f, -3.9f}, {-1, 0.1f, -3.9f}, {-1, 2, -3.9f}, {-3.5f, 2, -3.9f},
           add_material(scene, mirror));
  add_quad(scene, {3.9f, 0.2f, -3}, {3.9f, 3, -3}, {3.9f, 3, 1}, {3.9f, 0.2f, 1}, wall);
  scene.meshes.back().normals = {normalize(vec3{-1, 0.3f, 0.2f}), normalize(vec3{-1, -0.2f, 0}),
                                 normalize(vec3{-0.8f, 0, 0.4f}), {-1, 0, 0}};
  add_quad(scene, {-3.9f, 0.2f, 1}, {-3.9f, 3, 1}, {-3.9f, 3, 3}, {-3.9f, 0.2f, 3}, wall);
  scene.meshes.back().normals.assign(4, vec3{0, 0, 0});  // normalize() rescales: one path at a time
  add_box(scene, {0.5f, 0, -2}, {1.8f, 1, -0.8f}, add_diffuse(scene, {0.9f, 0.9f, 0.9f}));
  scene.instances.back().transform = translation({0.2f, 0.5f, 0.3f}) * rotation_axis({0, 1, 0}, 30);
  add_quad(scene, {0.5f, 0.2f, 2}, {1.5f, 0.2f, 2}, {1.5f, 1.5f, 2.5f}, {0.5f, 1.5f, 2.5f}, wall);
  scene.meshes.back().normals = {normalize(vec3{0.1f, -0.4f, 1}), normalize(vec3{-0.2f, -0.5f, 1}),
                                 normalize(vec3{0, -0.3f, 1}), normalize(vec3{0.3f, -0.4f, 0.9f})};
  scene.instances.back().transform = translation({-1, 0.1f, 0}) * scaling({-1, 1.2f, 1});  // mirrored
  MaterialDesc panel;
  panel.kd = {0, 0, 0}, panel.emission = {3, 3, 2}, panel.double_sided = false;
  add_quad(scene, {-1, 4, 1}, {1, 4, 1}, {1, 4, 3}, {-1, 4, 3}, add_material(scene, panel));  // facing down
  MaterialDesc shiny;  // the .scene format's Phong with glossy and mirror lobes, weights summing past one
  shiny.kd = {0.6f, 0.3f, 0.2f}, shiny.ks = {0.5f, 0.5f, 0.45f}, shiny.kr = {0.2f, 0.2f, 0.25f}, shiny.shininess = 40;
  add_box(scene, {2.2f, 0, -3.5f}, {3.5f, 1.2f, -2.5f}, add_material(scene, shiny));
  MaterialDesc lacquer;  // a glossy lobe alone, sharp
  lacquer.kd = {0, 0, 0}, lacquer.ks = {0.7f, 0.6f, 0.5f}, lacquer.shininess = 300;
  add_quad(scene, {-3.5f, 2.2f, -3.9f}, {-1, 2.2f, -3.9f}, {-1, 3.5f, -3.9f}, {-3.5f, 3.5f, -3.9f},
           add_material(scene, lacquer));
  scene.lights.push_back(point_light({2, 3, 2}, {8, 8, 8}));
  scene.lights.push_back(point_light({-2, 2, 1}, {3, 4, 5}, 1, 0.5f, 0));  // .scene-style attenuation
  LightDesc ranged = point_light({0, 1, 3}, {2, 2, 2});
  ranged.range = 3;
  scene.lights.push_back(ranged);
  LightDesc spot = point_light({-2, 3.5f, 2}, {10, 9, 8});
  spot.kind = LightKind::spot;
  spot.direction = normalize(vec3{1, -2, -1.5f});
  spot.use_cone = true, spot.inner_cone = 0.3f, spot.outer_cone = 0.5f;
  scene.lights.push_back(spot);
  spot.position = {1, 3.5f, 0}, spot.direction = normalize(vec3{-0.5f, -1, -1}), spot.use_cone = false;
  spot.spot_exponent = 8;
  scene.lights.push_back(spot);
  LightDesc sun;
  sun.kind = LightKind::directional, sun.direction = normalize(vec3{-0.3f, -1, -0.6f}), sun.intensity = {0.5f, 0.45f, 0.4f};
  scene.lights.push_back(sun);
  // The sky only at full size. Scaled down, Embree's kernels flush the barycentrics of these tiny
  // triangles to zero, so hits land on vertices, and its stream and single-ray kernels disagree
  // about shadow rays that leave the corner where three walls meet (docs/stability.md).
  if (scale == 1) scene.environment.color = {0.15f, 0.2f, 0.3f};
  ShapeDesc ball;  // shapes make Embree call radiant back for each ray: no packets
  ball.kind = ShapeKind::sphere, ball.center = {2.5f, 0.7f, 1}, ball.radius = 0.7f;
  ball.material = add_material(scene, plastic);
  scene.shapes.push_back(ball);
  ball.center = {-1.2f, 0.5f, 2}, ball.radius = 0.5f, ball.material = wall;
  scene.shapes.push_back(ball);
  ShapeDesc ceiling;
  ceiling.kind = ShapeKind::plane, ceiling.center = {0, 5, 0}, ceiling.axis = {0, -1, 0}, ceiling.material = wall;
  scene.shapes.push_back(ceiling);
  MaterialDesc glowing;  // an emitting sphere: a light the lanes draw one lane at a time
  glowing.kd = {0, 0, 0}, glowing.emission = {4, 3, 2};
  ball.center = {1.5f, 3.8f, -1}, ball.radius = 0.3f, ball.material = add_material(scene, glowing);
  scene.shapes.push_back(ball);
  if (!shapes) scene.shapes.clear();
  scene.cameras.push_back(perspective_camera({0, 2, 6}, normalize(vec3{0, -0.25f, -1}), {0, 1, 0}, 70));
  for (ShapeDesc& shape : scene.shapes) shape.center = shape.center * scale, shape.radius *= scale;
  for (MeshDesc& mesh : scene.meshes)
    for (vec3& p : mesh.positions) p = p * scale;
  for (InstanceDesc& instance : scene.instances)
    for (int row = 0; row < 3; ++row) instance.transform.m[row][3] *= scale;
  for (LightDesc& light : scene.lights) {
    light.position = light.position * scale, light.range *= scale;
    // The same image: the inverse square law (the sun's irradiance does not fall off).
    if (light.kind != LightKind::directional) light.intensity = light.intensity * (scale * scale);
  }
  scene.cameras[0].position = scene.cameras[0].position * scale;
  return scene;
}

TEST_CASE("batched paths: vertices shaded in SIMD lanes render what one path renders") {
  for (std::pair<float, bool> room : {std::pair{1.0f, false}, {1e-11f, false}, {1.0f, true}, {1e-11f, true}}) {
    // Named copies, not structured bindings: Clang 14 cannot capture those in CAPTURE's lambda.
    float scale = room.first;
    bool shapes = room.second;
    SceneDesc scene = surface_lanes_room(scale, shapes);
    for (bool aovs : {false, true}) {  // AOVs: the first vertices go one path at a time
      for (int max_depth : {1, 8}) {
        // The light BVH's choices, made ahead for the whole stage, reach the lanes too.
        for (LightSampler light_sampler : {LightSampler::power, LightSampler::bvh}) {
          CAPTURE(scale);
          CAPTURE(aovs);
          CAPTURE(max_depth);
          CAPTURE(int(light_sampler));
          CAPTURE(shapes);
          RenderOptions o;
          o.width = 30, o.height = 22, o.spp = 6, o.mode = RenderMode::path, o.max_depth = max_depth;
          o.light_sampler = light_sampler;
          if (aovs) o.aovs = {"albedo", "normal", "depth"};
          RenderResult result = render_scene(scene, o);
          CHECK(result.settings.light_sampler == light_sampler);
          CHECK((result.settings.effects & (effect_group_transparency | effect_group_textures)) == 0);
          CHECK(result.stats.rays.shadow > 1000);
          require_same_render(scene, o);
        }
      }
    }
  }
  // Each kind of light switched off (--effects): the lanes take only the other's vertices.
  for (std::string effects : {"-direct", "-emission", "-indirect"}) {
    CAPTURE(effects);
    RenderOptions o;
    o.width = 24, o.height = 18, o.spp = 4, o.mode = RenderMode::path;
    o.effects = effects;
    require_same_render(surface_lanes_room(1), o);
  }
  // The sky as a map, with a dark band: the lanes draw its directions from its distribution too.
  ScratchDir dir("batched-sky");
  std::vector<float> sky;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) sky.push_back(y == 2 ? 0.0f : 0.1f + 0.05f * float((x * 7 + y * 3 + c) % 11));
  write_test_image(dir.file("sky.exr"), 16, 8, {"R", "G", "B"}, sky);
  for (LightSampler light_sampler : {LightSampler::power, LightSampler::bvh}) {
    CAPTURE(int(light_sampler));
    RenderOptions o;
    o.width = 24, o.height = 18, o.spp = 4, o.mode = RenderMode::path, o.light_sampler = light_sampler;
    o.env_map = dir.file("sky.exr").string();
    require_same_render(surface_lanes_room(1), o);
  }
}

// The same room textured, as most real files are: a checker base colour on the walls and the
// matte box, vertex colours on the plastic box, a metallic-roughness texture whose black texels
// make the plastic smooth (those hits must leave the lanes), normal maps on the plastic box and
// the metal panel, a bump map on the walls (some with vertex normals), and an emission texture on
// the panel (vertices that choose it go one path at a time). Every quad gets UVs and a tangent.
SceneDesc textured_lanes_room() {
  SceneDesc scene = surface_lanes_room(1);
  auto add_texture = [&](std::string name, int width, int height, int channels, std::vector<uint8_t> texels) {
    ImageDesc image;
    image.name = std::move(name), image.width = width, image.height = height, image.channels = channels;
    image.texels8 = std::move(texels);
    scene.images.push_back(std::move(image));
    TextureDesc texture;
    texture.image = int(scene.images.size()) - 1;
    scene.textures.push_back(texture);
    TextureRef ref;
    ref.texture = int(scene.textures.size()) - 1;
    return ref;
  };
  std::vector<uint8_t> checker;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (uint8_t c : {uint8_t((x + y) % 2 ? 230 : 40), uint8_t(60 * x), uint8_t(200 - 40 * y)}) checker.push_back(c);
  TextureRef checker_texture = add_texture("checker", 4, 4, 3, checker);
  TextureRef roughness_metal = add_texture("roughness-metal", 2, 2, 3, {0, 255, 0, 0, 128, 255, 0, 0, 0, 0, 60, 30});
  TextureRef normal_map = add_texture("normals", 2, 2, 3, {128, 128, 255, 200, 128, 200, 90, 170, 220, 128, 40, 230});
  TextureRef height = add_texture("height", 2, 2, 1, {0, 255, 60, 128});
  MaterialDesc& wall = scene.materials[0];
  wall.base_color_texture = checker_texture;
  wall.bump_texture = height, wall.bump_scale = 0.05f;
  scene.materials[1].base_color_texture = checker_texture;  // the matte box
  MaterialDesc& plastic = scene.materials[2];
  plastic.metallic_roughness_texture = roughness_metal, plastic.normal_texture = normal_map;
  scene.materials[3].normal_texture = normal_map;  // the rough metal panel
  for (MaterialDesc& m : scene.materials)
    if (!is_black(m.emission)) m.emission_texture = checker_texture;
  for (MeshDesc& mesh : scene.meshes) {
    REQUIRE(mesh.positions.size() == 4);
    mesh.texcoords0 = {{0, 0}, {0, 2}, {2, 2}, {2, 0}};
    vec3 along = normalize(mesh.positions[3] - mesh.positions[0]);
    mesh.tangents.assign(4, vec4{along.x, along.y, along.z, 1});
    if (mesh.material == 2) mesh.colors = {{1, 1, 1, 1}, {0.2f, 1, 0.5f, 1}, {1, 0.3f, 0.3f, 1}, {0.5f, 0.5f, 1, 1}};
  }
  return scene;
}

TEST_CASE("batched paths: textured vertices shaded in SIMD lanes render what one path renders") {
  SceneDesc scene = textured_lanes_room();
  for (TextureFilterMode filter : {TextureFilterMode::bilinear, TextureFilterMode::trilinear}) {
    for (LightSampler light_sampler : {LightSampler::power, LightSampler::bvh}) {
      CAPTURE(int(filter));
      CAPTURE(int(light_sampler));
      RenderOptions o;
      o.width = 30, o.height = 22, o.spp = 6, o.mode = RenderMode::path, o.max_depth = 8;
      o.light_sampler = light_sampler, o.texture_filter = filter;
      RenderResult result = render_scene(scene, o);
      CHECK((result.settings.effects & effect_group_textures) == effect_group_textures);
      CHECK((result.settings.effects & effect_group_transparency) == 0);
      CHECK(result.stats.rays.shadow > 1000);
      require_same_render(scene, o);
    }
  }
  // Normal maps off (--effects): the lanes' own normals again, on the textured materials.
  RenderOptions o;
  o.width = 24, o.height = 18, o.spp = 4, o.mode = RenderMode::path;
  o.effects = "-normal-maps";
  require_same_render(scene, o);
}

// What a lanes room gains to be seen through: a pane that lets 60% of the light through
// unbent (kt, ior 1) under the first point light, a half-transparent card, and a glass box sunk
// into the floor with an absorbing volume, so that paths inside it reach the floor. Shadow rays
// then walk past occluders instead of asking one occlusion query, and the lanes must leave a
// path inside the volume to advance() (its segment's absorption comes first). With `textured`,
// the card's opacity comes from its base colour texture's alpha, a pattern fine enough that the
// mip level a shadow ray's walk reads at it depends on the vertex's texture footprint.
void add_see_through_occluders(SceneDesc& scene, bool textured) {
  MaterialDesc pane;
  pane.kd = {0.05f, 0.05f, 0.05f}, pane.kt = {0.6f, 0.5f, 0.4f}, pane.ior = 1;
  add_quad(scene, {1, 1.8f, 1}, {1, 1.8f, 3}, {3, 1.8f, 3}, {3, 1.8f, 1}, add_material(scene, pane));  // facing up
  MaterialDesc card;
  card.model = MaterialModel::metallic_roughness;
  card.base_color = {0.2f, 0.8f, 0.3f}, card.metallic = 0, card.alpha = 0.5f, card.alpha_mode = AlphaMode::blend;
  if (textured) {
    ImageDesc image;
    image.name = "see-through", image.width = 8, image.height = 8, image.channels = 4;
    for (int texel = 0; texel < 64; ++texel)
      for (int c = 0; c < 4; ++c) image.texels8.push_back(uint8_t((texel * 37 + c * 91) % 256));
    scene.images.push_back(image);
    TextureDesc texture;
    texture.image = int(scene.images.size()) - 1;
    scene.textures.push_back(texture);
    card.base_color_texture.texture = int(scene.textures.size()) - 1;
    card.alpha = 0.9f;
  }
  add_quad(scene, {-0.5f, 0, 0.5f}, {1, 0, 0.5f}, {1, 2, 0.5f}, {-0.5f, 2, 0.5f}, add_material(scene, card));
  if (textured) scene.meshes.back().texcoords0 = {{0, 0}, {0, 6}, {6, 6}, {6, 0}};
  MaterialDesc glass;
  glass.model = MaterialModel::metallic_roughness;
  glass.metallic = 0, glass.roughness = 0, glass.transmission = 1;
  glass.thickness = 1, glass.attenuation_distance = 1.5f, glass.attenuation_color = {0.9f, 0.6f, 0.3f};
  add_box(scene, {1.5f, -0.5f, -0.5f}, {2.8f, 1, 0.5f}, add_material(scene, glass));
}

TEST_CASE("batched paths: the opaque vertices of a scene that is seen through are shaded in SIMD lanes too") {
  for (bool textured : {false, true}) {
    SceneDesc scene = textured ? textured_lanes_room() : surface_lanes_room(1);
    add_see_through_occluders(scene, textured);
    for (LightSampler light_sampler : {LightSampler::power, LightSampler::bvh}) {
      CAPTURE(textured);
      CAPTURE(int(light_sampler));
      RenderOptions o;
      o.width = 30, o.height = 22, o.spp = 6, o.mode = RenderMode::path, o.max_depth = 8;
      o.light_sampler = light_sampler, o.texture_filter = TextureFilterMode::trilinear;
      RenderResult result = render_scene(scene, o);
      uint32_t see_through = effect_transparent_shadows | effect_refraction | effect_alpha | effect_absorption;
      CHECK((result.settings.effects & see_through) == see_through);
      CHECK(result.stats.rays.shadow > 1000);
      CHECK(result.stats.rays.refraction > 100);
      require_same_render(scene, o);
    }
  }
}

TEST_CASE("batched paths: the glTF Cornell box renders the same in batches, path, naive and Whitted") {
  SceneDesc scene = load_scene(source_path("assets/cornell.gltf").string());
  for (RenderMode mode : {RenderMode::path, RenderMode::naive, RenderMode::whitted}) {
    RenderOptions o;
    o.width = 37, o.height = 29, o.spp = 3, o.mode = mode;  // tiles cut short at the edges
    o.aovs = {"albedo", "normal", "depth"};
    CAPTURE(int(mode));
    require_same_render(scene, o);
  }
}

TEST_CASE("batched paths: a lens, Mitchell's negative lobes, a window and a transparent film change nothing") {
  SceneDesc scene = load_scene(source_path("assets/cornell.gltf").string());
  REQUIRE(!scene.cameras.empty());
  scene.cameras[0].lens_radius = 0.01f;
  scene.cameras[0].focus_distance = 1;
  RenderOptions o;
  o.width = 40, o.height = 40, o.spp = 4, o.mode = RenderMode::path;
  o.filter = PixelFilterKind::mitchell;
  o.crop = PixelWindow{5, 3, 33, 38};
  o.transparent = true;
  require_same_render(scene, o);
}

TEST_CASE("batched paths: glass with dispersion and absorption, metal, mirror, sky, area, point and spot lights") {
  for (bool cutout : {false, true}) {
    CAPTURE(cutout);
    SceneDesc scene = effects_room(cutout);
    RenderOptions o;
    o.width = 30, o.height = 22, o.spp = 6, o.mode = RenderMode::path, o.max_depth = 12;
    o.aovs = {"albedo", "normal", "depth"};
    RenderResult batched = render_scene(scene, o);
    // The scene exercises what it is meant to: refraction, absorption, both shadow kinds.
    CHECK((batched.settings.effects & effect_refraction) != 0);
    CHECK((batched.settings.effects & effect_absorption) != 0);
    CHECK(((batched.settings.effects & effect_alpha) != 0) == cutout);
    CHECK(batched.stats.rays.refraction > 100);
    CHECK(batched.stats.rays.shadow > 1000);
    require_same_render(scene, o);
    o.mode = RenderMode::naive;
    require_same_render(scene, o);
  }
}

TEST_CASE("batched paths: textures, normal maps and emission textures of real glTF files render the same") {
  for (const char* file : {"assets/models/checker-cube.gltf", "assets/models/normal-mapped-quad.gltf",
                           "assets/models/instanced-boxes.glb", "assets/models/textured-cube.obj",
                           "assets/models/lit-windows.gltf"}) {
    CAPTURE(file);
    SceneDesc scene = load_scene(source_path(file).string());
    RenderOptions o;
    o.width = 24, o.height = 24, o.spp = 4, o.mode = RenderMode::path;
    o.env_color = color3{1, 1, 1};  // the textured OBJ is lit by the sky alone
    require_same_render(scene, o);
  }
}

TEST_CASE("batched paths: every sampler and both light samplers draw what one path draws") {
  // The batch draws a vertex's random numbers ahead in SIMD, Sobol's points or the other
  // samplers' hashes (light choices, lobe choices, roulette among them: the room has four
  // lights, rough metal and glass, depth 12), and its surface lanes shade with them.
  SceneDesc scene = effects_room(false);
  for (SamplerKind sampler : {SamplerKind::sobol, SamplerKind::jittered, SamplerKind::random})
    for (LightSampler light_sampler : {LightSampler::power, LightSampler::bvh}) {
      CAPTURE(int(sampler));
      CAPTURE(int(light_sampler));
      RenderOptions o;
      o.width = 20, o.height = 16, o.spp = 4, o.mode = RenderMode::path, o.max_depth = 12;
      o.sampler = sampler;
      o.light_sampler = light_sampler;
      RenderResult result = render_scene(scene, o);
      CHECK(result.settings.sampler == sampler);
      CHECK(result.settings.light_sampler == light_sampler);
      require_same_render(scene, o);
    }
}

TEST_CASE("batched paths: analytic shapes and alpha masks, whose hits Embree calls back for, batch the same") {
  // Their callbacks take Embree's packets, so the batch traces these scenes' rays in streams too.
  SceneDesc room = effects_room(false);
  MaterialDesc chrome;
  chrome.kd = {0.1f, 0.1f, 0.1f}, chrome.kr = {0.7f, 0.7f, 0.7f};
  add_sphere(room, {2.5f, 0.7f, 0.5f}, 0.7f, add_material(room, chrome));
  add_sphere(room, {-2.5f, 0.5f, 1}, 0.5f, add_diffuse(room, {0.3f, 0.5f, 0.8f}));
  MaterialDesc leaf;  // a mask below its cutoff: every hit on the card is rejected by its callback
  leaf.model = MaterialModel::metallic_roughness;
  leaf.base_color = {0.2f, 0.8f, 0.3f}, leaf.metallic = 0, leaf.alpha = 0.3f, leaf.alpha_mode = AlphaMode::mask;
  add_quad(room, {-3, 0, 2}, {-1, 0, 2}, {-1, 2, 2}, {-3, 2, 2}, add_material(room, leaf));
  for (RenderMode mode : {RenderMode::path, RenderMode::naive, RenderMode::whitted}) {
    CAPTURE(int(mode));
    RenderOptions o;
    o.width = 26, o.height = 19, o.spp = 4, o.mode = mode, o.max_depth = 8;
    o.aovs = {"albedo", "normal", "depth"};
    require_same_render(room, o);
  }
  // The bundled many-lights scene: spheres and a plane under 400 lamps, by both light samplers.
  SceneDesc lamps = load_scene(source_path("assets/many-lights.scene").string());
  for (LightSampler light_sampler : {LightSampler::power, LightSampler::bvh}) {
    CAPTURE(int(light_sampler));
    RenderOptions o;
    o.width = 24, o.height = 18, o.spp = 4, o.mode = RenderMode::path;
    o.light_sampler = light_sampler;
    require_same_render(lamps, o);
  }
}

TEST_CASE("batched paths: sub-paths from the first hit (--indirect-paths) batch the same") {
  // Three sub-paths do not divide a batch (85 camera samples a batch), four do; every effect of
  // the room, an alpha card among them, and the glTF box's area light (MIS at the first bounce).
  for (int indirect_paths : {3, 4}) {
    CAPTURE(indirect_paths);
    SceneDesc room = effects_room(true);
    RenderOptions o;
    o.width = 21, o.height = 17, o.spp = 3, o.mode = RenderMode::path, o.max_depth = 10;
    o.indirect_paths = indirect_paths;
    o.aovs = {"albedo", "normal", "depth"};
    require_same_render(room, o);
    o.mode = RenderMode::naive;
    require_same_render(room, o);
    SceneDesc box = load_scene(source_path("assets/cornell.gltf").string());
    o.mode = RenderMode::path;
    require_same_render(box, o);
  }
}

TEST_CASE("batched paths: the sample clamps clamp the same in SIMD lanes as one path at a time") {
  for (bool lanes_room : {true, false}) {
    CAPTURE(lanes_room);
    SceneDesc scene = lanes_room ? surface_lanes_room(1.0f, false) : effects_room(false);
    RenderOptions o;
    o.width = 30, o.height = 22, o.spp = 6, o.mode = RenderMode::path, o.max_depth = 8;
    RenderResult unclamped = render_scene(scene, o);
    o.clamp_direct = 0.5f, o.clamp_indirect = 0.05f;  // low enough to cut most of both kinds
    RenderResult clamped = render_scene(scene, o);
    CHECK(mean_luminance(clamped.film) < 0.9 * mean_luminance(unclamped.film));
    require_same_render(scene, o);
    o.mode = RenderMode::naive;
    require_same_render(scene, o);
  }
}

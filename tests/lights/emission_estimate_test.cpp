// Emissive triangles are weighed by what their emission texture lets them emit: a triangle over
// black texels gets no light samples, one over bright texels gets its share, and the estimate
// reads every texel a lookup on the triangle could (wrap modes, filtering, coarse cells).
#include <doctest/doctest.h>

#include <cmath>

#include "lights/emission_estimate.h"
#include "lights/light_selection.h"
#include "load_scene.h"
#include "materials/texture_pyramid.h"
#include "support/film_measures.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A one-row float texture, black but for `bright` texels of value `value`.
SceneDesc textured_scene(int width, std::vector<int> bright, float value, TextureWrap wrap) {
  SceneDesc scene;
  ImageDesc image;
  image.name = "emission";
  image.width = width, image.height = 1, image.channels = 3;
  image.texels_float.assign(size_t(width) * 3, 0.0f);
  for (int x : bright)
    for (int c = 0; c < 3; ++c) image.texels_float[size_t(x) * 3 + size_t(c)] = value;
  scene.images.push_back(image);
  TextureDesc texture;
  texture.image = 0;
  texture.wrap_s = texture.wrap_t = wrap;
  texture.filter = TextureFilter::nearest;
  scene.textures.push_back(texture);
  MaterialDesc m;
  m.emission = {1, 1, 1};
  m.emission_texture.texture = 0;
  scene.materials.push_back(m);
  return scene;
}

// The estimate for a triangle spanning u in [u0, u1] (all of v).
float strip_luminance(const SceneDesc& scene, float u0, float u1) {
  EmissionEstimates estimates(scene, nullptr);
  vec2 uv[3] = {{u0, 0}, {u1, 0}, {u1, 1}};
  return estimates.triangle_luminance(scene.materials[0], uv);
}

// Eight quads side by side facing down (normal -y), quad k mapped onto u in [k/8, (k+1)/8] and
// made of material quad_material[k], each a mesh of its own (light slots 2k and 2k + 1 when all
// emit).
void add_strip(SceneDesc& scene, const int (&quad_material)[8]) {
  for (int k = 0; k < 8; ++k) {
    MeshDesc mesh;
    mesh.material = quad_material[k];
    float x0 = -4 + float(k), x1 = x0 + 1, u0 = float(k) / 8, u1 = float(k + 1) / 8;
    mesh.positions = {{x0, 2, -0.5f}, {x1, 2, -0.5f}, {x1, 2, 0.5f}, {x0, 2, 0.5f}};
    mesh.texcoords0 = {{u0, 0}, {u1, 0}, {u1, 1}, {u0, 1}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(mesh);
    InstanceDesc instance;
    instance.mesh = int(scene.meshes.size()) - 1;
    scene.instances.push_back(instance);
  }
}
void add_textured_strip(SceneDesc& scene) { add_strip(scene, {0, 0, 0, 0, 0, 0, 0, 0}); }

// Texels 48-55 of 64 glow (4): quad 6 of the strip, exactly, as the nearest texel is read.
SceneDesc glowing_quad_six() {
  std::vector<int> bright;
  for (int x = 48; x < 56; ++x) bright.push_back(x);
  return textured_scene(64, bright, 4.0f, TextureWrap::clamp_to_edge);
}

// A grey floor under the strip and a camera between them looking down at the floor below quads
// 5 to 7: it sees only light the strip sends there, not the strip's bright edges.
void add_floor_and_camera(SceneDesc& scene) {
  add_quad(scene, {-5, 0, -3}, {-5, 0, 3}, {5, 0, 3}, {5, 0, -3}, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  scene.cameras.push_back(perspective_camera({2.5f, 1, 0}, {0, -1, 0}, {0, 0, -1}, 90));
}

// Direct light only, the texture read at full resolution (its own filter: nearest).
RenderOptions direct_light(int spp, uint32_t seed) {
  RenderOptions o;
  o.width = o.height = 32;
  o.spp = spp;
  o.max_depth = 1;
  o.mode = RenderMode::path;
  o.seed = seed;
  o.texture_filter = TextureFilterMode::bilinear;
  o.env_preset = EnvironmentPreset::none;  // the emitter alone, not the default studio
  return o;
}

}  // namespace

TEST_CASE("emission estimate: the mean over the texels a triangle can read, zero only over black ones") {
  // Texels 48-55 of 64 are bright: quad 6 of the strip. A quad reads its own eight texels and,
  // through bilinear filtering, one more on each side: quads 5 and 7 see one bright texel,
  // quads 0-4 none.
  SceneDesc scene = glowing_quad_six();
  for (int k = 0; k <= 4; ++k) CHECK(strip_luminance(scene, float(k) / 8, float(k + 1) / 8) == 0.0f);
  CHECK(strip_luminance(scene, 6.0f / 8, 7.0f / 8) == doctest::Approx(4.0 * 8 / 10));  // texels 47-56
  CHECK(strip_luminance(scene, 5.0f / 8, 6.0f / 8) == doctest::Approx(4.0 * 1 / 10));  // texels 39-48
  CHECK(strip_luminance(scene, 7.0f / 8, 1.0f) == doctest::Approx(4.0 * 1 / 9));       // 55-63, clamped
  CHECK(strip_luminance(scene, 0, 1) == doctest::Approx(4.0 * 8 / 64));                // the whole image
  // The emission factor scales it, by luminance.
  scene.materials[0].emission = {0, 2, 0};
  CHECK(strip_luminance(scene, 6.0f / 8, 7.0f / 8) == doctest::Approx(0.7152 * 2 * 4.0 * 8 / 10).epsilon(1e-4));
}

TEST_CASE("emission estimate: wrap modes bring in the texels across the image's edge") {
  // Only the last texel is bright. Bilinear filtering at u = 0 reads it with repeat; clamping
  // and mirroring read the first texel instead. Beyond u = 1 mirroring reads it.
  CHECK(strip_luminance(textured_scene(64, {63}, 1, TextureWrap::repeat), 0, 1.0f / 8) > 0);
  CHECK(strip_luminance(textured_scene(64, {63}, 1, TextureWrap::clamp_to_edge), 0, 1.0f / 8) == 0);
  CHECK(strip_luminance(textured_scene(64, {63}, 1, TextureWrap::mirrored_repeat), 0, 1.0f / 8) == 0);
  CHECK(strip_luminance(textured_scene(64, {63}, 1, TextureWrap::mirrored_repeat), 1, 1.125f) > 0);
  CHECK(strip_luminance(textured_scene(64, {0}, 1, TextureWrap::repeat), 2.5f, 2.6f) == 0);
  CHECK(strip_luminance(textured_scene(64, {0}, 1, TextureWrap::repeat), 2.9f, 3.05f) > 0);
  // Coordinates no lookup can place (NaN, huge) may read any texel.
  float nan = std::nanf("");
  CHECK(strip_luminance(textured_scene(64, {0}, 1, TextureWrap::repeat), nan, 0.5f) > 0);
  CHECK(strip_luminance(textured_scene(64, {0}, 1, TextureWrap::repeat), 1e20f, 1e20f) > 0);
}

TEST_CASE("emission estimate: cells coarser than texels round the box out, never in") {
  // 1024 texels in 256 cells of four; texel 701 is bright (cell 175, texels 700-703).
  SceneDesc scene = textured_scene(1024, {701}, 1, TextureWrap::clamp_to_edge);
  CHECK(strip_luminance(scene, 100.0f / 1024, 110.0f / 1024) == 0);
  // Texels 699-702 read: cells 174-175, texels 696-703.
  CHECK(strip_luminance(scene, 700.0f / 1024, 702.0f / 1024) == doctest::Approx(1.0 / 8));
  // Texels 691-696 read: cells 172-174, texels 688-699, short of the bright one: still zero.
  CHECK(strip_luminance(scene, 692.0f / 1024, 696.0f / 1024) == 0);
  CHECK(strip_luminance(scene, 0, 1) == doctest::Approx(1.0 / 1024));
}

TEST_CASE("emission estimate: power selection gives black-textured triangles no samples") {
  SceneDesc scene = glowing_quad_six();
  add_textured_strip(scene);
  LightTable lights = make_light_table(scene, {0, 0, 0}, "", true, nullptr, LightSampler::power);
  REQUIRE(lights.area_lights.size() == 16);
  vec3 p = {0, 0, 0}, n = {0, 1, 0};
  double sum = 0;
  for (size_t slot = 0; slot < 16; ++slot) sum += light_choice_probability(lights, p, n, slot);
  CHECK(sum == doctest::Approx(1).epsilon(1e-5));
  for (size_t slot = 0; slot < 10; ++slot) CHECK(light_choice_probability(lights, p, n, slot) == 0);  // quads 0-4
  // Quad 6 (slots 12, 13) has 8/10 bright texels, quad 5 1/10 and quad 7 1/9 (see above).
  double quad6 = light_choice_probability(lights, p, n, 12) + light_choice_probability(lights, p, n, 13);
  CHECK(quad6 == doctest::Approx((8.0 / 10) / (8.0 / 10 + 1.0 / 10 + 1.0 / 9)).epsilon(1e-4));
}

TEST_CASE("emission estimate: a render that reads no textures weighs every triangle by its factor") {
  // --effects without textures: light samples then see the emission factor all over the strip.
  SceneDesc scene = glowing_quad_six();
  add_textured_strip(scene);
  MemoryBudget budget(1 << 20);
  LightTable lights = make_light_table(scene, {0, 0, 0}, "", true, &budget, LightSampler::power, false);
  for (size_t slot = 0; slot < 16; ++slot)
    CHECK(light_choice_probability(lights, {0, 0, 0}, {0, 1, 0}, slot) == doctest::Approx(1.0 / 16));
  CHECK(budget.used() == lights.area_light_memory.bytes());  // no emission tables were built
}

TEST_CASE("emission estimate: the light BVH goes by the same estimates") {
  SceneDesc scene = glowing_quad_six();
  add_textured_strip(scene);
  LightTable lights = make_light_table(scene, {0, 0, 0}, "", true, nullptr, LightSampler::bvh);
  REQUIRE(lights.sampler == LightSampler::bvh);
  vec3 p = {1.5f, 0, 0}, n = {0, 1, 0};  // below quad 5
  double sum = 0;
  for (size_t slot = 0; slot < 16; ++slot) sum += light_choice_probability(lights, p, n, slot);
  CHECK(sum == doctest::Approx(1).epsilon(1e-4));
  for (size_t slot = 0; slot < 10; ++slot) CHECK(light_choice_probability(lights, p, n, slot) == 0);
  CHECK(light_choice_probability(lights, p, n, 12) > 0);
}

TEST_CASE("emission estimate: an all-black emission texture leaves nothing to choose, without failing") {
  SceneDesc scene = textured_scene(64, {}, 0, TextureWrap::repeat);
  add_textured_strip(scene);
  for (LightSampler sampler : {LightSampler::power, LightSampler::bvh}) {
    LightTable lights = make_light_table(scene, {0, 0, 0}, "", true, nullptr, sampler);
    LightChoice choice;
    CHECK_FALSE(choose_light(lights, {0, 0, 0}, {0, 1, 0}, [] { return 0.5f; }, choice));
  }
}

TEST_CASE("emission estimate: its tables are charged to the memory budget") {
  SceneDesc scene = textured_scene(1024, {701}, 1, TextureWrap::repeat);
  add_textured_strip(scene);
  uint64_t table = uint64_t(257) * 2 * 3 * sizeof(double), building = 1024 * sizeof(size_t) + sizeof(int);
  CHECK(emission_estimate_bytes(scene) == table + sizeof(EmissionEstimates::ImageSums) + building);
  scene.materials[0].emission = {0, 0, 0};  // nothing emits: no tables
  CHECK(emission_estimate_bytes(scene) == 0);
  scene.materials[0].emission = {1, 1, 1};
  // Room for the 16 area lights (about 3 KB), not for the table (12 KB).
  MemoryBudget budget(8 * 1024);
  CHECK_THROWS_WITH_AS(make_light_table(scene, {0, 0, 0}, "", true, &budget, LightSampler::power),
                       doctest::Contains("emission textures"), MemoryLimitError);
  CHECK(budget.used() == 0);
}

TEST_CASE("emission estimate render: a textured emitter converges to its untextured equal, with about its noise") {
  // The same light two ways: quad 6 of the strip glowing through the texture, and quad 6 made of
  // an untextured emitter with the other quads not emitting at all.
  SceneDesc textured = glowing_quad_six();
  add_textured_strip(textured);
  add_floor_and_camera(textured);
  SceneDesc flat;
  flat.materials.push_back(MaterialDesc{});  // as the textured one, without emission
  MaterialDesc glow;
  glow.emission = {4, 4, 4};
  flat.materials.push_back(glow);
  add_strip(flat, {0, 0, 0, 0, 0, 0, 1, 0});
  add_floor_and_camera(flat);

  CHECK(largest_block_z(render_scene(textured, direct_light(64, 0)).film, render_scene(flat, direct_light(64, 1)).film) <
        4);
  Film reference = render_scene(flat, direct_light(1024, 2)).film;
  double textured_error = rms_difference(render_scene(textured, direct_light(16, 0)).film, reference);
  double flat_error = rms_difference(render_scene(flat, direct_light(16, 0)).film, reference);
  // The flat strip's light samples all land on quad 6 and its error is small: the light seen
  // from the floor hardly varies over the quad. The textured strip's land there 79% of the time
  // by power (quads 5 and 7 get the rest), and each miss adds the light's whole value to the
  // error. Measured: 2.15 times the flat strip's error; 5.57 times with every quad weighed by
  // its emission factor alone (an eighth of the samples each), as before the estimates.
  CHECK(textured_error < 3 * flat_error);
}

TEST_CASE("emission estimate: the lit-windows asset gives its light samples to the lit windows alone") {
  // A facade of 16 x 8 cells of 4 x 4 texels each; a lit window is its cell's inner 2 x 2 texels,
  // and the cells' borders are black, so no lookup on a dark cell reaches a lit window's texels.
  SceneDesc scene = load_scene(source_path("assets/models/lit-windows.gltf").string());
  const MeshDesc* facade = nullptr;
  for (const MeshDesc& mesh : scene.meshes)
    if (mesh.name == "facade") facade = &mesh;
  REQUIRE(facade);
  REQUIRE(facade->triangle_count() == 256);
  const ImageDesc& texture = scene.images.at(0);
  REQUIRE((texture.width == 64 && texture.height == 32));
  LightTable lights = make_light_table(scene, {0, 0, 0}, "", true, nullptr, LightSampler::power);
  REQUIRE(lights.area_lights.size() == 256);
  int lit_triangles = 0;
  double lit_probability = 0;
  for (size_t slot = 0; slot < 256; ++slot) {
    // The cell of the triangle: its texture coordinates' centre.
    const uint32_t* tri = &facade->indices[3 * lights.area_lights[slot].primitive];
    vec2 centre = (facade->texcoords0[tri[0]] + facade->texcoords0[tri[1]] + facade->texcoords0[tri[2]]) * (1.0f / 3);
    int column = int(centre.x * 16), row = int(centre.y * 8);
    bool lit = texel_value(texture, 4 * column + 1, 4 * row + 1, 0, true) > 0;
    float probability = light_choice_probability(lights, {0, 0, 5}, {0, 1, 0}, slot);
    CAPTURE(slot);
    CHECK((probability > 0) == lit);
    lit_triangles += lit;
    lit_probability += probability;
  }
  CHECK(lit_triangles == 32);  // 16 windows
  CHECK(lit_probability == doctest::Approx(1).epsilon(1e-5));
}

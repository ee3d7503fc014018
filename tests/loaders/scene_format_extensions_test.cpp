// The .scene loader: every extension block, with the exact values it produces.
#include <doctest/doctest.h>

#include <sstream>

#include "loaders/scene_format_test_support.h"
#include "scene_format/scene_format_mesh.h"
#include "scene_format/scene_format_polygons.h"
#include "support/test_support.h"

using namespace radiant;
using doctest::Approx;

static void check_vec3(vec3 actual, vec3 expected) {
  CHECK(actual.x == Approx(expected.x));
  CHECK(actual.y == Approx(expected.y));
  CHECK(actual.z == Approx(expected.z));
}

// ---------------------------------------------------------------- cameras

TEST_CASE("@camera with look-at, fov and resolution") {
  SceneDesc scene = test::load_scene_text("@camera top\nposition 1 2 3\nlook-at 1 2 -7\nfov 35\nresolution 640 480\n");
  REQUIRE(scene.cameras.size() == 1);
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.name == "top");
  check_vec3(camera.position, {1, 2, 3});
  check_vec3(camera.forward, {0, 0, -1});
  check_vec3(camera.up, {0, 1, 0});
  CHECK(camera.vertical_fov_degrees == 35);
  CHECK(camera.aspect == 0);
  CHECK(camera.width == 640);
  CHECK(camera.height == 480);
}

TEST_CASE("@camera makes a given up orthogonal to the direction, and defaults to fov 60") {
  SceneDesc scene = test::load_scene_text("@camera\nposition 0 0 0\ndirection 0 0 -5\nup 0 1 1\n");
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.name.empty());
  check_vec3(camera.forward, {0, 0, -1});
  check_vec3(camera.up, {0, 1, 0});
  CHECK(camera.vertical_fov_degrees == 60);
  CHECK(camera.width == 0);
}

TEST_CASE("@camera view plane: vfov = 2 atan((h/2)/d), aspect = w/h") {
  SceneDesc scene = test::load_scene_text("@camera\nposition 0 0 0\ndirection 1 0 0\nview-distance 2\nview-size 4 3\n");
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.vertical_fov_degrees == Approx(73.739795));
  CHECK(camera.aspect == Approx(4.0 / 3.0));
  check_vec3(camera.forward, {1, 0, 0});
  check_vec3(camera.up, {0, 1, 0});
}

TEST_CASE("@camera orthographic takes the full view height") {
  SceneDesc scene = test::load_scene_text("@camera\nposition 0 5 0\ndirection 0 -1 0\nup 0 0 -1\northographic 8\n");
  const CameraDesc& camera = scene.cameras[0];
  CHECK(camera.projection == Projection::orthographic);
  CHECK(camera.ortho_height == 8);
  check_vec3(camera.up, {0, 0, -1});
}

TEST_CASE("several cameras keep file order") {
  SceneDesc scene =
      test::load_scene_text("@camera a\nposition 0 0 0\ndirection 0 0 -1\n@camera b\nposition 0 0 0\ndirection 0 0 1\n");
  REQUIRE(scene.cameras.size() == 2);
  CHECK(scene.cameras[0].name == "a");
  CHECK(scene.cameras[1].name == "b");
}

// ---------------------------------------------------------------- lights

TEST_CASE("@light ambient: intensity = A / 255") {
  SceneDesc scene = test::load_scene_text("@light ambient\ncolor 51\n");
  REQUIRE(scene.lights.size() == 1);
  CHECK(scene.lights[0].kind == LightKind::ambient);
  check_vec3(scene.lights[0].intensity, {0.2f, 0.2f, 0.2f});
}

TEST_CASE("@light directional: intensity = pi I / 255, unit direction") {
  SceneDesc scene = test::load_scene_text("@light directional\ncolor 255 0 510\ndirection 0 -2 0\n");
  const LightDesc& light = scene.lights[0];
  CHECK(light.kind == LightKind::directional);
  check_vec3(light.intensity, {pi, 0, 2 * pi});
  check_vec3(light.direction, {0, -1, 0});
}

TEST_CASE("@light point: default color 255 and the classic no-attenuation kc = 1, kl = kq = 0") {
  SceneDesc scene = test::load_scene_text("@light point\nposition 1 2 3\n");
  const LightDesc& light = scene.lights[0];
  CHECK(light.kind == LightKind::point);
  check_vec3(light.intensity, {pi, pi, pi});
  check_vec3(light.position, {1, 2, 3});
  CHECK(light.kc == 1);
  CHECK(light.kl == 0);
  CHECK(light.kq == 0);
}

TEST_CASE("@light point with attenuation kc kl kq") {
  SceneDesc scene = test::load_scene_text("@light point\nposition 0 0 0\nattenuation 0.5 0.25 0.125\n");
  CHECK(scene.lights[0].kc == 0.5f);
  CHECK(scene.lights[0].kl == 0.25f);
  CHECK(scene.lights[0].kq == 0.125f);
}

TEST_CASE("@light spot: narrow-beam exponent, no glTF cone") {
  SceneDesc scene =
      test::load_scene_text("@light spot\ncolor 0 255 0\nposition 0 4 0\ndirection 0 -1 0\nexponent 12\n");
  const LightDesc& light = scene.lights[0];
  CHECK(light.kind == LightKind::spot);
  check_vec3(light.intensity, {0, pi, 0});
  check_vec3(light.direction, {0, -1, 0});
  CHECK(light.spot_exponent == 12);
  CHECK_FALSE(light.use_cone);
  CHECK(light.kc == 1);
}

// ---------------------------------------------------------------- materials

static const char* named_material = R"(
@material glass
kd 0.1 0.2 0.3
ks 0.5
ka 0.25
kr 0.4
kt 0.3 0.2 0.1
shininess 64
ior 1.5
emission 255 0 51
)";

TEST_CASE("@material: every attribute, grey or per channel, shared by the shapes naming it") {
  SceneDesc scene = test::load_scene_text(std::string(named_material) +
                                          "@sphere\ncenter 0 0 0\nradius 1\nmaterial glass\n"
                                          "@sphere\ncenter 3 0 0\nradius 1\nmaterial glass\n");
  REQUIRE(scene.materials.size() == 1);
  const MaterialDesc& material = scene.materials[0];
  CHECK(material.name == "glass");
  CHECK(material.model == MaterialModel::phong);
  check_vec3(material.kd, {0.1f, 0.2f, 0.3f});
  check_vec3(material.ks, {0.5f, 0.5f, 0.5f});
  check_vec3(material.ka, {0.25f, 0.25f, 0.25f});
  check_vec3(material.kr, {0.4f, 0.4f, 0.4f});
  check_vec3(material.kt, {0.3f, 0.2f, 0.1f});
  CHECK(material.shininess == 64);
  CHECK(material.ior == 1.5f);
  check_vec3(material.emission, {1, 0, 0.2f});
  CHECK(scene.shapes[0].material == 0);
  CHECK(scene.shapes[1].material == 0);
}

TEST_CASE("inline material attributes make an anonymous material with the .scene defaults") {
  SceneDesc scene = test::load_scene_text("@sphere\ncenter 0 0 0\nradius 1\nkd 0.5\n");
  REQUIRE(scene.materials.size() == 1);
  const MaterialDesc& material = scene.materials[0];
  check_vec3(material.kd, {0.5f, 0.5f, 0.5f});
  check_vec3(material.ka, {1, 1, 1});
  check_vec3(material.ks, {0, 0, 0});
  check_vec3(material.kt, {0, 0, 0});
  CHECK(material.ior == 1);
  CHECK(material.shininess == 1);
  CHECK(material.model == MaterialModel::phong);
}

TEST_CASE("inline attributes override a named material in a copy") {
  SceneDesc scene = test::load_scene_text(std::string(named_material) +
                                          "@sphere\ncenter 0 0 0\nradius 1\nmaterial glass\nkd 0.9\n");
  REQUIRE(scene.materials.size() == 2);
  const MaterialDesc& copy = scene.materials.at(size_t(scene.shapes[0].material));
  CHECK(scene.shapes[0].material == 1);
  check_vec3(copy.kd, {0.9f, 0.9f, 0.9f});
  check_vec3(copy.kt, {0.3f, 0.2f, 0.1f});
  check_vec3(scene.materials[0].kd, {0.1f, 0.2f, 0.3f});
}

TEST_CASE("shapes without material attributes share one default white material") {
  SceneDesc scene = test::load_scene_text("@sphere\ncenter 0 0 0\nradius 1\n@tube\npoint 0 0 0\naxis 0 1 0\nradius 1\n");
  REQUIRE(scene.materials.size() == 1);
  CHECK(scene.shapes[0].material == 0);
  CHECK(scene.shapes[1].material == 0);
  check_vec3(scene.materials[0].kd, {1, 1, 1});
  check_vec3(scene.materials[0].ka, {1, 1, 1});
}

// ---------------------------------------------------------------- analytic shapes

TEST_CASE("@sphere and @plane accept the long attribute names") {
  SceneDesc scene = test::load_scene_text("@sphere\ncenter 1 2 3\nradius 4\n@plane\npoint 0 -1 0\nnormal 0 3 4\n");
  check_vec3(scene.shapes[0].center, {1, 2, 3});
  CHECK(scene.shapes[0].radius == 4);
  CHECK(scene.shapes[1].kind == ShapeKind::plane);
  check_vec3(scene.shapes[1].center, {0, -1, 0});
  check_vec3(scene.shapes[1].axis, {0, 0.6f, 0.8f});
}

TEST_CASE("@cylinder from base, axis, radius and height") {
  SceneDesc scene = test::load_scene_text("@cylinder\nbase 1 0 0\naxis 0 0 2\nradius 0.5\nheight 3\n");
  const ShapeDesc& shape = scene.shapes[0];
  CHECK(shape.kind == ShapeKind::cylinder);
  check_vec3(shape.center, {1, 0, 0});
  check_vec3(shape.axis, {0, 0, 1});
  CHECK(shape.radius == 0.5f);
  CHECK(shape.height == 3);
}

TEST_CASE("@cylinder from two end points") {
  SceneDesc scene = test::load_scene_text("@cylinder\nfrom 1 1 1\nto 1 4 5\nradius 2\n");
  const ShapeDesc& shape = scene.shapes[0];
  check_vec3(shape.center, {1, 1, 1});
  check_vec3(shape.axis, {0, 0.6f, 0.8f});
  CHECK(shape.height == Approx(5));
  CHECK(shape.radius == 2);
}

TEST_CASE("@tube: a point on the axis, unit axis, radius") {
  SceneDesc scene = test::load_scene_text("@tube\npoint 0 1 0\naxis 2 0 0\nradius 0.25\n");
  const ShapeDesc& shape = scene.shapes[0];
  CHECK(shape.kind == ShapeKind::tube);
  check_vec3(shape.center, {0, 1, 0});
  check_vec3(shape.axis, {1, 0, 0});
  CHECK(shape.radius == 0.25f);
}

// ---------------------------------------------------------------- triangles and polygons

TEST_CASE("@triangle becomes a mesh with an identity instance and flat normals") {
  SceneDesc scene = test::load_scene_text("@triangle\nvertices 0 0 0  1 0 0  0 1 0\nkd 0.5\n");
  REQUIRE(scene.meshes.size() == 1);
  const MeshDesc& mesh = scene.meshes[0];
  CHECK(mesh.positions.size() == 3);
  check_vec3(mesh.positions[1], {1, 0, 0});
  CHECK(mesh.indices == std::vector<uint32_t>{0, 1, 2});
  CHECK(mesh.normals.empty());
  CHECK(mesh.material == 0);
  REQUIRE(scene.instances.size() == 1);
  CHECK(scene.instances[0].mesh == 0);
  CHECK(is_identity(scene.instances[0].transform));
}

TEST_CASE("a convex pentagon is fan-triangulated into 3 triangles") {
  SceneDesc scene = test::load_scene_text(
      "@polygon\nvertices 0 0 0  2 0 0  3 1 0  1 3 0  -1 1 0\n");
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.meshes[0].triangle_count() == 3);
  CHECK(scene.meshes[0].indices == std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4});
}

TEST_CASE("faces sharing a material share one mesh, other materials get their own") {
  SceneDesc scene = test::load_scene_text(
      "@material white\nkd 1\n"
      "@triangle\nvertices 0 0 0 1 0 0 0 1 0\nmaterial white\n"
      "@polygon\nvertices 0 0 1 1 0 1 1 1 1 0 1 1\nmaterial white\n"
      "@triangle\nvertices 0 0 2 1 0 2 0 1 2\nkd 0.5\n");
  REQUIRE(scene.meshes.size() == 2);
  CHECK(scene.instances.size() == 2);
  CHECK(scene.meshes[0].positions.size() == 7);
  CHECK(scene.meshes[0].indices == std::vector<uint32_t>{0, 1, 2, 3, 4, 5, 3, 5, 6});
  CHECK(scene.meshes[1].triangle_count() == 1);
  CHECK(scene.meshes[1].material == 1);
}

TEST_CASE("a concave polygon is cut into triangles that leave its notch empty") {
  // An L of area 3: a fan from the first vertex would also cover the notch [1,2]x[1,2].
  SceneDesc scene = test::load_scene_text("@polygon\nvertices 0 0 0  2 0 0  2 1 0  1 1 0  1 2 0  0 2 0\n");
  REQUIRE(scene.meshes.size() == 1);
  const MeshDesc& mesh = scene.meshes[0];
  REQUIRE(mesh.triangle_count() == 4);
  double area = 0;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]], c = mesh.positions[mesh.indices[t + 2]];
    CHECK(cross(b - a, c - a).z > 0);  // the polygon's winding, +z
    area += 0.5 * cross(b - a, c - a).z;
  }
  CHECK(area == doctest::Approx(3));
}

TEST_CASE("polygon_defect accepts planar polygons, convex or not, at any scale and place") {
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}).empty());
  CHECK(scene_format::polygon_defect({{1e4f, 1e4f, 0}, {1e4f + 1, 1e4f, 0}, {1e4f + 1, 1e4f + 1, 0}}).empty());
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {1e-4f, 0, 0}, {1e-4f, 1e-4f, 1e-4f}, {0, 1e-4f, 1e-4f}}).empty());
  // Collinear and repeated vertices along an edge, and a concave notch.
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}}).empty());
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}).empty());
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {2, 0, 0}, {1, 0.5f, 0}, {2, 2, 0}, {0, 2, 0}}).empty());
}

TEST_CASE("polygon_defect rejects non-planar and degenerate polygons") {
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 1, 0}}) ==
        "is not planar (vertex 1 is 0.118 away from the mean plane)");
  CHECK(scene_format::polygon_defect({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}) == "has zero area (its vertices are collinear)");
  CHECK(scene_format::polygon_defect({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}) == "has all its vertices at one point");
}

// ---------------------------------------------------------------- render settings

TEST_CASE("@render fills the settings and the background (0-255)") {
  SceneDesc scene = test::load_scene_text(
      "@render\nmode path\nspp 64\nsampler sobol\nmax-depth 8\nwidth 320\nheight 240\nbackground 255 51 0\n");
  CHECK(scene.settings.mode == RenderMode::path);
  CHECK(scene.settings.spp == 64);
  CHECK(scene.settings.sampler == SamplerKind::sobol);
  CHECK(scene.settings.max_depth == 8);
  CHECK(scene.settings.width == 320);
  CHECK(scene.settings.height == 240);
  check_vec3(scene.environment.color, {1, 0.2f, 0});
}

TEST_CASE("@render mode and sampler names map to their enums, absent settings stay unset") {
  auto mode = [](const std::string& name) { return test::load_scene_text("@render\nmode " + name + "\n").settings.mode; };
  CHECK(mode("auto") == RenderMode::auto_select);
  CHECK(mode("whitted") == RenderMode::whitted);
  CHECK(mode("naive") == RenderMode::naive);
  auto sampler = [](const std::string& name) {
    return test::load_scene_text("@render\nsampler " + name + "\n").settings.sampler;
  };
  CHECK(sampler("grid") == SamplerKind::grid);
  CHECK(sampler("random") == SamplerKind::random);
  CHECK(sampler("jittered") == SamplerKind::jittered);
  SceneDesc scene = test::load_scene_text("@render\nspp 4\n");
  CHECK_FALSE(scene.settings.mode.has_value());
  CHECK_FALSE(scene.settings.width.has_value());
  check_vec3(scene.environment.color, {0, 0, 0});
}

// ---------------------------------------------------------------- meshes

static mat4 transform_of(const std::string& text) {
  std::istringstream in(text);
  MemoryBudget budget(1 << 20);
  scene_format::SceneText parsed = scene_format::read_scene_text(in, "t.scene", budget);
  scene_format::BuildContext context;
  context.display_name = "t.scene";
  return scene_format::mesh_transform(context, parsed.blocks.at(0));
}

TEST_CASE("@mesh transform is translate * rotate * scale") {
  mat4 transform = transform_of("@mesh\nfile a.obj\nscale 2\nrotate 0 0 1 90\ntranslate 1 2 3\n");
  check_vec3(transform_point(transform, {1, 0, 0}), {1, 4, 3});
  check_vec3(transform_point(transform, {0, 0, 1}), {1, 2, 5});
}

TEST_CASE("@mesh matrix is row-major, 12 or 16 numbers") {
  mat4 transform = transform_of("@mesh\nfile a.obj\nmatrix 0 -1 0 5  1 0 0 6  0 0 1 7\n");
  check_vec3(transform_point(transform, {1, 0, 0}), {5, 7, 7});
  mat4 full = transform_of("@mesh\nfile a.obj\nmatrix 2 0 0 1  0 2 0 0  0 0 2 0  0 0 0 1\n");
  check_vec3(transform_point(full, {1, 1, 1}), {3, 2, 2});
}

TEST_CASE("@mesh includes an OBJ file with its transform and a material override") {
  test::ScratchDir dir("scene-mesh");
  dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::istringstream in("@mesh\nfile tri.obj\ntranslate 0 0 -5\nkd 0.5\n");
  SceneDesc scene = load_scene_format(in, "t.scene", dir.path.string(), {});
  REQUIRE(scene.meshes.size() == 1);
  REQUIRE(scene.instances.size() == 1);
  check_vec3(transform_point(scene.instances[0].transform, {0, 0, 0}), {0, 0, -5});
  const MaterialDesc& material = scene.materials.at(size_t(scene.meshes[0].material));
  check_vec3(material.kd, {0.5f, 0.5f, 0.5f});
}

// ---------------------------------------------------------------- docs/scene-format.md

TEST_CASE("the worked example of the units section converts as documented") {
  SceneDesc scene = test::load_scene_text(
      "@light ambient\ncolor 51 51 51\n@light point\ncolor 255 200 100\nposition 0 2 0\nattenuation 1 0 0.25\n"
      "@sphere\ncenter 0 -1 0\nradius 1\nkd 0.8\nemission 100 0 0\n");
  const LightDesc& ambient = scene.lights.at(0);
  const LightDesc& point = scene.lights.at(1);
  const MaterialDesc& material = scene.materials.at(0);
  check_vec3(point.intensity, {3.1415927f, 2.4639943f, 1.2319971f});
  float attenuation = point.kc + point.kl * 2 + point.kq * 4;
  CHECK(attenuation == 2);
  // The Whitted sum at the top of the sphere, as the spec writes it out.
  color3 shown = point.intensity / pi * material.kd / attenuation + material.ka * ambient.intensity + material.emission;
  check_vec3(shown * 255, {253, 131, 91});
}

// OBJ/MTL as exporters write them: Windows paths, missing libraries and textures, concave
// polygons, vertex colors, bump (height) maps, UTF-16 text.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "load_scene.h"
#include "obj/obj_paths.h"
#include "support/load_errors.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// A unit square at z = 0, corners at +-1, with texcoords 0..1 across it.
const char* square_with_texcoords =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";

// Renders `scene` seen straight down -z through an orthographic view `view` wide, lit by a
// directional light travelling along `light_direction`, one sample at each pixel centre.
Film render_from_above(SceneDesc scene, int size, float view, vec3 light_direction) {
  LightDesc light;
  light.kind = LightKind::directional;
  light.direction = normalize(light_direction);
  light.intensity = {1, 1, 1};
  scene.lights.push_back(light);
  scene.cameras.push_back(ortho_camera({0, 0, 5}, {0, 0, -1}, {0, 1, 0}, view));
  RenderOptions o;
  o.width = size, o.height = size, o.spp = 1, o.sampler = SamplerKind::grid, o.mode = RenderMode::whitted;
  return render_scene(scene, o).film;
}

bool has_warning(const SceneDesc& scene, const std::string& warning) {
  return std::find(scene.warnings.begin(), scene.warnings.end(), warning) != scene.warnings.end();
}

}  // namespace

TEST_CASE("obj paths: tinyobjloader's mtllib names map back to what the file wrote") {
  std::istringstream obj("mtllib sub\\m.mtl other.mtl\n  mtllib my\\ file.mtl\nmtllibx no.mtl\n");
  std::map<std::string, std::string> names = mtllib_names(obj);
  CHECK(names == std::map<std::string, std::string>{
                     {"subm.mtl", "sub/m.mtl"}, {"other.mtl", "other.mtl"}, {"my file.mtl", "my file.mtl"}});
  CHECK(portable_path(".\\textures\\wall.jpg") == "./textures/wall.jpg");
}

TEST_CASE("obj: backslashes in mtllib and map_Kd names are folder separators (assimp's spider.obj)") {
  ScratchDir dir("obj-windows-paths");
  std::filesystem::create_directories(dir.file("materials"));
  std::filesystem::create_directories(dir.file("textures"));
  dir.write("materials/m.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd .\\textures\\wall.png\n");
  write_texel_bytes(dir.file("textures/wall.png"), 2, 1, 1, {50, 150});
  std::string obj = std::string("mtllib materials\\m.mtl\n") + square_with_texcoords + "usemtl skin\nf 1/1 2/2 3/3 4/4\n";
  SceneDesc scene = load_scene(dir.write("spider.obj", obj).string());
  REQUIRE(scene.materials.size() == 1);
  CHECK(scene.materials[0].base_color_texture.valid());
  REQUIRE(scene.images.size() == 1);
  CHECK(scene.images[0].texels8 == std::vector<uint8_t>{50, 150});
  CHECK(scene.warnings.empty());  // the texture was found (no light is render's warning, not the loader's)
}

TEST_CASE("obj: a missing MTL is a warning and its faces get the default material (cube_mtllib_after_g.obj)") {
  ScratchDir dir("obj-missing-mtl");
  std::string path = dir.write("cube.obj", "g Object\nmtllib cube.mat\nusemtl MyMaterial\n"
                                           "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string();
  SceneDesc scene = load_scene(path);
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.materials.at(size_t(scene.meshes[0].material)).kd.x == doctest::Approx(0.8));  // the default
  CHECK(has_warning(scene, path + ": mtllib 'cube.mat': no such file; its materials are replaced by the default material"));
  // The OBJ itself is still required, and an MTL that is there but unreadable is still an error.
  CHECK(load_error(dir, dir.file("none.obj")) == "none.obj: no such file");
  std::filesystem::create_directory(dir.file("folder.mtl"));
  dir.write("folder.obj", "mtllib folder.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CHECK(load_error(dir, dir.file("folder.obj")) == "folder.obj: mtllib 'folder.mtl': is a directory");
}

TEST_CASE("obj: a missing texture is a warning and the material renders untextured") {
  ScratchDir dir("obj-missing-texture");
  dir.write("m.mtl", "newmtl skin\nKd 0.5 0.25 1\nmap_Kd .\\wal67ar_small.jpg\n");
  std::string path =
      dir.write("a.obj", std::string("mtllib m.mtl\n") + square_with_texcoords + "usemtl skin\nf 1/1 2/2 3/3 4/4\n").string();
  SceneDesc scene = load_scene(path);
  REQUIRE(scene.materials.size() == 1);
  CHECK_FALSE(scene.materials[0].base_color_texture.valid());
  CHECK(scene.materials[0].kd.y == doctest::Approx(0.25));
  CHECK(scene.images.empty());
  CHECK(has_warning(scene, path + ": material 'skin' map_Kd './wal67ar_small.jpg': no such file; "
                           "the material is rendered without it"));
  CommandResult r = run_radiant("render " + path + " -o " + dir.file("a.png").string() + " --width 8 --height 8 --env-color 1,1,1");
  CHECK(r.exit_code == 0);
  CHECK(r.err.find("wal67ar_small.jpg': no such file") != std::string::npos);
}

TEST_CASE("obj: a concave polygon covers exactly its area (an annulus with a bridge edge, concave_polygon.obj)") {
  ScratchDir dir("obj-concave");
  // Square [-2,2]^2 with the hole [-1,1]^2, one face: area 12. A fan would also fill the hole.
  std::string obj =
      "v -2 -2 0\nv 2 -2 0\nv 2 2 0\nv -2 2 0\nv -1 -1 0\nv -1 1 0\nv 1 1 0\nv 1 -1 0\n"
      "f 1 2 3 4 1 5 6 7 8 5\n";
  SceneDesc scene = load_scene(dir.write("annulus.obj", obj).string());
  // 32 pixels across 8 units: 16 pixels per unit of area, centres half a pixel from every edge.
  Film film = render_from_above(scene, 32, 8, {0, 0, -1});
  int covered = 0;
  for (const FilmPixel& pixel : film.pixels) covered += pixel_mean(pixel).x > 0;
  CHECK(covered == 12 * 16);
  CHECK(pixel_mean(film.at(16, 16)).x == 0);  // the hole's centre
}

TEST_CASE("obj: a polygon that crosses itself is still cut, with one warning naming the first") {
  ScratchDir dir("obj-crossing");
  std::string path = dir.write("bow.obj", "v 0 0 0\nv 3 3 0\nv 3 0 0\nv 0 1 0\nf 1 2 3 4\nf 1 2 3 4\n").string();
  SceneDesc scene = load_scene(path);
  CHECK(has_warning(scene, path + ":5:3: 2 polygons cross themselves (this one first); their triangles may overlap"));
  CHECK(scene.meshes.at(0).triangle_count() > 0);
}

TEST_CASE("obj: vertex colors (v x y z r g b) tint the diffuse color like glTF's COLOR_0") {
  ScratchDir dir("obj-vertex-colors");
  std::string obj = "v -1 -1 0 1 0 0\nv 1 -1 0 1 0 0\nv 1 1 0 0 0 1\nv -1 1 0 0 0 1\nf 1 2 3 4\n";
  SceneDesc scene = load_scene(dir.write("colors.obj", obj).string());
  REQUIRE(scene.meshes.size() == 1);
  const MeshDesc& mesh = scene.meshes[0];
  REQUIRE(mesh.colors.size() == mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    vec4 expected = mesh.positions[i].y < 0 ? vec4{1, 0, 0, 1} : vec4{0, 0, 1, 1};
    CHECK(mesh.colors[i].x == expected.x);
    CHECK(mesh.colors[i].z == expected.z);
    CHECK(mesh.colors[i].w == 1);
  }
  Film film = render_from_above(scene, 16, 2, {0, 0, -1});
  color3 bottom = pixel_mean(film.at(8, 15)), top = pixel_mean(film.at(8, 0));
  CHECK(bottom.x > 0);
  CHECK(bottom.y == 0);
  CHECK(bottom.z < 0.05f * bottom.x);  // 1/32 of the way to the blue edge
  CHECK(top.z > 0);
  CHECK(top.x < 0.05f * top.z);
  // Only some vertices colored: tinyobjloader drops them all, and so nothing is tinted.
  SceneDesc partial = load_scene(dir.write("partial.obj", "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string());
  CHECK(partial.meshes.at(0).colors.empty());
}

TEST_CASE("obj: a bump map tilts the shading normal by the height map's slope times -bm") {
  ScratchDir dir("obj-bump");
  // Heights rise by 32/255 per texel along u over 8 texels: dh/du = 32/255 * 8 per unit of u, and
  // u runs over 2 units of x. The slope seen in x is -bm times half of that.
  write_texel_bytes(dir.file("ramp.png"), 8, 1, 1, {0, 32, 64, 96, 128, 160, 192, 224});
  const float bump_multiplier = 1.5f;
  dir.write("bumpy.mtl", "newmtl m\nKd 1 1 1\nbump -bm 1.5 ramp.png\n");
  dir.write("flat.mtl", "newmtl m\nKd 1 1 1\n");
  std::string faces = std::string(square_with_texcoords) + "usemtl m\nf 1/1 2/2 3/3 4/4\n";
  SceneDesc bumpy = load_scene(dir.write("bumpy.obj", "mtllib bumpy.mtl\n" + faces).string());
  SceneDesc flat = load_scene(dir.write("flat.obj", "mtllib flat.mtl\n" + faces).string());
  REQUIRE(bumpy.materials.at(0).bump_texture.valid());
  CHECK_FALSE(bumpy.materials.at(0).normal_texture.valid());
  CHECK(bumpy.materials.at(0).bump_scale == bump_multiplier);
  float slope = bump_multiplier * (32.0f / 255.0f) * 8 / 2;  // dh/dx
  vec3 bumped_normal = normalize(vec3{-slope, 0, 1});
  // Light from -x and from +x, 45 degrees up: the bumped face turns towards the first.
  for (float side : {-1.0f, 1.0f}) {
    vec3 to_light = normalize(vec3{side, 0, 1});
    Film with_bump = render_from_above(bumpy, 20, 2.5f, -to_light);
    Film without = render_from_above(flat, 20, 2.5f, -to_light);
    float expected_ratio = dot(bumped_normal, to_light) / to_light.z;
    CAPTURE(side);
    int checked = 0;
    // Pixels whose central differences stay inside the ramp (x within +-0.6, away from the wrap).
    for (int y = 3; y < 17; ++y)
      for (int x = 6; x < 14; ++x) {
        float ratio = pixel_mean(with_bump.at(x, y)).x / pixel_mean(without.at(x, y)).x;
        CHECK(ratio == doctest::Approx(expected_ratio).epsilon(0.01));
        ++checked;
      }
    CHECK(checked == 112);
  }
}

TEST_CASE("obj: a UTF-16 file is refused with what it is and how to convert it") {
  ScratchDir dir("obj-utf16");
  auto utf16 = [](const std::string& text, bool little_endian, bool mark) {
    std::string bytes = mark ? (little_endian ? "\xFF\xFE" : "\xFE\xFF") : "";
    for (char c : text) bytes += little_endian ? std::string{c, '\0'} : std::string{'\0', c};
    return bytes;
  };
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::string advice = ": the file is UTF-16 little-endian text; radiant reads OBJ files as ASCII or UTF-8 "
                             "(convert it, e.g. iconv -f UTF-16 -t UTF-8)";
  CHECK(load_error(dir, dir.write("le.obj", utf16(triangle, true, true))) == "le.obj" + advice);
  CHECK(load_error(dir, dir.write("plain-le.obj", utf16(triangle, true, false))) == "plain-le.obj" + advice);
  CHECK(load_error(dir, dir.write("be.obj", utf16(triangle, false, true))).find("UTF-16 big-endian") !=
        std::string::npos);
  CHECK(load_error(dir, dir.write("utf8.obj", triangle)) == "no error");
}

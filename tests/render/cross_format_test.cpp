// The same content written as .scene, OBJ and glTF renders the same; glTF lights and materials
// follow DESIGN.md's units in both integrators.
#include <doctest/doctest.h>

#include <cmath>

#include "loaders/gltf_builder.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


const char* same_camera = " --look-from 0,0,3 --look-at 0,0,0 --up 0,1,0 --fov 40 --width 32 --height 32 --quiet";

// A triangle facing +z with a matte material of reflectance 0.8 (specularFactor 0: exactly Lambertian).
std::string triangle_gltf(const std::string& extra_nodes_and_extensions) {
  GltfBuilder b;
  b.floats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3", 3);
  b.indices({0, 1, 2});
  return b.gltf(
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.8,0.8,0.8,1],\"metallicFactor\":0,"
      "\"roughnessFactor\":1},\"doubleSided\":true,\"extensions\":{\"KHR_materials_specular\":{\"specularFactor\":0}}}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}],"
      "\"scenes\":[{\"nodes\":[0" + std::string(extra_nodes_and_extensions == "]" ? "" : ",1") + "]}],\"scene\":0," +
      "\"nodes\":[{\"mesh\":0}" + extra_nodes_and_extensions);
}

}  // namespace

TEST_CASE("cross-format: one lit triangle from .scene and glTF gives the same Whitted image") {
  ScratchDir dir("cross-whitted");
  // glTF point light of 5 W/sr; in .scene units that is color 5 * 255 / pi with 1/d^2.
  fs::path gltf = dir.write("t.gltf", triangle_gltf(
      ",{\"translation\":[0.3,0.2,2],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}],"
      "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
      "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\",\"intensity\":5}]}}"));
  fs::path scene = dir.write("t.scene",
                             "@light point\ncolor " + std::to_string(5 * 255 / M_PI) + "\nposition 0.3 0.2 2\n"
                             "attenuation 0 0 1\n@triangle\nvertices -1 -1 0  1 -1 0  0 1 0\nkd 0.8\n");
  for (const fs::path& input : {gltf, scene})
    REQUIRE(run_radiant("render " + quoted(input) + " -o " + quoted(dir.file(input.stem().string() + input.extension().string().substr(1) + ".exr")) +
                        " --mode whitted --spp 1" + same_camera).exit_code == 0);
  TestImage a = read_image(dir.file("tgltf.exr")), b = read_image(dir.file("tscene.exr"));
  int lit = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      lit += a.at(x, y, 0) > 0;
      CHECK(a.at(x, y, 0) == doctest::Approx(b.at(x, y, 0)).epsilon(1e-5));
    }
  CHECK(lit > 100);
}

TEST_CASE("cross-format: one triangle from .scene, OBJ and glTF under a uniform sky gives the same path-traced image") {
  ScratchDir dir("cross-path");
  fs::path gltf = dir.write("t.gltf", triangle_gltf("]"));
  fs::path obj = dir.write("t.obj", "mtllib t.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nusemtl matte\nf 1 2 3\n");
  dir.write("t.mtl", "newmtl matte\nKd 0.8 0.8 0.8\nKs 0 0 0\nillum 1\n");
  fs::path scene = dir.write("t.scene", "@triangle\nvertices -1 -1 0  1 -1 0  0 1 0\nkd 0.8\n");
  std::string flags = " --mode path --spp 256 --env-color 1,1,1" + std::string(same_camera);
  for (const fs::path& input : {gltf, obj, scene}) {
    CommandResult r = run_radiant("render " + quoted(input) + " -o " + quoted(dir.file(input.extension().string().substr(1) + ".exr")) + flags);
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
  }
  TestImage g = read_image(dir.file("gltf.exr")), o = read_image(dir.file("obj.exr")), s = read_image(dir.file("scene.exr"));
  // .scene and OBJ both load a Phong material with kd 0.8: the same samples give the same bits.
  CHECK(same_pixels(dir.file("obj.exr"), dir.file("scene.exr")));
  // glTF's dielectric without its specular layer is the same Lambertian surface: equal within
  // Monte Carlo error (the triangle seen under a white sky shows 0.8 everywhere).
  double sum_g = 0, sum_s = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) sum_g += g.at(x, y, 0), sum_s += s.at(x, y, 0);
  CHECK(sum_g == doctest::Approx(sum_s).epsilon(0.01));
  CHECK(o.at(16, 16, 0) == doctest::Approx(0.8).epsilon(0.02));
}

TEST_CASE("cross-format: a glTF Lambertian plane under a point light shows rho/pi * I * cos / d^2 in both modes") {
  ScratchDir dir("gltf-analytic");
  GltfBuilder b;
  b.floats({-4, 0, -4, -4, 0, 4, 4, 0, 4, 4, 0, -4}, "VEC3", 3);  // y = 0, facing +y
  b.indices({0, 1, 2, 0, 2, 3});
  // Orthographic camera 5 above, looking down (-z of the node rotated -90 degrees about x),
  // view 4 units tall; a point light of 7 W/sr at (0.5, 1.5, -0.25).
  fs::path file = dir.write("plane.gltf", b.gltf(
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.6,0.5,0.4,1],\"metallicFactor\":0,\"roughnessFactor\":1},"
      "\"extensions\":{\"KHR_materials_specular\":{\"specularFactor\":0}}}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0}]}],"
      "\"cameras\":[{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":2,\"ymag\":2,\"znear\":0.1,\"zfar\":10}}],"
      "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
      "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\",\"intensity\":7}]}},"
      "\"scenes\":[{\"nodes\":[0,1,2]}],\"scene\":0,"
      "\"nodes\":[{\"mesh\":0},{\"camera\":0,\"translation\":[0,5,0],\"rotation\":[-0.70710678,0,0,0.70710678]},"
      "{\"translation\":[0.5,1.5,-0.25],\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}]"));
  for (std::string mode : {"whitted", "path"}) {
    fs::path out = dir.file(mode + ".exr");
    REQUIRE(run_radiant("render " + quoted(file) + " -o " + quoted(out) + " --mode " + mode +
                        " --spp 1 --sampler jittered --width 8 --height 8 --quiet").exit_code == 0);
    TestImage img = read_image(out);
    for (auto [x, y] : {std::pair{0, 0}, {3, 4}, {6, 1}, {7, 7}}) {
      // Looking down -y with up -z: image x runs along +x, image y along +z.
      float px = -2 + 0.5f * (x + 0.5f), pz = -2 + 0.5f * (y + 0.5f);
      float dx = 0.5f - px, dy = 1.5f, dz = -0.25f - pz;
      float d2 = dx * dx + dy * dy + dz * dz;
      float cos_theta = dy / std::sqrt(d2);
      CAPTURE(mode);
      CHECK(img.at(x, y, 0) == doctest::Approx(0.6 / M_PI * 7 * cos_theta / d2).epsilon(1e-4));
      CHECK(img.at(x, y, 2) == doctest::Approx(0.4 / M_PI * 7 * cos_theta / d2).epsilon(1e-4));
    }
  }
}

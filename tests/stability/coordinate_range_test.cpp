// The supported coordinate range (scene/coordinate_range.h): scenes and flags beyond it are
// refused with one line naming the place, and no ray handed to Embree is ever invalid, whatever
// the scene. Every hostile case here aborted inside Embree (`ray.valid()`) before the range
// existed; far-away views also keep batch renders' pixels identical to separate renders.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "accel/scene_accel.h"
#include "stability/film_checks.h"
#include "support/scene_builders.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


// A lit sphere on a plane; `camera`, `plane_point` and `extra` are spliced into the text.
std::string scene_text(const std::string& camera, const std::string& plane_point, const std::string& extra = "") {
  return "@camera\n" + camera +
         "\n@light point\ncolor 255 255 255\nposition 0 5 0\n"
         "@sphere\ncenter 0 1 0\nradius 1\nkd 0.5\n" +
         extra + "@plane\npoint " + plane_point + "\nnormal 0 1 0\nkd 0.5\n";
}
const std::string near_camera = "position 0 2 8\ndirection 0 -0.2 -1";

struct Refusal {
  const char* name;
  std::string text;
  std::string flags;
  int exit_code;
  const char* message;  // a part of the one-line error
};

}  // namespace

TEST_CASE("coordinate range: scenes and flags beyond it are refused with the place named, never an abort") {
  const Refusal cases[] = {
      {"camera at 2e18", scene_text("position 2e18 2 8\ndirection 0 -0.2 -1", "0 0 0"), "", 1, "cameras[0].position: 2e+18"},
      {"plane at z = -1e19", scene_text(near_camera, "0 0 -1e19"), "", 1, "shapes[1].center: -1e+19"},
      {"orthographic height 1e38", scene_text("position 0 2 8\ndirection 0 -0.2 -1\northographic 1e38", "0 0 0"), "", 1,
       "cameras[0].orthographic_height"},
      {"glass of ior 1e30", scene_text(near_camera, "0 0 0", "@sphere\ncenter 2 1 0\nradius 1\nkt 1\nior 1e30\n"), "", 1,
       ".ior: 1e+30 is out of range"},
      {"--look-from 1.9e18", scene_text(near_camera, "0 0 0"), " --look-from 1.9e18,0,0", 2, "--look-from lies beyond"},
  };
  ScratchDir dir("coordinate-range");
  for (const Refusal& c : cases) {
    CAPTURE(std::string(c.name));
    fs::path scene = dir.write("hostile.scene", c.text), out = dir.file("out.png");
    for (std::string command : {"render", "converge"}) {
      std::string output = command == "render" ? " -o " + quoted(out) + " --spp 1" : " --out " + quoted(dir.file("report"));
      CommandResult r = run_radiant(command + " " + quoted(scene) + output + " --width 8 --height 8" + c.flags);
      CHECK(r.exit_code == c.exit_code);
      CHECK(r.err.find(c.message) != std::string::npos);
      CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      CHECK(!fs::exists(out));
    }
  }
}

TEST_CASE("coordinate range: an instance whose float inverse fails is refused at load, never an abort") {
  // Found by the render fuzzer: Embree inverted the transform in float, got infinities and
  // aborted on `ray.valid()` for the first ray that reached the instance.
  ScratchDir dir("coordinate-range-inverse");
  dir.write("tri.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
  fs::path scene = dir.write("sheared.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\n"
                                              "@light point\nposition 0 0 5\ncolor 255 255 255\n"
                                              "@mesh\nfile tri.obj\nmatrix 1.00000012 1 0 0 1 0.99999994 0 0 0 0 1 0\n");
  fs::path out = dir.file("out.png");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out) + " --width 8 --height 8 --spp 1");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: " + scene.string() +
                     ":9:1: 'matrix' is too close to singular to invert in single precision, as ray tracing must\n");
  CHECK(!fs::exists(out));
}

TEST_CASE("coordinate range: a plane 1e15 below a camera looking at the horizon renders, cut off before Embree's limit") {
  SceneDesc scene;
  int m = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  add_plane(scene, {0, -1e15f, 0}, {0, 1, 0}, m);
  add_sphere(scene, {0, 0, -10}, 1, m);
  scene.lights.push_back(point_light({0, 1e14f, 0}, {1e28f, 1e28f, 1e28f}));
  scene.cameras.push_back(perspective_camera({0, 0, 0}, {0, -0.001f, -1}, {0, 1, 0}, 60));
  for (RenderMode mode : {RenderMode::whitted, RenderMode::path}) {
    RenderOptions options = whitted_options(16);
    options.mode = mode;
    RenderResult r = render_finite(scene, options);
    CHECK(r.stats.untraceable_rays == 0);
  }
}

TEST_CASE("coordinate range: a ray Embree could not trace is a miss and a blocked shadow ray, and is counted") {
  SceneDesc scene;
  add_sphere(scene, {0, 0, 0}, 1, add_diffuse(scene, {0.5f, 0.5f, 0.5f}));
  auto accel = build_scene_accel(scene);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const Ray hostile[] = {
      {{0, 0, 2e18f}, {0, 0, -1}},   // origin beyond Embree's 1.8e18
      {{0, 0, 5}, {0, nan, -1}},     // NaN direction (a NaN in a later component, which std::max drops)
      {{nan, 0, 5}, {0, 0, -1}},     // NaN origin
      {{0, 0, 5}, {0, 0, -inf}},     // infinite direction
      {{0, 0, 5}, {0, 0, -1}, nan},  // NaN tmax
      {{0, 0, 5}, {0, 0, -4e17f}},   // Embree would take it, but not beyond twice the traceable range
  };
  for (const Ray& ray : hostile) {
    CHECK(!intersect_nearest(*accel, ray).valid());
    CHECK(is_occluded(*accel, ray));
  }
  CHECK(accel->untraceable_rays.load() == 2 * std::size(hostile));
  // The same ray, traceable, hits.
  CHECK(intersect_nearest(*accel, Ray{{0, 0, 5}, {0, 0, -1}}).valid());
  CHECK(accel->untraceable_rays.load() == 2 * std::size(hostile));
}

TEST_CASE("coordinate range: an instance that shrinks space too much for the scene's extent is refused by name") {
  SceneDesc scene;
  int m = add_diffuse(scene, {0.5f, 0.5f, 0.5f});
  add_quad(scene, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, m);
  scene.instances.push_back(scene.instances[0]);  // placed twice: traced in its object space
  scene.instances[1].transform = translation({1e12f, 0, 0}) * scaling({1e-9f, 1e-9f, 1e-9f});
  scene.instances[1].name = "speck";
  scene.source_path = "tiny.gltf";
  CHECK_THROWS_WITH_AS(build_scene_accel(scene), doctest::Contains("tiny.gltf: instances[1] 'speck': its transform shrinks space by 1e-09"),
                       std::runtime_error);
  // The same speck near the camera fits: its object space stays in range.
  scene.instances[1].transform = translation({3, 0, 0}) * scaling({1e-9f, 1e-9f, 1e-9f});
  auto accel = build_scene_accel(scene);
  // 1e17 / (2 * 1e9): the range shrinks with the instance, the scene still fits.
  CHECK(accel->max_ray_coordinate == doctest::Approx(5e7).epsilon(1e-3));
}

TEST_CASE("render space: a far view in a batch leaves the other views' pixels identical to separate renders") {
  ScratchDir dir("render-space-batch");
  // Integer coordinates 1e7 away: a second view 2000 units off moves the render origin.
  std::string text = "@camera\nposition 10000000 10000002 10000008\ndirection 0 -0.2 -1\n"
                     "@light point\ncolor 255 255 255\nposition 10000000 10000005 10000000\n"
                     "@sphere\ncenter 10000000 10000001 10000000\nradius 1\nkd 0.5\n"
                     "@plane\npoint 10000000 10000000 10000000\nnormal 0 1 0\nkd 0.5\n";
  fs::path scene = dir.write("far.scene", text);
  const std::string common = " --width 16 --height 16 --spp 2 --mode path --quiet";
  const std::string far_view = " --look-from 10002000,10000100,10002000 --look-at 10000000,10000001,10000000";
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("alone.png")) + common).exit_code == 0);
  REQUIRE(run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("far-alone.png")) + common + far_view).exit_code == 0);
  fs::path script = dir.write("views.txt", "scene far.scene\nrender -o a.png" + common + "\nrender -o far.png" + common +
                                               far_view + "\nrender -o a-again.png" + common + "\n");
  CommandResult r = run_radiant("batch " + quoted(script));
  REQUIRE(r.exit_code == 0);
  CHECK(same_pixels(dir.file("a.png"), dir.file("alone.png")));
  CHECK(same_pixels(dir.file("a-again.png"), dir.file("alone.png")));
  CHECK(same_pixels(dir.file("far.png"), dir.file("far-alone.png")));
  // And the image at 1e7 is the image of the same scene at the origin.
  std::string at_origin = "@camera\nposition 0 2 8\ndirection 0 -0.2 -1\n"
                          "@light point\ncolor 255 255 255\nposition 0 5 0\n"
                          "@sphere\ncenter 0 1 0\nradius 1\nkd 0.5\n@plane\npoint 0 0 0\nnormal 0 1 0\nkd 0.5\n";
  fs::path origin_scene = dir.write("origin.scene", at_origin);
  REQUIRE(run_radiant("render " + quoted(origin_scene) + " -o " + quoted(dir.file("origin.png")) + common).exit_code == 0);
  CHECK(same_pixels(dir.file("origin.png"), dir.file("alone.png")));
}

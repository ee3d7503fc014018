// --light-sampler and what --stats says was chosen: the BVH for the bundled many-lights scene,
// power sampling for a scene with one light, either when asked.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


// The light sampler the --stats file of a small render of `scene` with `flags` reports.
std::string chosen_light_sampler(const std::string& scene, const std::string& flags) {
  ScratchDir dir("cli-light-sampler");
  fs::path stats = dir.file("stats.json");
  CommandResult r = run_radiant("render " + quoted(source_path(scene)) + " -o " + quoted(dir.file("out.png")) +
                                " --width 16 --height 12 --spp 1 --mode path --quiet --stats " + quoted(stats) + " " +
                                flags);
  REQUIRE(r.exit_code == 0);
  std::string json = read_bytes(stats);
  size_t at = json.find("\"light_sampler\": \"");
  REQUIRE(at != std::string::npos);
  at += std::string("\"light_sampler\": \"").size();
  return json.substr(at, json.find('"', at) - at);
}

}  // namespace

TEST_CASE("render cli: --light-sampler auto picks the BVH for 400 lights and power sampling for one") {
  CHECK(chosen_light_sampler("assets/many-lights.scene", "") == "bvh");
  CHECK(chosen_light_sampler("assets/first-render.scene", "") == "power");
  CHECK(chosen_light_sampler("assets/many-lights.scene", "--light-sampler power") == "power");
  CHECK(chosen_light_sampler("assets/first-render.scene", "--light-sampler bvh") == "bvh");
}

TEST_CASE("render cli: an unknown --light-sampler is a usage error naming the choices") {
  ScratchDir dir("cli-light-sampler-bad");
  fs::path out = dir.file("out.png");
  CommandResult r = run_radiant("render " + quoted(source_path("assets/first-render.scene")) + " -o " + quoted(out) +
                                " --light-sampler tree");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("unknown light sampler 'tree' (expected auto, power or bvh)") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

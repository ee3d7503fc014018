// `radiant batch`: `scene PATH --scene N --variant NAME` loads that glTF scene and material
// variant, as `render` does with the same flags; a `render` line, which renders a scene already
// loaded, refuses them naming its line instead of ignoring them.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "loaders/gltf_builder.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// One quad, white by default and red in the variant "red"; scene 1 adds a second quad beside it.
std::string variants_gltf() {
  GltfBuilder b = quad_builder();
  return b.gltf(
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,1]}},"
      "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]}}],"
      "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":0,"
      "\"extensions\":{\"KHR_materials_variants\":{\"mappings\":[{\"material\":1,\"variants\":[0]}]}}}]}],"
      "\"nodes\":[{\"mesh\":0},{\"mesh\":0,\"translation\":[1.5,0,0]}],"
      "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[0,1]}],\"scene\":0,"
      "\"extensionsUsed\":[\"KHR_materials_variants\"],"
      "\"extensions\":{\"KHR_materials_variants\":{\"variants\":[{\"name\":\"red\"}]}}");
}

const std::string view_flags = " --width 16 --height 12 --spp 1 --env-color 1,1,1 --quiet";

}  // namespace

TEST_CASE("batch: a scene line's --scene and --variant load what render's do, pixel for pixel") {
  ScratchDir dir("batch-scene-line");
  fs::path scene = dir.write("v.gltf", variants_gltf());
  fs::path script = dir.write("views.txt", "scene v.gltf --variant red\nrender -o batch-red.png" + view_flags +
                                               "\nscene v.gltf --scene 1\nrender -o batch-scene1.png" + view_flags +
                                               "\nscene v.gltf\nrender -o batch-plain.png" + view_flags + "\n");
  CommandResult batch = run_radiant("batch " + quoted(script));
  INFO(batch.err);
  REQUIRE(batch.exit_code == 0);
  for (const char* flags : {"--variant red", "--scene 1"}) {
    CAPTURE(flags);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("render.png")) + " " + flags + view_flags);
    REQUIRE(r.exit_code == 0);
    std::string batch_file = std::string(flags) == "--variant red" ? "batch-red.png" : "batch-scene1.png";
    CHECK(same_pixels(dir.file(batch_file), dir.file("render.png")));
    CHECK(!same_pixels(dir.file(batch_file), dir.file("batch-plain.png")));
  }
}

TEST_CASE("batch: --scene or --variant on a render line is refused naming the line, and nothing renders") {
  ScratchDir dir("batch-render-line-load-flags");
  dir.write("v.gltf", variants_gltf());
  for (const char* flag : {"--variant red", "--scene 1"}) {
    CAPTURE(flag);
    fs::path script = dir.write("views.txt", "scene v.gltf\nrender -o a.png" + view_flags + "\nrender -o b.png " + flag +
                                                 view_flags + "\n");
    CommandResult r = run_radiant("batch " + quoted(script));
    CHECK(r.exit_code == 1);
    std::string name = std::string(flag).substr(0, std::string(flag).find(' '));
    CHECK(dir.without_path(r.err) == "radiant batch: views.txt:3: " + name +
                                         " chooses what is loaded, not a view of it: give it where the scene is "
                                         "loaded (in a batch script, on the 'scene' line: scene PATH " + name + " ...)\n");
    CHECK_FALSE(fs::exists(dir.file("a.png")));
  }
}

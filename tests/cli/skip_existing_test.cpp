// `render --skip-existing`: a shard already complete at -o with this command line, scene and files
// exits 0 before the scene is loaded; a changed scene file, a changed file it reads or a changed
// flag renders again; a command line spelled differently that makes the same shard still skips,
// after loading.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

const std::string skipped_line = "radiant: shard.exr already holds this shard, complete; skipped\n";

// A copy of the textured cube (a .gltf that reads a .bin and a .png) that the test may change.
struct CubeFolder {
  ScratchDir dir{"skip-existing"};
  fs::path scene = dir.file("checker-cube.gltf"), shard = dir.file("shard.exr");
  CubeFolder() {
    for (const char* name : {"checker-cube.gltf", "checker-cube.bin", "checker.png"})
      fs::copy_file(source_path(std::string("assets/models/") + name), dir.file(name));
  }
  // `render` of shard 1/2 of the cube with `flags` after the common ones.
  CommandResult render(const std::string& flags) const {
    return run_radiant("render " + quoted(scene) + " -o " + quoted(shard) +
                       " --width 8 --height 8 --spp 2 --env-color 1,1,1 --shard 1/2 " + flags);
  }
};

// Renders a shard that must be written (not skipped).
void render_written(const CubeFolder& cube, const std::string& flags) {
  CommandResult r = cube.render(flags);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("skipped") == std::string::npos);
}

// A --max-memory (42 KiB) below what loading the cube charges (95 KiB for its JSON alone), above
// what reading the shard's header does (OpenEXR's buffers and the pixels' copy, about 10 KiB).
const char* too_little_memory = " --max-memory 0.00004";

}  // namespace

TEST_CASE("skip existing: a complete matching shard exits 0 without loading the scene, even one loading would refuse") {
  CubeFolder cube;
  render_written(cube, "--quiet");
  auto written = fs::last_write_time(cube.shard);
  std::string bytes = read_bytes(cube.shard);
  // Flags in another order and spelling, and flags that cannot change a shard, still match.
  CommandResult skipped = run_radiant("render --shard=1/2 --spp=2 " + quoted(cube.scene) + " --env-color=1,1,1 -o " +
                                      quoted(cube.shard) + " --height 8 --width 8 --threads 1 --skip-existing" +
                                      too_little_memory);
  CHECK(skipped.exit_code == 0);
  CHECK(cube.dir.without_path(skipped.err) == skipped_line);
  CHECK(fs::last_write_time(cube.shard) == written);
  CHECK(read_bytes(cube.shard) == bytes);
  // The same memory cap without a shard to skip: loading is refused, so the skip loaded nothing.
  CommandResult loaded = cube.render("--seed 3 --skip-existing" + std::string(too_little_memory));
  CHECK(loaded.exit_code == 1);
  CHECK(loaded.err.find("over the memory limit") != std::string::npos);
  CHECK(read_bytes(cube.shard) == bytes);
}

TEST_CASE("skip existing: a changed scene file, a changed file the scene reads or a changed flag renders again") {
  CubeFolder cube;
  render_written(cube, "--quiet");
  std::string first = read_bytes(cube.shard);

  SUBCASE("the scene file") {
    std::ofstream(cube.scene, std::ios::app) << "\n";  // the same scene, other bytes
  }
  SUBCASE("its texture") {
    write_texel_bytes(cube.dir.file("checker.png"), 2, 2, 3, {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255});
  }
  SUBCASE("its buffer") {
    std::string buffer = read_bytes(cube.dir.file("checker-cube.bin"));
    buffer[576] ^= 1;  // the last bit of the first texture coordinate
    std::ofstream(cube.dir.file("checker-cube.bin"), std::ios::binary) << buffer;
  }
  std::string flags = "--skip-existing";
  SUBCASE("a flag") { flags += " --seed 5"; }
  render_written(cube, flags + " --quiet");
  CHECK(read_bytes(cube.shard) != first);
}

TEST_CASE("skip existing: a command line that differs but makes the same shard skips after loading") {
  CubeFolder cube;
  render_written(cube, "--quiet");
  auto written = fs::last_write_time(cube.shard);
  // --seed 0 is the default: another command line, the same shard. Known only once loaded, so the
  // memory cap that refuses loading now fails the run instead of skipping it.
  CommandResult refused = cube.render("--seed 0 --skip-existing" + std::string(too_little_memory));
  CHECK(refused.exit_code == 1);
  CommandResult skipped = cube.render("--seed 0 --skip-existing");
  CHECK(skipped.exit_code == 0);
  CHECK(cube.dir.without_path(skipped.err) == skipped_line);
  CHECK(fs::last_write_time(cube.shard) == written);
}

TEST_CASE("skip existing: another shard's file or a file that is not a shard at -o renders again") {
  CubeFolder cube;
  fs::path other = cube.dir.file("other.exr");
  CommandResult first = run_radiant("render " + quoted(cube.scene) + " -o " + quoted(other) +
                                    " --width 8 --height 8 --spp 2 --env-color 1,1,1 --shard 0/2 --quiet");
  REQUIRE(first.exit_code == 0);
  fs::copy_file(other, cube.shard);  // shard 0 where shard 1 goes
  render_written(cube, "--skip-existing --quiet");
  std::ofstream(cube.shard, std::ios::binary) << "not an image";
  render_written(cube, "--skip-existing --quiet");
}

TEST_CASE("skip existing: a shard cut short or with a bit flipped is rendered again, repairing it") {
  CubeFolder cube;
  render_written(cube, "--quiet");
  std::string intact = read_bytes(cube.shard);
  SUBCASE("cut short by 10 bytes") { std::ofstream(cube.shard, std::ios::binary) << intact.substr(0, intact.size() - 10); }
  SUBCASE("a bit flipped in its pixels") {
    std::string flipped = intact;
    flipped[flipped.size() - 20] ^= 4;
    std::ofstream(cube.shard, std::ios::binary) << flipped;
  }
  SUBCASE("a metadata value edited in place") {
    std::string edited = intact;
    size_t at = edited.find("radiant:seed");
    REQUIRE(at != std::string::npos);
    at = edited.find('0', at + 12);  // the seed's digit, after the attribute's type and size
    REQUIRE(at != std::string::npos);
    edited[at] = '7';
    std::ofstream(cube.shard, std::ios::binary) << edited;
  }
  render_written(cube, "--skip-existing --quiet");
  CommandResult again = cube.render("--skip-existing");  // repaired: the next run skips it
  CHECK(again.exit_code == 0);
  CHECK(cube.dir.without_path(again.err) == skipped_line);
}

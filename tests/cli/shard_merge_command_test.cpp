// `render --shard`/`--sample-range` and `radiant merge`: any exact cover of the image x [0, spp)
// merges to the pixels of one render, bit for bit; what cannot merge is refused and writes nothing.
#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "image/image_io.h"
#include "support/radiant_ok.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// A scene and the flags of a tiny render of it in one mode.
struct Case {
  const char* name;
  const char* scene;
  const char* flags;
};
const Case cases[] = {
    {"path", "assets/cornell.gltf", "--mode path --width 12 --height 10 --spp 8 --max-depth 3"},
    {"naive", "assets/cornell.gltf", "--mode naive --width 12 --height 10 --spp 8 --max-depth 3"},
    {"whitted", "assets/showcase.scene", "--mode whitted --width 12 --height 10 --spp 4"},
};
const char* all_aovs = " --aov albedo,normal,depth,variance,spp";

CommandResult quiet_ok(const std::string& args) { return radiant_ok(args + " --quiet"); }

// The words of `text`, split at spaces.
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  std::istringstream in(text);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

// Runs `words` (a command and its arguments) in this process, quietly; it must succeed.
void in_process_ok(std::vector<std::string> words) {
  words.push_back("--quiet");
  CommandResult r = run_radiant_in_process(words);
  std::string line;
  for (const std::string& word : words) line += word + " ";
  INFO(line);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
}

ImageHeader header_of(const fs::path& file) {
  std::string error;
  auto source = open_image_file(file.string(), error, nullptr);
  REQUIRE_MESSAGE(source, error);
  return source->header();
}

}  // namespace

TEST_CASE("merge cli: tiles, sample ranges and both merge to a single render's pixels bit for bit, PNG and EXR with all AOVs") {
  // 3 modes x (2 single renders + 3 splits x (4 shards + 2 merges)): 60 commands, run in this
  // process (the commands' own functions), where a process each cost a minute. The other tests
  // here run the executable.
  ScratchDir dir("merge-identical");
  for (const Case& c : cases) {
    CAPTURE(c.name);
    std::vector<std::string> base = {source_path(c.scene).string()};
    for (const std::string& word : words_of(c.flags)) base.push_back(word);
    auto with = [&](std::vector<std::string> words, const std::vector<std::string>& more) {
      words.insert(words.end(), more.begin(), more.end());
      return words;
    };
    std::vector<std::string> aovs = {"--aov", "albedo,normal,depth,variance,spp"};
    std::string single_exr = dir.file(std::string(c.name) + ".exr"), single_png = dir.file(std::string(c.name) + ".png");
    in_process_ok(with(with({"render"}, base), with({"-o", single_exr}, aovs)));
    in_process_ok(with(with({"render"}, base), {"-o", single_png}));
    for (const char* split : {"tiles", "samples", "both"}) {
      CAPTURE(split);
      std::vector<std::string> shards;
      std::vector<fs::path> shard_files;
      for (int i = 0; i < 4; ++i) {
        std::string shard = dir.file(std::string(c.name) + "-" + split + "-" + std::to_string(i) + ".exr");
        in_process_ok(with(with({"render"}, base),
                           with({"-o", shard, "--shard", std::to_string(i) + "/4", "--split", split}, aovs)));
        shards.insert(shards.begin(), shard);  // merged in another order than rendered
        shard_files.push_back(shard);
      }
      std::string merged_exr = dir.file("merged.exr"), merged_png = dir.file("merged.png");
      in_process_ok(with(with({"merge"}, shards), {"-o", merged_exr}));
      in_process_ok(with(with({"merge"}, shards), {"-o", merged_png}));
      CHECK(same_pixels(single_exr, merged_exr));
      CHECK(same_pixels(single_png, merged_png));
      // The merged image records the render the shards made together.
      for (const char* field : {"radiant:scene", "radiant:mode", "radiant:sampler", "radiant:spp", "radiant:seed"})
        CHECK(image_attribute(merged_png, field) == image_attribute(single_png, field));
      CHECK(image_attribute(merged_png, "radiant:shards") == "4");
      std::string shards_words;
      for (const std::string& shard : shards) shards_words += shard + " ";
      CHECK(image_attribute(merged_png, "Comment") == "radiant merge " + shards_words + "-o " + merged_png + " --quiet");
      CHECK(image_attribute(merged_png, "radiant:shard_command").rfind("radiant render ", 0) == 0);
      double seconds = 0;
      uint64_t rays = 0;
      for (const fs::path& shard : shard_files) {
        seconds += std::stod(image_attribute(shard, "radiant:render_seconds"));
        rays += std::stoull(image_attribute(shard, "radiant:rays"));
      }
      CHECK(std::stod(image_attribute(merged_png, "radiant:render_seconds")) == doctest::Approx(seconds).epsilon(1e-5));
      CHECK(std::stoull(image_attribute(merged_png, "radiant:rays")) == rays);
      CHECK(image_attribute(merged_png, "radiant:rays") == image_attribute(single_png, "radiant:rays"));
    }
  }
}

TEST_CASE("merge cli: the merged PNG is encoded as the render's: the scene's view, --exposure and --bit-depth") {
  ScratchDir dir("merge-encoding");
  // first-render.scene chooses `view linear`; a merge that ignored it would write standard sRGB.
  std::string scene = quoted(source_path("assets/first-render.scene")), base = " --width 12 --height 10 --spp 4";
  for (std::string encoding : {std::string(""), std::string(" --exposure 1.5 --bit-depth 16")}) {
    CAPTURE(encoding);
    fs::path single = dir.file("single.png"), merged = dir.file("merged.png");
    quiet_ok("render " + scene + " -o " + quoted(single) + base + encoding);
    std::string shards;
    for (int i = 0; i < 2; ++i) {
      std::string shard = quoted(dir.file("s" + std::to_string(i) + ".exr"));
      quiet_ok("render " + scene + " -o " + shard + base + encoding + " --shard " + std::to_string(i) + "/2");
      shards += shard + " ";
    }
    quiet_ok("merge " + shards + "-o " + quoted(merged));
    CHECK(same_pixels(single, merged));
    CHECK(header_of(merged).channel_types == header_of(single).channel_types);
  }
  // Shards of one render share its encoding; others are refused.
  quiet_ok("render " + scene + " -o " + quoted(dir.file("other.exr")) + base + " --view filmic --shard 1/2");
  fs::path refused = dir.file("refused.png");
  CommandResult r = run_radiant("merge " + quoted(dir.file("s0.exr")) + " " + quoted(dir.file("other.exr")) + " -o " +
                                quoted(refused));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("its image encoding 'filmic, exposure 0.000000, 8 bits' differs") != std::string::npos);
  CHECK_FALSE(fs::exists(refused));
}

TEST_CASE("merge cli: --keep-accum merges part of the shards into a shard that merges with the rest") {
  ScratchDir dir("merge-hierarchical");
  std::string scene = quoted(source_path("assets/cornell.gltf")), base = " --width 12 --height 10 --spp 8 --max-depth 3";
  fs::path single = dir.file("single.exr");
  quiet_ok("render " + scene + " -o " + quoted(single) + base + all_aovs);
  std::string shard[4];
  for (int i = 0; i < 4; ++i) {
    shard[i] = quoted(dir.file("s" + std::to_string(i) + ".exr"));
    quiet_ok("render " + scene + " -o " + shard[i] + base + all_aovs + " --shard " + std::to_string(i) + "/4 --split both");
  }
  // --split both of 4: shards 0 and 1 are the two sample ranges of the first tile.
  fs::path half = dir.file("half.exr"), merged = dir.file("merged.exr");
  quiet_ok("merge " + shard[1] + " " + shard[0] + " -o " + quoted(half) + " --keep-accum");
  quiet_ok("merge " + quoted(half) + " " + shard[3] + " " + shard[2] + " -o " + quoted(merged));
  CHECK(same_pixels(single, merged));
  // Shards 0 and 3 (a range of each tile) make no region x sample range: nothing to keep.
  fs::path refused = dir.file("refused.exr");
  CommandResult r = run_radiant("merge " + shard[0] + " " + shard[3] + " -o " + quoted(refused) + " --keep-accum");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: not covered by any shard: pixels 6,0,12,10 samples 0:4\n");
  CHECK_FALSE(fs::exists(refused));
}

TEST_CASE("merge cli: a sobol render of samples 0:4 extended by samples 4:16 of 16 spp equals a 16-spp render, jittered is refused") {
  ScratchDir dir("merge-extend");
  std::string scene = quoted(source_path("assets/cornell.gltf")), base = " --width 10 --height 8 --max-depth 2";
  fs::path single = dir.file("single.exr"), early = dir.file("early.exr"), later = dir.file("later.exr"),
           merged = dir.file("merged.exr");
  quiet_ok("render " + scene + " -o " + quoted(single) + base + " --sampler sobol --spp 16");
  quiet_ok("render " + scene + " -o " + quoted(early) + base + " --sampler sobol --spp 4 --sample-range 0:4");
  quiet_ok("render " + scene + " -o " + quoted(later) + base + " --sampler sobol --spp 16 --sample-range 4:16");
  quiet_ok("merge " + quoted(early) + " " + quoted(later) + " -o " + quoted(merged));
  CHECK(same_pixels(single, merged));

  quiet_ok("render " + scene + " -o " + quoted(early) + base + " --sampler jittered --spp 4 --sample-range 0:4");
  quiet_ok("render " + scene + " -o " + quoted(later) + base + " --sampler jittered --spp 16 --sample-range 4:16");
  fs::path refused = dir.file("refused.exr");
  CommandResult r = run_radiant("merge " + quoted(early) + " " + quoted(later) + " -o " + quoted(refused));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("later.exr: its settings hash") != std::string::npos);
  CHECK_FALSE(fs::exists(refused));
}

TEST_CASE("merge cli: missing shards are listed, mismatched ones named, and nothing is written") {
  ScratchDir dir("merge-refusals");
  std::string scene = quoted(source_path("assets/cornell.gltf")), base = " --width 8 --height 8 --spp 2 --max-depth 2";
  for (int i : {0, 2})
    quiet_ok("render " + scene + " -o " + quoted(dir.file("s" + std::to_string(i) + ".exr")) + base + " --shard " +
               std::to_string(i) + "/4");
  fs::path out = dir.file("out.png");
  CommandResult missing = run_radiant("merge " + quoted(dir.file("s0.exr")) + " " + quoted(dir.file("s2.exr")) + " -o " + quoted(out));
  CHECK(missing.exit_code == 1);
  CHECK(missing.err == "radiant: missing: 1,3 (of --shard I/4 --split tiles)\n");
  CHECK_FALSE(fs::exists(out));

  quiet_ok("render " + scene + " -o " + quoted(dir.file("s1.exr")) + base + " --shard 1/4 --seed 9");
  quiet_ok("render " + scene + " -o " + quoted(dir.file("s3.exr")) + base + " --shard 3/4");
  CommandResult mismatched = run_radiant("merge " + quoted(dir.file("s0.exr")) + " " + quoted(dir.file("s1.exr")) + " " +
                                         quoted(dir.file("s2.exr")) + " " + quoted(dir.file("s3.exr")) + " -o " + quoted(out));
  CHECK(mismatched.exit_code == 1);
  CHECK(dir.without_path(mismatched.err).find("radiant: s1.exr: its settings hash") == 0);
  CHECK_FALSE(fs::exists(out));

  fs::path plain = dir.file("plain.exr");
  quiet_ok("render " + scene + " -o " + quoted(plain) + base);
  CommandResult not_shard = run_radiant("merge " + quoted(plain) + " -o " + quoted(out));
  CHECK(not_shard.exit_code == 1);
  CHECK(dir.without_path(not_shard.err) == "radiant: plain.exr: not a radiant shard (its radiant:format is not 'radiant shard 1')\n");
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("render cli: a --crop EXR and a shard carry their region as data window and the full image as display window") {
  ScratchDir dir("shard-windows");
  std::string scene = quoted(source_path("assets/cornell.gltf")), base = " --width 16 --height 12 --spp 1 --max-depth 1";
  fs::path crop = dir.file("crop.exr"), shard = dir.file("shard.exr");
  quiet_ok("render " + scene + " -o " + quoted(crop) + base + " --crop 2,3,10,7");
  quiet_ok("render " + scene + " -o " + quoted(shard) + base + " --shard 3/4");
  for (auto [file, x, y, w, h] : {std::tuple{crop, 2, 3, 8, 4}, {shard, 8, 6, 8, 6}}) {
    fs::path image = file;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
    CAPTURE(image);
    ImageHeader header = header_of(image);
    CHECK(header.x == x);
    CHECK(header.y == y);
    CHECK(header.width == w);
    CHECK(header.height == h);
    CHECK(header.full_x == 0);
    CHECK(header.full_y == 0);
    CHECK(header.full_width == 16);
    CHECK(header.full_height == 12);
  }
}

TEST_CASE("render cli: splits that cannot be exact are refused as usage errors, writing nothing") {
  ScratchDir dir("shard-usage");
  std::string scene = quoted(source_path("assets/cornell.gltf")), base = " --width 8 --height 8 --spp 4";
  fs::path out = dir.file("out.exr");
  for (std::string flags : {"--noise-threshold 0.1 --sample-range 0:2", "--noise-threshold 0.1 --shard 0/2 --split samples",
                            "--time-limit 5 --shard 0/2", "--time-limit 5 --sample-range 0:2", "--shard 0/2 --crop 0,0,4,4",
                            "--split tiles", "--skip-existing", "--shard 2/2", "--shard 0/9 --split samples",
                            "--sample-range 3:9"}) {
    CAPTURE(flags);
    CommandResult r = run_radiant("render " + scene + " -o " + quoted(out) + base + " " + flags);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find('\n') == r.err.size() - 1);
    CHECK_FALSE(fs::exists(out));
  }
  CommandResult png = run_radiant("render " + scene + " -o " + quoted(dir.file("out.png")) + base + " --shard 0/2");
  CHECK(png.exit_code == 2);
  CHECK(png.err.find("-o must end in .exr") != std::string::npos);
  // Adaptive sampling splits by tiles: each pixel keeps all its samples in one shard.
  quiet_ok("render " + scene + " -o " + quoted(out) + base + " --noise-threshold 0.1 --shard 0/2 --split tiles");
}

TEST_CASE("batch cli: --shard I/K renders render lines I, I+K, ... of the script") {
  ScratchDir dir("batch-shard");
  std::string script = "scene " + source_path("assets/first-render.scene").string() + "\n";
  for (int i = 0; i < 5; ++i) script += "render -o " + dir.file("v" + std::to_string(i) + ".png").string() + " --width 8 --height 8 --spp 1\n";
  fs::path file = dir.write("views.txt", script);
  quiet_ok("batch " + quoted(file) + " --shard 1/2");
  for (int i = 0; i < 5; ++i) CHECK(fs::exists(dir.file("v" + std::to_string(i) + ".png")) == (i % 2 == 1));
}

TEST_CASE("merge cli: a damaged shard is refused naming it and what is wrong, and nothing is written") {
  ScratchDir dir("merge-damaged");
  std::string scene = quoted(source_path("assets/cornell.gltf")), base = " --width 8 --height 8 --spp 2 --max-depth 2";
  for (int i : {0, 1})
    quiet_ok("render " + scene + " -o " + quoted(dir.file("s" + std::to_string(i) + ".exr")) + base + " --shard " +
             std::to_string(i) + "/2");
  std::string bytes = read_bytes(dir.file("s1.exr"));
  fs::path out = dir.file("out.png");
  auto merge_with_s1 = [&](const std::string& s1) {
    dir.write("s1.exr", s1);
    return run_radiant("merge " + quoted(dir.file("s0.exr")) + " " + quoted(dir.file("s1.exr")) + " -o " + quoted(out));
  };
  CommandResult cut = merge_with_s1(bytes.substr(0, bytes.size() - 10));
  CHECK(cut.exit_code == 1);
  CHECK(dir.without_path(cut.err) == "radiant: s1.exr: the file is " + std::to_string(bytes.size() - 10) +
                                         " bytes but its last chunk ends at byte " + std::to_string(bytes.size()) +
                                         " (cut short or extended)\n");
  CHECK_FALSE(fs::exists(out));
  // A bit flipped in each of 40 places: refused with a reason naming the shard, or merged unchanged.
  CommandResult intact = merge_with_s1(bytes);
  REQUIRE(intact.exit_code == 0);
  std::string merged = read_bytes(out);
  fs::remove(out);
  for (size_t k = 0; k < 40; ++k) {
    std::string flipped = bytes;
    size_t at = k * bytes.size() / 40;
    flipped[at] = char(flipped[at] ^ 0x10);
    CAPTURE(at);
    CommandResult r = merge_with_s1(flipped);
    if (r.exit_code == 0) {
      CHECK(read_bytes(out) == merged);
      fs::remove(out);
      continue;
    }
    std::string line = dir.without_path(r.err);
    CHECK(r.exit_code == 1);
    CHECK(line.rfind("radiant: s1.exr: ", 0) == 0);
    CHECK(line.size() > std::string("radiant: s1.exr: \n").size());
    CHECK_FALSE(fs::exists(out));
  }
}

// Shard files: every accumulator comes back exactly, with its window and metadata; files that are
// not shards radiant wrote are refused naming the file and the place.
#include <doctest/doctest.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "film/shard_file.h"
#include "image/image_io.h"
#include "image/render_metadata.h"
#include "output/output_set.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

ShardInfo window_info() {
  ShardInfo info;
  info.version = "9.9", info.scene_hash = "0123456789abcdef", info.settings_hash = "fedcba9876543210";
  info.isa = "avx2", info.sampler = "sobol", info.seed = 7, info.spp = 64;
  info.sample_begin = 16, info.sample_end = 32;
  info.x0 = 5, info.y0 = 1, info.x1 = 8, info.y1 = 3, info.full_width = 10, info.full_height = 4;
  info.aovs = {"albedo", "variance"};
  info.shard_index = 1, info.shard_count = 4, info.split = "both";
  info.request_hash = "0011223344556677", info.inputs = {"/scenes/a b,c.bin", "/scenes/tex.png"};
  info.transparent = true;
  return info;
}

// A 3x2 film at (5, 1) of a 10x4 image, with AOV and coverage sums, of values that use every
// bin and sign, some of them negatively weighted.
Film window_film() {
  Film film = make_film(3, 2, true, true);
  film.x = 5, film.y = 1, film.full_width = 10, film.full_height = 4;
  for (size_t i = 0; i < film.pixels.size(); ++i)
    for (int s = 0; s < 16; ++s) {
      float v = float(i + 1) * (s % 3 ? 0.37f : 3.0e30f) + float(s) * 1e-30f;
      add_sample(film.pixels[i], {v, v * 0.5f, 1e-40f * float(s)}, s % 5 == 0);
      film.alpha[i].add(s % 5 == 0 ? -0.75 : 1.0);
      FilmAovs& a = film.aovs[i];
      for (int k = 0; k < 3; ++k) a.albedo[k].add(0.25 * k), a.normal[k].add(k == 1 ? -0.9 : 0.1 * s);
      a.depth.add(1e38);
    }
  return film;
}

}  // namespace

TEST_CASE("shard file: every exact sum, sample count, window and metadata field comes back as written") {
  ScratchDir dir("shard-file");
  std::string path = dir.file("shard.exr").string();
  Film film = window_film();
  ShardInfo info = window_info();
  RenderRecord record{"9.9", "radiant render s.gltf -o shard.exr --shard 1/4", "s.gltf", "path", "sobol", 64, 7, 2.5, 123456};
  OutputSet outputs;
  write_shard(outputs.create(path), film, info, render_metadata(record), nullptr);
  outputs.commit();
  CHECK(read_shard_info(path, nullptr) == info);
  // The render's record beside the shard's own fields; what both hold (spp, seed, sampler) once.
  ImageMetadata metadata = read_image_header(path, nullptr).metadata;
  CHECK(parse_render_metadata(metadata) == record);
  for (const char* shared : {"radiant:spp", "radiant:seed", "radiant:sampler"})
    CHECK(std::count_if(metadata.begin(), metadata.end(), [&](const auto& a) { return a.first == shared; }) == 1);
  LoadedShard loaded = read_shard_film(path, info, nullptr);
  REQUIRE(loaded.film.pixels.size() == film.pixels.size());
  CHECK(loaded.film.x == 5);
  CHECK(loaded.film.y == 1);
  CHECK(loaded.film.full_width == 10);
  for (size_t i = 0; i < film.pixels.size(); ++i) {
    CAPTURE(i);
    CHECK(loaded.film.pixels[i].samples == film.pixels[i].samples);
    CHECK(loaded.film.pixels[i].negative_samples == 4);
    CHECK(loaded.film.alpha[i] == film.alpha[i]);
    for (int c = 0; c < 3; ++c) {
      CHECK(loaded.film.pixels[i].sum[c] == film.pixels[i].sum[c]);
      CHECK(loaded.film.pixels[i].sum_squares[c] == film.pixels[i].sum_squares[c]);
      CHECK(loaded.film.aovs[i].albedo[c] == film.aovs[i].albedo[c]);
      CHECK(loaded.film.aovs[i].normal[c] == film.aovs[i].normal[c]);
    }
    CHECK(loaded.film.aovs[i].depth == film.aovs[i].depth);
  }
}

TEST_CASE("shard file: an EXR without radiant's metadata, or with a sum no render makes, is refused") {
  ScratchDir dir("shard-file-refused");
  std::string plain = dir.file("plain.exr").string();
  write_test_image(plain, 2, 2, {"R", "G", "B"}, std::vector<float>(12, 0.5f));
  CHECK_THROWS_WITH_AS(read_shard_info(plain, nullptr), (plain + ": not a radiant shard (its radiant:format is not 'radiant shard 1')").c_str(),
                       std::runtime_error);

  // A shard whose first pixel's sum.R claims a top bin past the largest double's.
  std::string path = dir.file("forged.exr").string();
  Film film = window_film();
  film.pixels[0].sum[0] = ExactSum();
  ShardInfo info = window_info();
  OutputSet outputs;
  write_shard(outputs.create(path), film, info, {}, nullptr);
  outputs.commit();
  std::string error;
  auto source = open_image_file(path, error, nullptr);
  REQUIRE(source);
  ImageHeader header = source->header();
  std::vector<uint32_t> words(size_t(header.width) * header.height * header.channels);
  REQUIRE(source->read_channels(0, header.channels, PixelType::uint32, words.data()));
  source.reset();
  for (size_t c = 0; c < header.channel_names.size(); ++c)
    if (header.channel_names[c] == "sum.R.t") words[c] = 100;  // pixel (5, 1)
  ImageWriteSpec spec;
  spec.width = header.width, spec.height = header.height, spec.x = header.x, spec.y = header.y;
  spec.full_width = header.full_width, spec.full_height = header.full_height;
  spec.channel_names = header.channel_names;
  spec.channel_types.assign(header.channel_names.size(), PixelType::uint32);
  spec.metadata = shard_metadata(info);
  size_t pixels = size_t(header.width) * size_t(header.height);
  // Written without a checksum, then with the one that matches the forged words.
  OutputSet unsummed;
  write_image_file(unsummed.create(path), spec, words.data());
  unsummed.commit();
  CHECK_THROWS_WITH_AS(read_shard_info(path, nullptr),
                       (path + ": no radiant:checksum attribute, so its contents cannot be verified").c_str(),
                       std::runtime_error);
  spec.metadata.emplace_back("radiant:checksum", shard_checksum(spec.metadata, spec.channel_names, words.data(), pixels));
  OutputSet rewrite;
  write_image_file(rewrite.create(path), spec, words.data());
  rewrite.commit();
  CHECK_THROWS_WITH_AS(read_shard_film(path, info, nullptr),
                       (path + ": pixel (5, 1): channel sum.R.t holds a sum no render makes").c_str(), std::runtime_error);

  // More negatively weighted samples than its 16 samples (checked before the sums).
  for (size_t c = 0; c < header.channel_names.size(); ++c)
    if (header.channel_names[c] == "negative_samples") words[c] = 17;  // pixel (5, 1)
  spec.metadata.back().second = shard_checksum(spec.metadata, spec.channel_names, words.data(), pixels);
  OutputSet again;
  write_image_file(again.create(path), spec, words.data());
  again.commit();
  CHECK_THROWS_WITH_AS(read_shard_film(path, info, nullptr), (path + ": pixel (5, 1) holds more negative samples than samples").c_str(),
                       std::runtime_error);
}

namespace {

// The shard of window_film and window_info with a render record, as `write_shard` makes it.
std::string written_shard(const ScratchDir& dir, const std::string& name) {
  std::string path = dir.file(name).string();
  RenderRecord record{"9.9", "radiant render s.gltf -o shard.exr --shard 1/4", "s.gltf", "path", "sobol", 64, 7, 2.5, 123456};
  OutputSet outputs;
  write_shard(outputs.create(path), window_film(), window_info(), render_metadata(record), nullptr);
  outputs.commit();
  return path;
}

// "" when the shard at `path` reads back as window_film exactly, else the reason it was refused
// ("(no reason)" for an empty one).
std::string shard_refusal(const std::string& path) {
  try {
    ShardInfo info = read_shard_info(path, nullptr);
    LoadedShard loaded = read_shard_film(path, info, nullptr);
    Film film = window_film();
    bool same = info == window_info() && loaded.film.pixels.size() == film.pixels.size();
    for (size_t i = 0; same && i < film.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c)
        same = same && loaded.film.pixels[i].sum[c] == film.pixels[i].sum[c] &&
               loaded.film.pixels[i].sum_squares[c] == film.pixels[i].sum_squares[c] &&
               loaded.film.pixels[i].samples == film.pixels[i].samples && loaded.film.alpha[i] == film.alpha[i] &&
               loaded.film.aovs[i].albedo[c] == film.aovs[i].albedo[c] && loaded.film.aovs[i].depth == film.aovs[i].depth;
    return same ? "" : "read back different contents without an error";
  } catch (const std::runtime_error& e) {
    std::string message = e.what();
    if (message.rfind(path + ": ", 0) != 0) return "refused without naming the file: " + message;
    std::string reason = message.substr(path.size() + 2);
    return reason.empty() ? "(no reason)" : reason;
  }
}

}  // namespace

TEST_CASE("shard file: the checksum covers metadata and accumulators, and every refusal says what is wrong") {
  ScratchDir dir("shard-checksum");
  std::string path = written_shard(dir, "shard.exr");
  CHECK(shard_refusal(path) == "");
  std::string bytes = read_bytes(path);
  std::string checksum = image_attribute(path, "radiant:checksum");
  CHECK(checksum.size() == 33);

  // One bit flipped at a time, at 400 places spread over the file: each either reads back the
  // very film written, or is refused with a reason.
  size_t flips = 400, refused = 0;
  for (size_t k = 0; k < flips; ++k) {
    size_t at = k * bytes.size() / flips;
    std::string flipped = bytes;
    flipped[at] = char(flipped[at] ^ (1 << (k % 8)));
    std::string damaged = dir.write("flipped.exr", flipped).string();
    std::string refusal = shard_refusal(damaged);
    CAPTURE(at);
    CHECK(refusal != "(no reason)");
    CHECK(refusal != "read back different contents without an error");
    CHECK(refusal.find("refused without naming the file") == std::string::npos);
    refused += !refusal.empty();
  }
  CHECK(refused > flips * 9 / 10);

  // A file cut short, or with bytes added, is refused for its size before its pixels are read.
  std::string shorter = dir.write("short.exr", bytes.substr(0, bytes.size() - 10)).string();
  CHECK(shard_refusal(shorter).find("(cut short or extended)") != std::string::npos);
  std::string longer = dir.write("long.exr", bytes + "0123456789").string();
  CHECK(shard_refusal(longer).find("(cut short or extended)") != std::string::npos);
}

TEST_CASE("shard file: a changed metadata value or accumulator word is refused for its checksum") {
  ScratchDir dir("shard-checksum-edit");
  std::string path = written_shard(dir, "shard.exr");
  std::string error;
  auto source = open_image_file(path, error, nullptr);
  REQUIRE(source);
  ImageHeader header = source->header();
  std::vector<uint32_t> words(size_t(header.width) * header.height * header.channels);
  REQUIRE(source->read_channels(0, header.channels, PixelType::uint32, words.data()));
  source.reset();
  ImageWriteSpec spec;
  spec.width = header.width, spec.height = header.height, spec.x = header.x, spec.y = header.y;
  spec.full_width = header.full_width, spec.full_height = header.full_height;
  spec.channel_names = header.channel_names;
  spec.channel_types.assign(header.channel_names.size(), PixelType::uint32);
  spec.metadata = radiant_attributes(header.metadata);
  auto rewrite = [&] {
    OutputSet outputs;
    write_image_file(outputs.create(path), spec, words.data());
    outputs.commit();
  };
  rewrite();  // the same words and attributes written again: still intact
  CHECK(shard_refusal(path) == "");

  // The seed edited: still a well-formed shard, but not the one the checksum describes.
  for (auto& [key, value] : spec.metadata)
    if (key == "radiant:seed") value = "8";
  rewrite();
  CHECK(shard_refusal(path) == "its metadata does not match its radiant:checksum: the file is damaged");

  // The seed back, one sum's low bit changed: a plausible sum, caught by the checksum alone.
  for (auto& [key, value] : spec.metadata)
    if (key == "radiant:seed") value = "7";
  for (size_t c = 0; c < header.channel_names.size(); ++c)
    if (header.channel_names[c] == "sum.G.l0") words[header.channels + c] ^= 1;  // pixel (6, 1)
  rewrite();
  CHECK(shard_refusal(path) == "its accumulators do not match its radiant:checksum: the file is damaged");
}

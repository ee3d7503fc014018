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
  OutputSet rewrite;
  write_image_file(rewrite.create(path), spec, words.data());
  rewrite.commit();
  CHECK_THROWS_WITH_AS(read_shard_film(path, info, nullptr),
                       (path + ": pixel (5, 1): channel sum.R.t holds a sum no render makes").c_str(), std::runtime_error);

  // More negatively weighted samples than its 16 samples (checked before the sums).
  for (size_t c = 0; c < header.channel_names.size(); ++c)
    if (header.channel_names[c] == "negative_samples") words[c] = 17;  // pixel (5, 1)
  OutputSet again;
  write_image_file(again.create(path), spec, words.data());
  again.commit();
  CHECK_THROWS_WITH_AS(read_shard_film(path, info, nullptr), (path + ": pixel (5, 1) holds more negative samples than samples").c_str(),
                       std::runtime_error);
}

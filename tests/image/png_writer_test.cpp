// radiant's own PNG encoder: rows filtered and deflated in pieces on all threads, read back
// exactly by libpng (radiant's reader) and by zlib, the same bytes on any number of threads.
#include <doctest/doctest.h>
#include <tbb/task_arena.h>
#include <zlib.h>

#include <algorithm>
#include <random>

#include "image/image_io.h"
#include "image/parallel_deflate.h"
#include "image/png_writer.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

// The segments of deflate_in_pieces, joined, inflated by zlib: the bytes they hold.
std::vector<unsigned char> inflated(const std::vector<std::vector<unsigned char>>& segments, size_t expected_size) {
  std::vector<unsigned char> stream;
  for (const auto& segment : segments) stream.insert(stream.end(), segment.begin(), segment.end());
  std::vector<unsigned char> out(expected_size + 1);
  uLongf size = uLongf(out.size());
  REQUIRE(uncompress(out.data(), &size, stream.data(), uLong(stream.size())) == Z_OK);  // checks the Adler-32 too
  out.resize(size);
  return out;
}

size_t joined_size(const std::vector<std::vector<unsigned char>>& segments) {
  size_t size = 0;
  for (const auto& segment : segments) size += segment.size();
  return size;
}

// The size of `data` deflated by zlib as one stream at its default level with `strategy`.
size_t deflated_size(const std::vector<unsigned char>& data, int strategy) {
  z_stream stream{};
  REQUIRE(deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15, 8, strategy) == Z_OK);
  std::vector<unsigned char> out(deflateBound(&stream, uLong(data.size())));
  stream.next_in = const_cast<unsigned char*>(data.data());
  stream.avail_in = uInt(data.size());
  stream.next_out = out.data();
  stream.avail_out = uInt(out.size());
  REQUIRE(deflate(&stream, Z_FINISH) == Z_STREAM_END);
  size_t size = out.size() - stream.avail_out;
  deflateEnd(&stream);
  return size;
}

// `width` x `height` display values: smooth gradients with noise, so that every PNG filter wins
// somewhere and deflate finds matches.
std::vector<float> test_pixels(int width, int height, int channels) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> noise(-0.02f, 0.02f);
  std::vector<float> pixels(size_t(width) * height * channels);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < channels; ++c)
        pixels[(size_t(y) * width + x) * channels + c] = float(x + c * y) / float(width + height) + (x % 7 == 0 ? noise(random) : 0);
  return pixels;
}

ImageWriteSpec png_spec(int width, int height, std::vector<std::string> channels) {
  ImageWriteSpec spec;
  spec.width = width, spec.height = height;
  spec.channel_names = std::move(channels);
  spec.type = PixelType::uint8;
  return spec;
}

}  // namespace

TEST_CASE("parallel deflate: pieces join into one zlib stream of the input, at any size around a piece's") {
  std::mt19937 random(3);
  for (size_t size : {size_t(1), deflate_piece_bytes - 1, deflate_piece_bytes, deflate_piece_bytes + 1, 3 * deflate_piece_bytes + 17}) {
    CAPTURE(size);
    std::vector<unsigned char> data(size);
    for (size_t i = 0; i < size; ++i) data[i] = (unsigned char)(i % 251 < 100 ? random() : i % 13);
    auto segments = deflate_in_pieces(data.data(), data.size());
    CHECK(segments.size() == (size + deflate_piece_bytes - 1) / deflate_piece_bytes);
    CHECK(inflated(segments, size) == data);
  }
}

TEST_CASE("parallel deflate: each piece reaches back into the one before, so a seam costs almost nothing") {
  // A 16 KiB block of random bytes in runs of 8, repeated for four pieces. Runs alone shrink it
  // to about a quarter, so each piece is also searched, and the search finds every copy after the
  // first whole. A piece that did not see the 32 KiB before it would pay for a first copy again.
  std::mt19937 random(5);
  std::vector<unsigned char> block(16 << 10), data;
  for (size_t i = 0; i < block.size(); i += 8) std::fill_n(block.begin() + i, 8, (unsigned char)random());
  while (data.size() < 4 * deflate_piece_bytes) data.insert(data.end(), block.begin(), block.end());
  auto segments = deflate_in_pieces(data.data(), data.size());
  REQUIRE(segments.size() == 4);
  CHECK(inflated(segments, data.size()) == data);
  // Each later piece is one long match after another (at most 258 bytes each): a few hundred bytes.
  CHECK(joined_size(segments) < deflated_size(block, Z_FILTERED) + 3 * 1024);
}

TEST_CASE("parallel deflate: noise is run-length coded for speed, structure searched for size") {
  std::mt19937 random(11);
  SUBCASE("a noisy render's filtered rows: within 1% of the default level's size") {
    // Small differences around zero, as the Sub or Paeth filter leaves of 1-spp noise: nothing
    // for a search to find beyond runs, so run-length coding costs no size to speak of.
    std::normal_distribution<float> noise(0.0f, 6.0f);
    std::vector<unsigned char> data(4 * deflate_piece_bytes);
    for (unsigned char& b : data) b = (unsigned char)(int(std::lround(noise(random))) & 0xff);
    auto segments = deflate_in_pieces(data.data(), data.size());
    CHECK(inflated(segments, data.size()) == data);
    CHECK(double(joined_size(segments)) < 1.01 * double(deflated_size(data, Z_FILTERED)));
  }
  SUBCASE("a clean render's: about the default level's size, far below runs alone") {
    // A flat background (zeros after filtering) with one 48-byte motif, an object's edge, every
    // 400 bytes: runs shrink the background, and only a search finds the motif's repeats.
    std::vector<unsigned char> motif(48), data(4 * deflate_piece_bytes, 0);
    for (unsigned char& b : motif) b = (unsigned char)random();
    for (size_t i = 0; i + motif.size() <= data.size(); i += 400) std::copy(motif.begin(), motif.end(), data.begin() + i);
    auto segments = deflate_in_pieces(data.data(), data.size());
    CHECK(inflated(segments, data.size()) == data);
    // Each piece's own block header and first motif: tens of bytes a piece.
    CHECK(joined_size(segments) < deflated_size(data, Z_FILTERED) + 4 * 64);
    CHECK(double(joined_size(segments)) < 0.5 * double(deflated_size(data, Z_RLE)));
  }
}

TEST_CASE("PNG encoder: gray, RGB and RGBA read back exactly, in files of many pieces") {
  ScratchDir dir("png-encoder");
  // 300 x 120 pixels: 36 to 144 KB of rows, one to three pieces.
  for (auto channels : {std::vector<std::string>{"Y"}, {"R", "G", "B"}, {"R", "G", "B", "A"}}) {
    int count = int(channels.size());
    CAPTURE(count);
    std::vector<float> pixels = test_pixels(300, 120, count);
    std::filesystem::path file = dir.file("image" + std::to_string(count) + ".png");
    write_test_image(file, 300, 120, channels, pixels);
    std::string error;
    auto input = open_image_file(file.string(), error, nullptr);
    REQUIRE(input);
    CHECK(input->header().channels == count);
    CHECK(input->header().color_space == "sRGB");
    std::vector<unsigned char> read(pixels.size());
    REQUIRE(input->read(count, PixelType::uint8, read.data()));
    size_t wrong = 0;
    for (size_t i = 0; i < pixels.size(); ++i)
      wrong += read[i] != (unsigned char)std::clamp(int(pixels[i] * 255.0f + 0.5f), 0, 255);
    CHECK(wrong == 0);
  }
}

TEST_CASE("PNG encoder: the same bytes on one thread and on four") {
  ImageWriteSpec spec = png_spec(400, 300, {"R", "G", "B"});
  spec.metadata = {{"Software", "radiant"}};
  std::vector<float> pixels = test_pixels(400, 300, 3);
  std::string error;
  std::vector<unsigned char> one, four;
  tbb::task_arena(1).execute([&] { one = encode_png(spec, pixels.data(), error); });
  tbb::task_arena(4).execute([&] { four = encode_png(spec, pixels.data(), error); });
  CHECK(error.empty());
  CHECK(one.size() > 1000);
  CHECK(one == four);
}

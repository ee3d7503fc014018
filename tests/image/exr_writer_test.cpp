// EXR written without OpenImageIO: every file must read back through OpenEXR (in the module)
// exactly as the same image written by OpenImageIO's own EXR writer does.
#include <doctest/doctest.h>
#include <tbb/task_arena.h>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>

#include "image/image_io.h"
#include "output/output_set.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

void write_ours(const fs::path& file, const ImageWriteSpec& spec, const void* pixels) {
  OutputSet outputs;
  write_image_file(outputs.create(file.string()), spec, pixels);
  outputs.commit();
}

void write_theirs(const fs::path& file, const ImageWriteSpec& spec, const void* pixels) {
  int descriptor = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  REQUIRE(descriptor >= 0);
  std::string error = image_io_module().write(descriptor, file.string(), spec, pixels);
  ::close(descriptor);
  REQUIRE(error == "");
}

// A file as OpenEXR reads it: the header and each channel's values as stored (4 bytes each:
// uint32 channels as integers, the others as floats).
struct ReadBack {
  ImageHeader header;  // its metadata without "compression", which is kept apart
  std::string compression;
  std::vector<std::vector<uint32_t>> channels;
};

ReadBack read_back(const fs::path& file) {
  std::string error;
  auto source = image_io_module().open(file.string(), error);
  REQUIRE_MESSAGE(source, error);
  ReadBack r{source->header(), {}, {}};
  size_t pixels = size_t(r.header.width) * size_t(r.header.height);
  for (int c = 0; c < r.header.channels; ++c) {
    std::vector<uint32_t> values(pixels);
    PixelType type = r.header.channel_types[size_t(c)] == PixelType::uint32 ? PixelType::uint32 : PixelType::float32;
    REQUIRE(source->read_channels(c, c + 1, type, values.data()));
    r.channels.push_back(std::move(values));
  }
  for (const auto& [name, value] : r.header.metadata)
    if (name == "compression") r.compression = value;
  // OpenImageIO's writer adds an empty capture date on its own, which radiant's omits.
  std::erase_if(r.header.metadata, [](const auto& entry) { return entry.first == "DateTime" || entry.first == "compression"; });
  return r;
}

void check_same(const ReadBack& ours, const ReadBack& theirs) {
  CHECK(ours.header.width == theirs.header.width);
  CHECK(ours.header.height == theirs.header.height);
  CHECK(ours.header.x == theirs.header.x);
  CHECK(ours.header.y == theirs.header.y);
  CHECK(ours.header.full_width == theirs.header.full_width);
  CHECK(ours.header.full_height == theirs.header.full_height);
  CHECK(ours.header.channel_names == theirs.header.channel_names);
  CHECK(ours.header.channel_types == theirs.header.channel_types);
  CHECK(ours.header.alpha_channel == theirs.header.alpha_channel);
  CHECK(ours.header.color_space == theirs.header.color_space);
  CHECK(ours.header.metadata == theirs.header.metadata);
  REQUIRE(ours.channels.size() == theirs.channels.size());
  for (size_t c = 0; c < ours.channels.size(); ++c) {
    CAPTURE(ours.header.channel_names[c]);
    CHECK(ours.channels[c] == theirs.channels[c]);  // bit for bit
  }
}

// Floats over many magnitudes and both signs, with infinities and zeros of both signs: the
// values a render and its AOVs hold (NaN is left to its own test: its payload may differ).
std::vector<float> varied_floats(size_t count, uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<float> values(count);
  for (size_t i = 0; i < count; ++i) {
    float magnitude = std::ldexp(std::uniform_real_distribution<float>(1, 2)(random), int(random() % 60) - 30);
    values[i] = random() % 2 ? -magnitude : magnitude;
    if (i % 97 == 0) values[i] = std::numeric_limits<float>::infinity();
    if (i % 89 == 0) values[i] = -0.0f;
  }
  return values;
}

// A smooth image (what ZIP compresses) in the first rows, noise (stored raw) in the rest.
std::vector<float> smooth_then_noise(int width, int height, int channels) {
  std::vector<float> values = varied_floats(size_t(width) * height * channels, 3);
  for (int y = 0; y < height / 2; ++y)
    for (int i = 0; i < width * channels; ++i) values[size_t(y) * width * channels + i] = 0.01f * float(i / channels + y);
  return values;
}

}  // namespace

TEST_CASE("EXR writer: float and half images read back as OpenImageIO's writer's, compressed or not") {
  ScratchDir dir("exr-writer");
  const int width = 37, height = 35;  // not a multiple of the 16 lines of a ZIP chunk
  for (PixelType type : {PixelType::float32, PixelType::half})
    for (bool zip : {true, false})
      for (bool windowed : {false, true}) {
        CAPTURE(int(type));
        CAPTURE(zip);
        CAPTURE(windowed);
        ImageWriteSpec spec;
        spec.width = width, spec.height = height;
        if (windowed) spec.x = 5, spec.y = 9, spec.full_width = 64, spec.full_height = 50;
        spec.channel_names = {"R", "G", "B", "A", "albedo.R", "Z"};
        spec.type = type;
        spec.zip = zip;
        spec.color_space = "Linear";
        spec.metadata = {{"Software", "radiant test"}, {"radiant:empty", ""}, {"radiant:lines", "a\nb\n"},
                         {"Comment", std::string(300, 'x')}};
        std::vector<float> pixels = smooth_then_noise(width, height, int(spec.channel_names.size()));
        write_ours(dir.file("ours.exr"), spec, pixels.data());
        write_theirs(dir.file("theirs.exr"), spec, pixels.data());
        ReadBack ours = read_back(dir.file("ours.exr"));
        check_same(ours, read_back(dir.file("theirs.exr")));
        // OpenImageIO's writer compresses with ZIP unless told otherwise, which ImageWriteSpec cannot.
        CHECK(ours.compression == (zip ? "zip" : "none"));
      }
}

TEST_CASE("EXR writer: chunks compressed on one thread and on four make the same file") {
  ScratchDir dir("exr-threads");
  ImageWriteSpec spec;
  spec.width = 50, spec.height = 117;  // 8 chunks: two batches of four and a short last chunk
  spec.channel_names = {"R", "G", "B"};
  spec.type = PixelType::float32;
  spec.zip = true;
  std::vector<float> pixels = smooth_then_noise(spec.width, spec.height, 3);
  tbb::task_arena(1).execute([&] { write_ours(dir.file("one.exr"), spec, pixels.data()); });
  tbb::task_arena(4).execute([&] { write_ours(dir.file("four.exr"), spec, pixels.data()); });
  std::string one = read_bytes(dir.file("one.exr"));
  CHECK(one.size() > 1000);
  CHECK(one == read_bytes(dir.file("four.exr")));
  ReadBack back = read_back(dir.file("four.exr"));
  REQUIRE(back.channels.size() == 3);
  REQUIRE(back.header.channel_names == std::vector<std::string>{"R", "G", "B"});
  size_t wrong = 0;  // bit for bit
  for (size_t i = 0; i < size_t(spec.width) * spec.height; ++i)
    for (size_t c = 0; c < 3; ++c) wrong += back.channels[c][i] != std::bit_cast<uint32_t>(pixels[i * 3 + c]);
  CHECK(wrong == 0);
}

TEST_CASE("EXR writer: a shard's exact uint32 channels beside float colour read back bit for bit") {
  ScratchDir dir("exr-writer-shard");
  ImageWriteSpec spec;
  spec.width = 19, spec.height = 40;
  spec.x = 3, spec.y = 17, spec.full_width = 30, spec.full_height = 80;
  spec.channel_names = {"R", "G", "B", "radiant.samples", "radiant.sum.R", "radiant.sum.G"};
  spec.channel_types = {PixelType::float32, PixelType::float32, PixelType::float32,
                        PixelType::uint32,  PixelType::uint32,  PixelType::uint32};
  spec.type = PixelType::float32;
  spec.zip = true;
  std::mt19937 random(7);
  std::vector<uint32_t> words(size_t(spec.width) * spec.height * spec.channel_names.size());
  std::vector<float> floats = varied_floats(words.size(), 11);
  for (size_t i = 0; i < words.size(); ++i)
    words[i] = i % 6 < 3 ? std::bit_cast<uint32_t>(floats[i]) : uint32_t(random());
  write_ours(dir.file("ours.exr"), spec, words.data());
  write_theirs(dir.file("theirs.exr"), spec, words.data());
  ReadBack ours = read_back(dir.file("ours.exr"));
  check_same(ours, read_back(dir.file("theirs.exr")));
  REQUIRE(ours.header.channel_names.size() == 6);
  CHECK(ours.header.channel_types[3] == PixelType::uint32);
}

TEST_CASE("EXR writer: half floats round to nearest, ties to even, as OpenEXR's conversion does") {
  ScratchDir dir("exr-writer-half");
  const float inf = std::numeric_limits<float>::infinity();
  struct Case {
    float value, expected;
  };
  const Case cases[] = {
      {1 + std::ldexp(1.0f, -11), 1},                                   // a tie: to the even 1
      {1 + 3 * std::ldexp(1.0f, -11), 1 + std::ldexp(1.0f, -9)},        // a tie: to the even neighbour above
      {1 + std::ldexp(1.0f, -11) + std::ldexp(1.0f, -20), 1 + std::ldexp(1.0f, -10)},  // past the tie
      {65504, 65504},                                                   // the largest half
      {65519.99f, 65504},
      {65520, inf},                                                     // a tie past it overflows
      {-1e9f, -inf},
      {std::ldexp(1.0f, -14), std::ldexp(1.0f, -14)},                   // the smallest normal
      {std::ldexp(1.0f, -14) - std::ldexp(1.0f, -26), std::ldexp(1.0f, -14)},  // a subnormal rounding up to it
      {std::ldexp(1.0f, -24), std::ldexp(1.0f, -24)},                   // the smallest subnormal
      {std::ldexp(1.0f, -25), 0},                                       // a tie: to the even 0
      {std::ldexp(1.5f, -25), std::ldexp(1.0f, -24)},
      {std::ldexp(3.0f, -25), std::ldexp(1.0f, -23)},                   // 1.5 units: a tie, to 2
      {std::ldexp(5.0f, -25), std::ldexp(1.0f, -23)},                   // 2.5 units: a tie, to 2
      {std::ldexp(1.0f, -30), 0},
      {-0.0f, -0.0f},
  };
  const int count = int(std::size(cases)) + 1;
  ImageWriteSpec spec;
  spec.width = count, spec.height = 1;
  spec.channel_names = {"Y"};
  spec.type = PixelType::half;
  spec.zip = true;
  std::vector<float> values;
  for (const Case& c : cases) values.push_back(c.value);
  values.push_back(std::nanf(""));
  write_ours(dir.file("half.exr"), spec, values.data());
  ReadBack r = read_back(dir.file("half.exr"));
  REQUIRE(r.channels.size() == 1);
  for (int i = 0; i < count - 1; ++i) {
    CAPTURE(cases[i].value);
    CHECK(std::bit_cast<uint32_t>(std::bit_cast<float>(r.channels[0][size_t(i)])) ==
          std::bit_cast<uint32_t>(cases[i].expected));
  }
  CHECK(std::isnan(std::bit_cast<float>(r.channels[0].back())));

  // And OpenEXR's own conversion agrees on a million floats across the half range and beyond.
  spec.width = 1000, spec.height = 1000;
  std::mt19937 random(5);
  values.resize(size_t(spec.width) * spec.height);
  for (float& v : values) {
    do v = std::bit_cast<float>(uint32_t(random()) & 0xc7ffffffu);  // exponents up to 2^16
    while (std::isnan(v));
  }
  write_ours(dir.file("ours.exr"), spec, values.data());
  write_theirs(dir.file("theirs.exr"), spec, values.data());
  check_same(read_back(dir.file("ours.exr")), read_back(dir.file("theirs.exr")));
}

TEST_CASE("EXR writer: what OpenEXR cannot store is an error naming the reason, and nothing is written") {
  ScratchDir dir("exr-writer-errors");
  ImageWriteSpec spec;
  spec.width = spec.height = 1;
  spec.type = PixelType::float32;
  float pixel[2] = {0.5f, 0.5f};
  auto write_error = [&] {
    OutputSet outputs;
    try {
      write_image_file(outputs.create(dir.file("out.exr").string()), spec, pixel);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("written");
  };
  spec.channel_names = {"Y", "Y"};
  CHECK(write_error() == "cannot write '" + dir.file("out.exr").string() + "': two channels are named 'Y'");
  spec.channel_names = {"Y"};
  spec.metadata = {{"dataWindow", "0 0 9 9"}};
  CHECK(write_error() ==
        "cannot write '" + dir.file("out.exr").string() + "': the attribute name 'dataWindow' is reserved by OpenEXR");
  CHECK(fs::is_empty(dir.path));
  spec.metadata = {{std::string(40, 'n'), "a name past 31 bytes sets OpenEXR's long-names flag"}};
  write_ours(dir.file("long.exr"), spec, pixel);
  ReadBack r = read_back(dir.file("long.exr"));
  CHECK(std::count(r.header.metadata.begin(), r.header.metadata.end(), spec.metadata[0]) == 1);
  // OpenEXR 3.1 reads the name without the flag as well, so the flag is checked in the bytes:
  // version 2, flag 0x400 in the second byte.
  std::string bytes = read_bytes(dir.file("long.exr"));
  CHECK(bytes.substr(4, 4) == std::string("\x02\x04\x00\x00", 4));
}

#include "film/shard_file.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <charconv>
#include <cmath>
#include <memory>
#include <utility>
#include <stdexcept>

#include "image/exr_header_check.h"
#include "image/image_io.h"
#include "image/render_metadata.h"
#include "math/fnv_hash.h"

namespace radiant {

namespace {

constexpr const char* shard_format = "radiant shard 1";
constexpr int words_per_sum = 5;  // top bin, high bin in two halves, low bin in two halves
constexpr int color_channels = 3, count_channels = 2;  // samples, negative_samples
constexpr int max_sums = 17;

// The exact sums of one pixel in channel order: color sums, squares, coverage, the AOV sums, then
// the odd half's color sums.
struct PixelSums {
  std::array<ExactSum*, max_sums> sums{};
  int count = 0;
};

PixelSums pixel_sums(FilmPixel& p, ExactSum* alpha, FilmAovs* a, FilmHalf* odd) {
  PixelSums s;
  for (ExactSum& sum : p.sum) s.sums[s.count++] = &sum;
  for (ExactSum& sum : p.sum_squares) s.sums[s.count++] = &sum;
  if (alpha) s.sums[s.count++] = alpha;
  if (a) {
    for (ExactSum& sum : a->albedo) s.sums[s.count++] = &sum;
    for (ExactSum& sum : a->normal) s.sums[s.count++] = &sum;
    s.sums[s.count++] = &a->depth;
  }
  if (odd)
    for (ExactSum& sum : odd->sum) s.sums[s.count++] = &sum;
  return s;
}

// The odd half's sample counts follow every sum's words, so that the channels before them keep
// their places with and without halves.
std::vector<std::string> channel_names(bool with_alpha, bool with_aovs, bool with_halves) {
  std::vector<std::string> sums = {"sum.R", "sum.G", "sum.B", "sum2.R", "sum2.G", "sum2.B"};
  if (with_alpha) sums.push_back("alpha.A");
  if (with_aovs) sums.insert(sums.end(), {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z", "depth.Z"});
  if (with_halves) sums.insert(sums.end(), {"odd.R", "odd.G", "odd.B"});
  std::vector<std::string> names = {"R", "G", "B", "samples", "negative_samples"};
  for (const std::string& sum : sums)
    for (const char* word : {".t", ".h0", ".h1", ".l0", ".l1"}) names.push_back(sum + word);
  if (with_halves) names.insert(names.end(), {"odd.samples", "odd.negative_samples"});
  return names;
}

bool lists_halves(const std::vector<std::string>& aovs) {
  return std::find(aovs.begin(), aovs.end(), "halves") != aovs.end();
}

std::string join(const std::vector<std::string>& words, char separator) {
  std::string text;
  for (size_t i = 0; i < words.size(); ++i) text += (i ? std::string(1, separator) : "") + words[i];
  return text;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> words;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(separator, start);
    if (end == std::string::npos) end = text.size();
    words.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

template <typename Number>
Number parse_number(const std::string& name, const std::string& text) {
  Number value{};
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw std::runtime_error("radiant:" + name + " '" + text + "' is not a number");
  return value;
}

// The shortest text that reads back as `value` exactly.
std::string float_text(float value) {
  char text[32];
  auto [end, error] = std::to_chars(text, text + sizeof text, value);
  return std::string(text, end);
}

// "A:B" or "X0,Y0,X1,Y1" as numbers.
std::vector<int64_t> parse_numbers(const std::string& name, const std::string& text, char separator, size_t count) {
  std::vector<int64_t> numbers;
  size_t start = 0;
  for (size_t i = 0; i < count; ++i) {
    size_t end = i + 1 < count ? text.find(separator, start) : text.size();
    if (end == std::string::npos) throw std::runtime_error("radiant:" + name + " '" + text + "' is malformed");
    numbers.push_back(parse_number<int64_t>(name, text.substr(start, end - start)));
    start = end + 1;
  }
  return numbers;
}

void check(bool ok, const std::string& path, const std::string& why) {
  if (!ok) throw std::runtime_error(path + ": " + why);
}

constexpr const char* checksum_attribute = "radiant:checksum";

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// The radiant attributes other than the checksum, by name, those with a value: what the file
// says about itself.
uint64_t metadata_hash(const ImageMetadata& metadata) {
  ImageMetadata attributes = radiant_attributes(metadata);
  std::sort(attributes.begin(), attributes.end());
  uint64_t hash = fnv_offset;
  for (const auto& [key, value] : attributes) {
    if (key == checksum_attribute || value.empty()) continue;  // an empty attribute is not written
    hash = fnv1a(hash, key.c_str(), key.size() + 1);  // with its NUL, so that key and value cannot trade bytes
    hash = fnv1a(hash, value.c_str(), value.size() + 1);
  }
  return hash;
}

// Every accumulator word (all channels but the mean R, G, B a viewer shows), pixel by pixel, each
// pixel's channels by name: the file's order and the writer's agree on that.
uint64_t accumulator_hash(const std::vector<std::string>& names, const uint32_t* words, size_t pixels) {
  std::vector<size_t> order;
  for (size_t c = 0; c < names.size(); ++c)
    if (names[c] != "R" && names[c] != "G" && names[c] != "B") order.push_back(c);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return names[a] < names[b]; });
  uint64_t hash = fnv_offset;
  for (size_t i = 0; i < pixels; ++i)
    for (size_t c : order) {
      uint32_t word = words[i * names.size() + c];
      unsigned char bytes[4] = {uint8_t(word), uint8_t(word >> 8), uint8_t(word >> 16), uint8_t(word >> 24)};
      hash = fnv1a(hash, bytes, sizeof bytes);
    }
  return hash;
}

// The recorded checksum's two halves: the metadata's hash and the accumulators'.
std::pair<std::string, std::string> recorded_checksum(const ImageMetadata& metadata, const std::string& path) {
  std::optional<std::string> text = find_attribute(metadata, checksum_attribute);
  check(text.has_value(), path, "no radiant:checksum attribute, so its contents cannot be verified");
  check(text->size() == 33 && (*text)[16] == ' ', path, "its radiant:checksum is malformed (damaged?)");
  return {text->substr(0, 16), text->substr(17)};
}

}  // namespace

ImageMetadata shard_metadata(const ShardInfo& info) {
  ImageMetadata m = {
      {"radiant:format", shard_format},
      {"radiant:version", info.version},
      {"radiant:scene_hash", info.scene_hash},
      {"radiant:settings_hash", info.settings_hash},
      {"radiant:isa", info.isa},
      {"radiant:sampler", info.sampler},
      {"radiant:seed", std::to_string(info.seed)},
      {"radiant:spp", std::to_string(info.spp)},
      {"radiant:sample_range", std::to_string(info.sample_begin) + ":" + std::to_string(info.sample_end)},
      {"radiant:region", std::to_string(info.x0) + "," + std::to_string(info.y0) + "," + std::to_string(info.x1) + "," +
                             std::to_string(info.y1)},
      {"radiant:full_size", std::to_string(info.full_width) + "x" + std::to_string(info.full_height)},
      {"radiant:aovs", join(info.aovs, ',')},
      {"radiant:shard", info.shard_count ? std::to_string(info.shard_index) + "/" + std::to_string(info.shard_count) : ""},
      {"radiant:split", info.split},
      {"radiant:request_hash", info.request_hash},
      {"radiant:inputs", join(info.inputs, '\n')},
  };
  if (info.transparent) m.emplace_back("radiant:transparent", "1");
  m.emplace_back("radiant:view", view_transform_name(info.display.view));
  if (info.display.exposure != 0) m.emplace_back("radiant:exposure", float_text(info.display.exposure));
  if (info.bit_depth != 8) m.emplace_back("radiant:bit_depth", std::to_string(info.bit_depth));
  if (info.half) m.emplace_back("radiant:half", "1");
  if (!info.partial.empty()) m.emplace_back("radiant:partial", info.partial);
  return m;
}

ShardInfo parse_shard_metadata(const ImageMetadata& metadata) {
  auto find = [&](const std::string& name, bool required) -> std::string {
    for (const auto& [key, value] : metadata)
      if (key == "radiant:" + name) return value;
    if (required) throw std::runtime_error("no radiant:" + name + " attribute");
    return "";
  };
  if (find("format", false) != shard_format)
    throw std::runtime_error("not a radiant shard (its radiant:format is not '" + std::string(shard_format) + "')");
  ShardInfo info;
  info.version = find("version", true);
  info.scene_hash = find("scene_hash", true);
  info.settings_hash = find("settings_hash", true);
  info.isa = find("isa", true);
  info.sampler = find("sampler", true);
  info.seed = parse_number<uint32_t>("seed", find("seed", true));
  info.spp = parse_number<uint32_t>("spp", find("spp", true));
  if (info.spp > ExactSum::max_terms)
    throw std::runtime_error("radiant:spp " + std::to_string(info.spp) + " is more than a pixel's sums hold (2^24)");
  std::vector<int64_t> range = parse_numbers("sample_range", find("sample_range", true), ':', 2);
  std::vector<int64_t> region = parse_numbers("region", find("region", true), ',', 4);
  std::vector<int64_t> size = parse_numbers("full_size", find("full_size", true), 'x', 2);
  if (!(range[0] >= 0 && range[0] < range[1] && range[1] <= info.spp))
    throw std::runtime_error("radiant:sample_range " + find("sample_range", true) + " is not within [0, spp)");
  if (!(size[0] >= 1 && size[1] >= 1 && size[0] <= 65536 && size[1] <= 65536))
    throw std::runtime_error("radiant:full_size " + find("full_size", true) + " is out of range");
  if (!(region[0] >= 0 && region[1] >= 0 && region[0] < region[2] && region[1] < region[3] && region[2] <= size[0] &&
        region[3] <= size[1]))
    throw std::runtime_error("radiant:region " + find("region", true) + " is not inside the full image");
  info.sample_begin = uint32_t(range[0]), info.sample_end = uint32_t(range[1]);
  info.x0 = int(region[0]), info.y0 = int(region[1]), info.x1 = int(region[2]), info.y1 = int(region[3]);
  info.full_width = int(size[0]), info.full_height = int(size[1]);
  info.aovs = split(find("aovs", false), ',');
  if (std::string shard = find("shard", false); !shard.empty()) {
    std::vector<int64_t> index = parse_numbers("shard", shard, '/', 2);
    if (!(index[0] >= 0 && index[0] < index[1] && index[1] <= 1 << 20))
      throw std::runtime_error("radiant:shard '" + shard + "' is not I/K with 0 <= I < K");
    info.shard_index = int(index[0]), info.shard_count = int(index[1]);
  }
  info.split = find("split", false);
  std::string transparent = find("transparent", false);
  if (!transparent.empty() && transparent != "1")
    throw std::runtime_error("radiant:transparent '" + transparent + "' is not 1");
  info.transparent = transparent == "1";
  if (std::string view = find("view", false); !view.empty()) {
    try {
      info.display.view = parse_view_transform(view);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error("radiant:view: " + std::string(e.what()));
    }
  }
  if (std::string exposure = find("exposure", false); !exposure.empty()) {
    info.display.exposure = parse_number<float>("exposure", exposure);
    if (!std::isfinite(info.display.exposure) || std::abs(info.display.exposure) > 64)
      throw std::runtime_error("radiant:exposure '" + exposure + "' is not a number of stops in [-64, 64]");
  }
  if (std::string depth = find("bit_depth", false); !depth.empty()) {
    if (depth != "16") throw std::runtime_error("radiant:bit_depth '" + depth + "' is not 16");
    info.bit_depth = 16;
  }
  std::string half = find("half", false);
  if (!half.empty() && half != "1") throw std::runtime_error("radiant:half '" + half + "' is not 1");
  info.half = half == "1";
  info.partial = find("partial", false);
  info.request_hash = find("request_hash", false);
  info.inputs = split(find("inputs", false), '\n');
  return info;
}

void write_shard(TemporaryFile& file, const Film& film, const ShardInfo& info, const ImageMetadata& record,
                 MemoryBudget* budget) {
  bool with_aovs = !film.aovs.empty(), with_alpha = !film.alpha.empty(), with_halves = !film.odd_half.empty();
  ImageWriteSpec spec;
  spec.width = film.width, spec.height = film.height;
  spec.x = film.x, spec.y = film.y, spec.full_width = film.full_width, spec.full_height = film.full_height;
  spec.channel_names = channel_names(with_alpha, with_aovs, with_halves);
  spec.type = PixelType::float32;
  spec.channel_types.assign(spec.channel_names.size(), PixelType::uint32);
  for (int c = 0; c < color_channels; ++c) spec.channel_types[size_t(c)] = PixelType::float32;
  spec.color_space = "Linear";
  spec.zip = true;
  spec.metadata = shard_metadata(info);
  add_missing_attributes(spec.metadata, record);  // seed, spp and sampler are the shard's own
  std::erase_if(spec.metadata, [](const auto& attribute) { return attribute.first == checksum_attribute; });
  size_t stride = spec.channel_names.size();
  MemoryCharge memory(budget, saturating_multiply(film.pixels.size(), stride * sizeof(uint32_t)),
                      file.target() + ": the shard's channels");
  std::vector<uint32_t> words(film.pixels.size() * stride);
  for (size_t i = 0; i < film.pixels.size(); ++i) {
    uint32_t* out = &words[i * stride];
    FilmPixel pixel = film.pixels[i];
    FilmAovs aovs = with_aovs ? film.aovs[i] : FilmAovs{};
    ExactSum alpha = with_alpha ? film.alpha[i] : ExactSum{};
    FilmHalf odd = with_halves ? film.odd_half[i] : FilmHalf{};
    color3 mean = pixel_mean(pixel);
    for (int c = 0; c < color_channels; ++c) *out++ = std::bit_cast<uint32_t>(mean[c]);
    *out++ = pixel.samples;
    *out++ = pixel.negative_samples;
    PixelSums sums = pixel_sums(pixel, with_alpha ? &alpha : nullptr, with_aovs ? &aovs : nullptr,
                                with_halves ? &odd : nullptr);
    for (int s = 0; s < sums.count; ++s) {
      const ExactSum& sum = *sums.sums[size_t(s)];
      uint64_t high = uint64_t(sum.high()), low = uint64_t(sum.low());
      *out++ = uint32_t(sum.top());
      *out++ = uint32_t(high), *out++ = uint32_t(high >> 32);
      *out++ = uint32_t(low), *out++ = uint32_t(low >> 32);
    }
    if (with_halves) *out++ = odd.samples, *out++ = odd.negative_samples;
  }
  spec.metadata.emplace_back(checksum_attribute, shard_checksum(spec.metadata, spec.channel_names, words.data(),
                                                                film.pixels.size()));
  write_image_file(file, spec, words.data());
}

std::string shard_checksum(const ImageMetadata& metadata, const std::vector<std::string>& channel_names,
                           const uint32_t* words, size_t pixels) {
  return hex(metadata_hash(metadata)) + " " + hex(accumulator_hash(channel_names, words, pixels));
}

ShardInfo read_shard_info(const std::string& path, MemoryBudget* budget) {
  std::string error;
  std::unique_ptr<ImageSource> source = open_image_file(path, error, budget);
  check(source != nullptr, path, error.empty() ? "cannot be read as an image (damaged?)" : error);
  const ImageHeader& header = source->header();
  ShardInfo info;
  try {
    info = parse_shard_metadata(header.metadata);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  check(recorded_checksum(header.metadata, path).first == hex(metadata_hash(header.metadata)), path,
        "its metadata does not match its radiant:checksum: the file is damaged");
  std::string extent = exr_extent_problem(path);
  check(extent.empty(), path, extent);
  check(header.x == info.x0 && header.y == info.y0 && header.width == info.x1 - info.x0 &&
            header.height == info.y1 - info.y0 && header.depth == 1,
        path, "its data window does not match its radiant:region");
  check(header.full_x == 0 && header.full_y == 0 && header.full_width == info.full_width &&
            header.full_height == info.full_height,
        path, "its display window does not match its radiant:full_size");
  return info;
}

LoadedShard read_shard_film(const std::string& path, const ShardInfo& info, MemoryBudget* budget) {
  std::string error;
  std::unique_ptr<ImageSource> source = open_image_file(path, error, budget);
  check(source != nullptr, path, error.empty() ? "cannot be read as an image (damaged?)" : error);
  const ImageHeader& header = source->header();
  bool with_aovs = !info.aovs.empty(), with_halves = lists_halves(info.aovs);
  std::vector<std::string> names = channel_names(info.transparent, with_aovs, with_halves);
  // Where each channel radiant needs lies in the file (EXR stores channels sorted by name).
  std::vector<int> file_channel(names.size());
  for (size_t n = color_channels; n < names.size(); ++n) {
    int found = -1;
    for (size_t c = 0; c < header.channel_names.size(); ++c)
      if (header.channel_names[c] == names[n]) found = int(c);
    check(found >= 0, path, "no channel " + names[n]);
    check(size_t(found) < header.channel_types.size() && header.channel_types[size_t(found)] == PixelType::uint32, path,
          "channel " + names[n] + " is not stored as uint32");
    file_channel[n] = found;
  }
  int width = info.x1 - info.x0, height = info.y1 - info.y0;
  // The file read again: it must still be the shard read_shard_info described.
  check(header.width == width && header.height == height && header.depth == 1, path, "changed while being merged");
  uint64_t pixels = uint64_t(width) * uint64_t(height);
  MemoryCharge read_memory(budget, saturating_multiply(pixels, uint64_t(header.channels) * sizeof(uint32_t)),
                           path + ": the shard's channels");
  MemoryCharge film_memory(budget,
                           saturating_multiply(pixels, film_pixel_bytes(with_aovs, info.transparent, with_halves)),
                           path + ": the shard's film");
  std::vector<uint32_t> words(pixels * size_t(header.channels));
  if (!source->read_channels(0, header.channels, PixelType::uint32, words.data())) {
    std::string why = source->error();
    check(false, path, why.empty() ? "its pixels cannot be decoded: the file is damaged or cut short" : why);
  }
  auto [metadata_sum, accumulator_sum] = recorded_checksum(header.metadata, path);
  check(metadata_sum == hex(metadata_hash(header.metadata)), path,
        "its metadata does not match its radiant:checksum: the file is damaged");
  check(accumulator_sum == hex(accumulator_hash(header.channel_names, words.data(), pixels)), path,
        "its accumulators do not match its radiant:checksum: the file is damaged");

  Film film = make_film(width, height, with_aovs, info.transparent, with_halves);
  film.x = info.x0, film.y = info.y0, film.full_width = info.full_width, film.full_height = info.full_height;
  uint32_t range = info.sample_end - info.sample_begin;
  for (size_t i = 0; i < film.pixels.size(); ++i) {
    const uint32_t* in = &words[i * size_t(header.channels)];
    auto word = [&](size_t name) { return in[file_channel[name]]; };
    auto place = [&] {
      return "pixel (" + std::to_string(info.x0 + int(i % size_t(width))) + ", " +
             std::to_string(info.y0 + int(i / size_t(width))) + ")";
    };
    FilmPixel& pixel = film.pixels[i];
    pixel.samples = word(color_channels);
    if (pixel.samples > range) check(false, path, place() + " holds more samples than its sample range");
    pixel.negative_samples = word(color_channels + 1);
    if (pixel.negative_samples > pixel.samples) check(false, path, place() + " holds more negative samples than samples");
    FilmHalf* odd = with_halves ? &film.odd_half[i] : nullptr;
    PixelSums sums = pixel_sums(pixel, info.transparent ? &film.alpha[i] : nullptr, with_aovs ? &film.aovs[i] : nullptr,
                                odd);
    if (odd) {
      size_t counts = color_channels + count_channels + size_t(sums.count) * words_per_sum;
      odd->samples = word(counts);
      if (odd->samples > pixel.samples) check(false, path, place() + " holds more odd samples than samples");
      odd->negative_samples = word(counts + 1);
      if (odd->negative_samples > odd->samples || odd->negative_samples > pixel.negative_samples)
        check(false, path, place() + " holds more negative odd samples than it can");
    }
    for (int s = 0; s < sums.count; ++s) {
      size_t first = color_channels + count_channels + size_t(s) * words_per_sum;
      int64_t high = int64_t(uint64_t(word(first + 1)) | uint64_t(word(first + 2)) << 32);
      int64_t low = int64_t(uint64_t(word(first + 3)) | uint64_t(word(first + 4)) << 32);
      if (!ExactSum::from_state(int(word(first)), high, low, *sums.sums[size_t(s)], pixel.samples))
        check(false, path, place() + ": channel " + names[first] + " holds a sum no render makes");
    }
  }
  return {std::move(film), std::move(film_memory)};
}

}  // namespace radiant

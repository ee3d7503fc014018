// Reading the channels that take part in a comparison: color (R,G,B by name), alpha, variance.
#include <algorithm>

#include "image/compare.h"
#include "image/image_io.h"

namespace radiant {

namespace {

// Refuse headers that would make us allocate more than 4 GiB of floats (hostile or absurd files).
constexpr size_t max_values = size_t(1) << 30;

// Every channel of subimage 0 as float, with the header it came from.
struct FileImage {
  ImageHeader header;
  MemoryCharge memory;
  std::vector<float> pixels;  // header.width * header.height * header.channels
};

FileImage read_file_image(const std::string& path, MemoryBudget* budget) {
  std::string error;
  auto source = open_image_file(path, error, budget);
  if (!source) throw CompareError(path + ": cannot read image: " + error);
  FileImage image;
  image.header = source->header();
  size_t count = size_t(std::max(image.header.width, 0)) * size_t(std::max(image.header.height, 0)) *
                 size_t(std::max(image.header.channels, 0));
  if (image.header.depth > 1 || image.header.deep)
    throw CompareError(path + ": volume and deep images cannot be compared");
  // What is compared must be what a viewer shows: refused rather than compared as stored.
  if (image.header.more_subimages)
    throw CompareError(path + ": it has more than one part (or page); compare reads one: extract the part to compare");
  if (image.header.orientation != 1)
    throw CompareError(path + ": its Orientation " + std::to_string(image.header.orientation) +
                       " flips or rotates it for display; compare images stored as they are shown");
  if (count == 0 || count > max_values)
    throw CompareError(path + ": image size " + std::to_string(image.header.width) + "x" +
                       std::to_string(image.header.height) + "x" +
                       std::to_string(image.header.channels) + " is empty or too large");
  image.memory = MemoryCharge(budget, count * sizeof(float), path + ": its pixels as float");
  image.pixels.resize(count);
  if (!source->read(image.header.channels, PixelType::float32, image.pixels.data()))
    throw CompareError(path + ": cannot read pixels: " + source->error());
  return image;
}

ImageWindow data_window(const ImageHeader& header) { return {header.x, header.y, header.width, header.height}; }

ImageWindow display_window(const ImageHeader& header) {
  if (header.full_width <= 0 || header.full_height <= 0) return data_window(header);
  return {header.full_x, header.full_y, header.full_width, header.full_height};
}

// `window`, or the whole image where none was given.
ImageWindow window_or_image(const ImageWindow& window, const CompareImage& image) {
  return window.width > 0 ? window : ImageWindow{0, 0, image.width, image.height};
}

std::string window_text(const ImageWindow& w) {
  return std::to_string(w.width) + "x" + std::to_string(w.height) + " at (" + std::to_string(w.x) + ", " +
         std::to_string(w.y) + ")";
}

// "data window 8x8 at (2, 0) in display window 8x8 at (0, 0)"
std::string windows_text(const ImageWindow& data, const ImageWindow& display) {
  return "data window " + window_text(data) + " in display window " + window_text(display);
}

int channel_index(const ImageHeader& header, const std::string& name) {
  auto& names = header.channel_names;
  auto found = std::find(names.begin(), names.end(), name);
  return found == names.end() ? -1 : int(found - names.begin());
}

// R,G,B by name; else the first three channels; else the non-alpha channels of a gray image.
std::vector<int> color_channels(const ImageHeader& header) {
  std::vector<int> rgb = {channel_index(header, "R"), channel_index(header, "G"), channel_index(header, "B")};
  if (std::count(rgb.begin(), rgb.end(), -1) == 0) return rgb;
  if (header.channels >= 3) return {0, 1, 2};
  std::vector<int> gray;
  for (int c = 0; c < header.channels; ++c)
    if (c != header.alpha_channel) gray.push_back(c);
  return gray;
}

int alpha_channel(const ImageHeader& header) {
  int named = channel_index(header, "A");
  return named >= 0 ? named : header.alpha_channel;
}

// Channel indices of "variance.<name>" for each color channel of `image`, or empty if any lacks.
std::vector<int> variance_channels(const ImageHeader& header, const CompareImage& image,
                                   int color_count) {
  std::vector<int> found;
  for (int c = 0; c < color_count; ++c) {
    int index = channel_index(header, "variance." + image.channel_names[c]);
    if (index < 0) return {};
    found.push_back(index);
  }
  return found;
}

// Copies channels `source` of `file` into `out` (laid out like `image`), scaled by `scale`;
// the compared channels past source.size() (alpha) get zero.
void copy_channels(const FileImage& file, const std::vector<int>& source, float scale,
                   const CompareImage& image, std::vector<float>& out) {
  int channels = image.channels(), file_channels = file.header.channels;
  out.assign(image.pixel_count() * channels, 0.0f);
  for (size_t p = 0; p < image.pixel_count(); ++p)
    for (size_t c = 0; c < source.size(); ++c)
      out[p * channels + c] = file.pixels[p * file_channels + source[c]] * scale;
}

// Removes the last channel (alpha) of every pixel from `values`, if not empty.
void drop_last_channel(std::vector<float>& values, int channels) {
  if (values.empty()) return;
  size_t kept = 0;
  for (size_t i = 0; i < values.size(); ++i)
    if (int(i % channels) != channels - 1) values[kept++] = values[i];
  values.resize(kept);
}

void drop_alpha(CompareImage& image) {
  drop_last_channel(image.values, image.channels());
  drop_last_channel(image.variance, image.channels());
  image.channel_names.pop_back();
  image.has_alpha = false;
}

}  // namespace

CompareImage read_compare_image(const std::string& path, MemoryBudget* budget) {
  FileImage file = read_file_image(path, budget);
  std::vector<int> source = color_channels(file.header);
  int color_count = int(source.size());
  int alpha = alpha_channel(file.header);
  CompareImage image;
  image.has_alpha = alpha >= 0 && std::find(source.begin(), source.end(), alpha) == source.end();
  if (image.has_alpha) source.push_back(alpha);
  image.path = path;
  image.width = file.header.width;
  image.height = file.header.height;
  image.data_window = data_window(file.header);
  image.display_window = display_window(file.header);
  image.color_space = file.header.color_space;
  for (int c : source) image.channel_names.push_back(file.header.channel_names[c]);
  std::vector<int> variance = variance_channels(file.header, image, color_count);
  uint64_t kept = image.pixel_count() * (source.size() + (variance.empty() ? 0 : source.size()));
  image.memory = std::make_shared<MemoryCharge>(budget, kept * sizeof(float), path + ": the compared channels");
  copy_channels(file, source, 1.0f, image, image.values);
  if (!variance.empty()) copy_channels(file, variance, 1.0f, image, image.variance);
  return image;
}

std::vector<float> read_variance_image(const std::string& path, const CompareImage& image,
                                       int samples_per_pixel, MemoryBudget* budget) {
  FileImage file = read_file_image(path, budget);
  if (file.header.width != image.width || file.header.height != image.height)
    throw CompareError(path + ": variance image is " + std::to_string(file.header.width) + "x" +
                       std::to_string(file.header.height) + " but " + image.path + " is " +
                       std::to_string(image.width) + "x" + std::to_string(image.height));
  ImageWindow data = window_or_image(image.data_window, image), display = window_or_image(image.display_window, image);
  if (data_window(file.header) != data || display_window(file.header) != display)
    throw CompareError(path + ": its " + windows_text(data_window(file.header), display_window(file.header)) +
                       " differs from " + image.path + "'s " + windows_text(data, display));
  int color_count = image.color_channels();
  std::vector<int> source = variance_channels(file.header, image, color_count);
  if (source.empty()) source = color_channels(file.header);
  if (int(source.size()) != color_count) {
    if (file.header.channels != 1)
      throw CompareError(path + ": variance image has " + std::to_string(file.header.channels) +
                         " channels; expected 1 or " + std::to_string(color_count));
    source.assign(color_count, 0);
  }
  std::vector<float> variance;
  MemoryCharge memory(budget, image.pixel_count() * image.channels() * sizeof(float), path + ": the variance");
  copy_channels(file, source, 1.0f / float(samples_per_pixel), image, variance);
  return variance;
}

void match_alpha(CompareImage& a, CompareImage& b) {
  if (a.has_alpha && !b.has_alpha) drop_alpha(a);
  if (b.has_alpha && !a.has_alpha) drop_alpha(b);
}

void check_comparable(const CompareImage& a, const CompareImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw CompareError("image sizes differ: " + a.path + " is " + std::to_string(a.width) + "x" +
                       std::to_string(a.height) + ", " + b.path + " is " +
                       std::to_string(b.width) + "x" + std::to_string(b.height));
  if (a.channels() != b.channels())
    throw CompareError("channel counts differ: " + a.path + " has " +
                       std::to_string(a.channels()) + " compared channels, " + b.path + " has " +
                       std::to_string(b.channels()));
  ImageWindow data_a = window_or_image(a.data_window, a), display_a = window_or_image(a.display_window, a);
  ImageWindow data_b = window_or_image(b.data_window, b), display_b = window_or_image(b.display_window, b);
  if (data_a != data_b || display_a != display_b)
    throw CompareError("image windows differ: " + a.path + " has its " + windows_text(data_a, display_a) + ", " +
                       b.path + " its " + windows_text(data_b, display_b) + " (a viewer shows them in different places)");
}

}  // namespace radiant

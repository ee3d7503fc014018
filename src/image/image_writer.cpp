#include "image/image_writer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/exr_writer.h"
#include "image/image_io.h"
#include "image/png_writer.h"

namespace radiant {

namespace {

// Whether the image's fourth channel is the alpha of a transparent render.
bool has_alpha(const OutputImage& image) { return image.channels.size() >= 4 && image.channels[3] == "A"; }

// How `image` is stored in `path`: every channel as linear float in a float format, otherwise
// the color display-encoded in 8 or 16 bits, with its alpha when it has one.
ImageWriteSpec output_spec(const std::string& path, const OutputImage& image) {
  bool as_float = is_float_format(path);
  ImageWriteSpec spec;
  spec.width = image.width;
  spec.height = image.height;
  int channels = as_float ? int(image.channels.size()) : has_alpha(image) ? 4 : 3;
  spec.channel_names.assign(image.channels.begin(), image.channels.begin() + channels);
  if (as_float) spec.type = image.half ? PixelType::half : PixelType::float32;
  else spec.type = image.bit_depth == 16 ? PixelType::uint16 : PixelType::uint8;
  spec.color_space = as_float ? "Linear" : "sRGB";
  spec.zip = as_float;
  if (as_float) {
    spec.x = image.x, spec.y = image.y;
    spec.full_width = image.full_width, spec.full_height = image.full_height;
  }
  spec.metadata = image.metadata;
  return spec;
}

// The display values of the color channels (and straight alpha) of `image`, `channels` per pixel;
// the writer quantizes them to 8 or 16 bits. Float formats keep the film's associated
// (premultiplied) color, as OpenEXR defines it; display formats store straight alpha, as PNG
// defines it: the color is divided by its alpha before it is encoded (where alpha is 0 there is
// no color to divide).
std::vector<float> display_values(const OutputImage& image, size_t channels) {
  size_t stride = image.channels.size();
  bool alpha = channels == 4;
  std::vector<float> data(size_t(image.width) * image.height * channels);
  tbb::parallel_for(size_t(0), size_t(image.width) * image.height, [&](size_t i) {
    const float* p = &image.pixels[i * stride];
    color3 color = {p[0], p[1], p[2]};
    if (alpha && p[3] > 0) color = color / p[3];
    color3 shown = display_encode(color, image.display);
    for (int c = 0; c < 3; ++c) data[i * channels + c] = shown[c];
    if (alpha) data[i * channels + 3] = std::clamp(p[3], 0.0f, 1.0f);
  });
  return data;
}

}  // namespace

void write_image(TemporaryFile& file, const OutputImage& image) {
  ImageWriteSpec spec = output_spec(file.target(), image);
  bool as_float = spec.type == PixelType::float32 || spec.type == PixelType::half;
  std::vector<float> data;
  if (!as_float) data = display_values(image, spec.channel_names.size());
  write_image_file(file, spec, as_float ? image.pixels.data() : data.data());
}

std::vector<unsigned char> encode_preview_png(const OutputImage& image, std::string& error) {
  ImageWriteSpec spec;
  spec.width = image.width;
  spec.height = image.height;
  spec.channel_names = has_alpha(image) ? std::vector<std::string>{"R", "G", "B", "A"}
                                        : std::vector<std::string>{"R", "G", "B"};
  std::vector<float> data = display_values(image, spec.channel_names.size());
  return encode_png(spec, data.data(), error);
}

void check_image_output(const std::string& path) {
  OutputImage color_only;  // what decides the writer: the format and the first three channels
  color_only.channels = {"R", "G", "B"};
  ImageWriteSpec spec = output_spec(path, color_only);
  if (writes_as_png(path, spec) || writes_as_exr(path, spec)) return;
  std::string extension = lowercase_extension(path);
  if (extension.empty())
    throw std::invalid_argument("cannot write '" + path + "': no extension names its image format (.png, .exr, ...)");
  if (!image_io_module().can_write(path))
    throw std::invalid_argument("cannot write '" + path + "': no image format radiant writes has the extension '" +
                                extension + "'");
}

void charge_image_output(MemoryBudget* budget, const std::string& path, int bit_depth) {
  OutputImage color_only;
  color_only.channels = {"R", "G", "B"};
  color_only.bit_depth = bit_depth;
  ImageWriteSpec spec = output_spec(path, color_only);
  if (!budget || writes_as_png(path, spec) || writes_as_exr(path, spec)) return;
  budget->charge_once("OpenImageIO", image_module_bytes, path + ": OpenImageIO's libraries and buffers to write it");
}

}  // namespace radiant

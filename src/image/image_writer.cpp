#include "image/image_writer.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace radiant {

namespace fs = std::filesystem;

namespace {

std::string lowercase_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string temporary_path_beside(const std::string& path) {
  fs::path p(path);
  // Keep the extension: OpenImageIO picks the format from it.
  std::string name = "." + p.stem().string() + ".tmp-" + std::to_string(getpid()) + p.extension().string();
  return (p.parent_path() / name).string();
}

void write_with_oiio(const std::string& file, const OutputImage& image, bool as_float) {
  auto out = OIIO::ImageOutput::create(file);
  if (!out) throw std::runtime_error(OIIO::geterror());
  int channels = as_float ? int(image.channels.size()) : 3;
  OIIO::ImageSpec spec(image.width, image.height, channels, as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  spec.channelnames.assign(image.channels.begin(), image.channels.begin() + channels);
  // No time stamp: the same render must give the same bytes.
  spec.attribute("DateTime", "");
  if (as_float) {
    spec.attribute("oiio:ColorSpace", "Linear");
    spec.attribute("compression", "zip");
  } else {
    spec.attribute("oiio:ColorSpace", "sRGB");
  }
  std::vector<float> data;
  const float* source = image.pixels.data();
  if (!as_float) {
    // sRGB-encode and clamp the color channels; OpenImageIO quantizes to 8 bits.
    size_t stride = image.channels.size();
    data.resize(size_t(image.width) * image.height * 3);
    for (size_t i = 0; i < size_t(image.width) * image.height; ++i)
      for (int c = 0; c < 3; ++c) data[i * 3 + c] = linear_to_srgb(std::clamp(image.pixels[i * stride + c], 0.0f, 1.0f));
    source = data.data();
  }
  if (!out->open(file, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, source) || !out->close())
    throw std::runtime_error(out->geterror());
}

}  // namespace

bool is_float_format(const std::string& path) {
  std::string ext = lowercase_extension(path);
  return ext == ".exr" || ext == ".hdr" || ext == ".pfm";
}

float linear_to_srgb(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void write_image(const std::string& path, const OutputImage& image) {
  std::string temporary = temporary_path_beside(path);
  try {
    write_with_oiio(temporary, image, is_float_format(path));
    fs::rename(temporary, path);
  } catch (const std::exception& e) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    // Name the file the user asked for, not the temporary one.
    std::string reason = e.what();
    for (size_t at; (at = reason.find(temporary)) != std::string::npos;) reason.replace(at, temporary.size(), path);
    throw std::runtime_error("cannot write '" + path + "': " + reason);
  }
}

}  // namespace radiant

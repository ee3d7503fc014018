// radiant's OpenImageIO module: the ImageIoModule interface (src/image/image_io_module.h) on
// OpenImageIO. Built as a shared library that radiant loads on first use.
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "image/image_io_module.h"

namespace radiant {

namespace {

// OpenImageIO's errors can span lines; the first one is the message.
std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? "unknown error" : line;
}

OIIO::TypeDesc type_desc(PixelType type) {
  switch (type) {
    case PixelType::uint8: return OIIO::TypeDesc::UINT8;
    case PixelType::half: return OIIO::TypeDesc::HALF;
    case PixelType::float32: return OIIO::TypeDesc::FLOAT;
  }
  return OIIO::TypeDesc::FLOAT;
}

class OiioImageSource final : public ImageSource {
 public:
  explicit OiioImageSource(std::unique_ptr<OIIO::ImageInput> input) : input_(std::move(input)) {
    const OIIO::ImageSpec& spec = input_->spec();
    header_.width = spec.width;
    header_.height = spec.height;
    header_.depth = spec.depth;
    header_.channels = spec.nchannels;
    header_.alpha_channel = spec.alpha_channel;
    header_.deep = spec.deep;
    header_.channel_names = spec.channelnames;
    header_.color_space = spec.get_string_attribute("oiio:ColorSpace");
  }
  const ImageHeader& header() const override { return header_; }
  bool read(int channels, PixelType type, void* out) override {
    bool read = input_->read_image(0, 0, 0, channels, type_desc(type), out);
    // libjpeg only warns about a file that ends early and fills the rest with gray; OpenImageIO
    // passes the warning on as an error message of a successful read. A partial read fails.
    std::string message = input_->geterror();
    if (read && message.empty()) return true;
    error_ = first_line(message);
    return false;
  }
  std::string error() override { return error_; }

 private:
  std::unique_ptr<OIIO::ImageInput> input_;
  ImageHeader header_;
  std::string error_;
};

std::unique_ptr<ImageSource> open_image(const std::string& path, std::string& error) {
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    error = first_line(OIIO::geterror());
    return nullptr;
  }
  return std::make_unique<OiioImageSource>(std::move(input));
}

std::string write_image(const std::string& path, const ImageWriteSpec& spec, const float* pixels) {
  auto output = OIIO::ImageOutput::create(path);
  if (!output) return "no image format for this extension";
  OIIO::ImageSpec file_spec(spec.width, spec.height, int(spec.channel_names.size()), type_desc(spec.type));
  file_spec.channelnames = spec.channel_names;
  // Alpha by name only (the constructor guesses channel 3 of four, which may be an AOV).
  auto alpha = std::find(spec.channel_names.begin(), spec.channel_names.end(), "A");
  file_spec.alpha_channel = alpha == spec.channel_names.end() ? -1 : int(alpha - spec.channel_names.begin());
  // No time stamp: the same render must give the same bytes.
  file_spec.attribute("DateTime", "");
  if (!spec.color_space.empty()) file_spec.attribute("oiio:ColorSpace", spec.color_space);
  if (spec.zip) file_spec.attribute("compression", "zip");
  if (!output->open(path, file_spec) || !output->write_image(OIIO::TypeDesc::FLOAT, pixels) || !output->close())
    return first_line(output->geterror());
  return "";
}

PixelDifference compare_pixels(const float* a, const float* b, int width, int height, int channels,
                               float fail_threshold, float warn_threshold) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  // Wrapped without copying: compare only reads.
  OIIO::ImageBuf buffer_a(spec, const_cast<float*>(a)), buffer_b(spec, const_cast<float*>(b));
  auto result = OIIO::ImageBufAlgo::compare(buffer_a, buffer_b, fail_threshold, warn_threshold);
  PixelDifference difference;
  // result.error is set whenever pixels fail; only an ImageBuf error means the comparison broke.
  if (buffer_a.has_error() || buffer_b.has_error()) difference.error = buffer_a.geterror() + buffer_b.geterror();
  difference.mean_error = result.meanerror;
  difference.rms_error = result.rms_error;
  difference.psnr = result.PSNR;
  difference.max_error = result.maxerror;
  difference.max_x = result.maxx;
  difference.max_y = result.maxy;
  difference.max_channel = result.maxc;
  difference.warn_pixels = result.nwarn;
  difference.fail_pixels = result.nfail;
  return difference;
}

constexpr ImageIoModule module_table = {image_io_interface_version, open_image, write_image, compare_pixels};

}  // namespace

}  // namespace radiant

extern "C" __attribute__((visibility("default"))) const radiant::ImageIoModule* radiant_image_io_module() {
  return &radiant::module_table;
}

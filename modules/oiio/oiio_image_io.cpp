// radiant's OpenImageIO module: the ImageIoModule interface (src/image/image_io_module.h) on
// OpenImageIO. Built as a shared library that radiant loads on first use.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <mutex>

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
    case PixelType::uint16: return OIIO::TypeDesc::UINT16;
    case PixelType::uint32: return OIIO::TypeDesc::UINT32;
    case PixelType::other: break;
  }
  return OIIO::TypeDesc::FLOAT;
}

PixelType pixel_type(OIIO::TypeDesc type) {
  if (type == OIIO::TypeDesc::UINT8) return PixelType::uint8;
  if (type == OIIO::TypeDesc::HALF) return PixelType::half;
  if (type == OIIO::TypeDesc::FLOAT) return PixelType::float32;
  if (type == OIIO::TypeDesc::UINT32) return PixelType::uint32;
  if (type == OIIO::TypeDesc::UINT16) return PixelType::uint16;
  return PixelType::other;
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
    header_.x = spec.x, header_.y = spec.y;
    header_.full_x = spec.full_x, header_.full_y = spec.full_y;
    header_.full_width = spec.full_width, header_.full_height = spec.full_height;
    for (int c = 0; c < spec.nchannels; ++c) header_.channel_types.push_back(pixel_type(spec.channelformat(c)));
    header_.color_space = spec.get_string_attribute("oiio:ColorSpace");
    for (const OIIO::ParamValue& attribute : spec.extra_attribs)
      if (attribute.type() == OIIO::TypeDesc::STRING)
        header_.metadata.emplace_back(attribute.name().string(), attribute.get_string());
    header_.orientation = spec.get_int_attribute("Orientation", 1);
    // Only where parts are separate pictures: OpenImageIO 2.4's WebP reader cannot seek back
    // to frame 0 of an animation. Reads ask for subimage 0 by number; the failed seek's message
    // must not fail them.
    std::string format = input_->format_name();
    if (format == "openexr" || format == "tiff") {
      header_.more_subimages = input_->seek_subimage(1, 0);
      input_->seek_subimage(0, 0);
      input_->geterror();
    }
  }
  const ImageHeader& header() const override { return header_; }
  bool read(int channels, PixelType type, void* out) override { return read_channels(0, channels, type, out); }
  bool read_channels(int begin, int end, PixelType type, void* out) override {
    bool read = input_->read_image(0, 0, begin, end, type_desc(type), out);
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

// Writes to a descriptor radiant opened (an exclusive temporary) and keeps the first error:
// OpenImageIO's writers do not all check what their proxy returns.
class DescriptorOutput final : public OIIO::Filesystem::IOProxy {
 public:
  DescriptorOutput(int descriptor, const std::string& path) : IOProxy(path, Write), descriptor_(descriptor) {}
  const char* proxytype() const override { return "descriptor"; }
  size_t read(void* data, size_t size) override {
    size_t got = pread(data, size, m_pos);
    m_pos += int64_t(got);
    return got;
  }
  size_t write(const void* data, size_t size) override {
    size_t written = pwrite(data, size, m_pos);
    m_pos += int64_t(written);
    return written;
  }
  size_t pread(void* data, size_t size, int64_t offset) override {
    ssize_t got = ::pread(descriptor_, data, size, offset);
    return got > 0 ? size_t(got) : 0;
  }
  size_t pwrite(const void* data, size_t size, int64_t offset) override {
    const char* bytes = static_cast<const char*>(data);
    size_t done = 0;
    while (done < size) {
      ssize_t n = ::pwrite(descriptor_, bytes + done, size - done, offset + int64_t(done));
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_number_) error_number_ = errno;
        break;
      }
      done += size_t(n);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    size_ = std::max(size_, size_t(offset) + done);
    return done;
  }
  size_t size() const override {
    std::lock_guard<std::mutex> lock(mutex_);
    return size_;
  }
  // The first failed write's errno, or 0.
  int error_number() const { return error_number_; }

 private:
  int descriptor_;
  size_t size_ = 0;
  int error_number_ = 0;
  mutable std::mutex mutex_;
};

bool can_write(const std::string& path) {
  if (OIIO::ImageOutput::create(path)) return true;
  OIIO::geterror();  // read, so that OpenImageIO does not print it at exit
  return false;
}

std::string write_image(int descriptor, const std::string& path, const ImageWriteSpec& spec, const void* pixels) {
  auto output = OIIO::ImageOutput::create(path);
  if (!output) return first_line(OIIO::geterror());
  OIIO::ImageSpec file_spec(spec.width, spec.height, int(spec.channel_names.size()), type_desc(spec.type));
  file_spec.channelnames = spec.channel_names;
  // The pixels as given: floats, or 4-byte values of each channel's own type.
  OIIO::TypeDesc given = OIIO::TypeDesc::FLOAT;
  if (!spec.channel_types.empty()) {
    file_spec.channelformats.clear();
    for (PixelType type : spec.channel_types) file_spec.channelformats.push_back(type_desc(type));
    file_spec.format = OIIO::TypeDesc::FLOAT;
    given = OIIO::TypeDesc::UNKNOWN;
  }
  file_spec.x = spec.x, file_spec.y = spec.y;
  file_spec.full_x = 0, file_spec.full_y = 0;
  file_spec.full_width = spec.full_width > 0 ? spec.full_width : spec.width;
  file_spec.full_height = spec.full_height > 0 ? spec.full_height : spec.height;
  // Alpha by name only (the constructor guesses channel 3 of four, which may be an AOV).
  auto alpha = std::find(spec.channel_names.begin(), spec.channel_names.end(), "A");
  file_spec.alpha_channel = alpha == spec.channel_names.end() ? -1 : int(alpha - spec.channel_names.begin());
  // radiant gives display formats (8 and 16 bits) straight alpha, as PNG and TIFF's unassociated
  // alpha store it: OpenImageIO would otherwise take it as associated and divide the color again.
  bool display = spec.channel_types.empty() && (spec.type == PixelType::uint8 || spec.type == PixelType::uint16);
  if (file_spec.alpha_channel >= 0 && display) file_spec.attribute("oiio:UnassociatedAlpha", 1);
  // No time stamp: the same render must give the same bytes.
  file_spec.attribute("DateTime", "");
  if (!spec.color_space.empty()) file_spec.attribute("oiio:ColorSpace", spec.color_space);
  if (spec.zip) file_spec.attribute("compression", "zip");
  for (const auto& [name, value] : spec.metadata) file_spec.attribute(name, value);
  DescriptorOutput proxy(descriptor, path);
  // OpenImageIO 2.4's TIFF writer, given any proxy, writes a directory without ImageLength when
  // it rewrites the Exif directory: TIFF goes by name.
  bool by_name = !output->supports("ioproxy") || std::string(output->format_name()) == "tiff";
  if (!by_name && !output->set_ioproxy(&proxy)) return first_line(output->geterror());
  bool written = output->open(path, file_spec) && output->write_image(given, pixels) && output->close();
  if (proxy.error_number()) return std::strerror(proxy.error_number());
  return written ? "" : first_line(output->geterror());
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

constexpr ImageIoModule module_table = {image_io_interface_version, open_image, can_write, write_image, compare_pixels};

}  // namespace

}  // namespace radiant

extern "C" __attribute__((visibility("default"))) const radiant::ImageIoModule* radiant_image_io_module() {
  // OpenEXR decoding on the calling thread: a file then costs one chunk's buffers, which radiant
  // charges to its memory budget before opening it (exr_header_check.h), not one per core.
  OIIO::attribute("exr_threads", -1);
  return &radiant::module_table;
}

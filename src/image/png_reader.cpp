#include "image/png_reader.h"

#include <png.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace radiant {

namespace {

// libpng's state for one file. libpng reports errors by longjmp, so the functions that call it
// hold only trivially destructible locals between their setjmp and the calls.
struct PngState {
  FILE* file = nullptr;
  png_structp png = nullptr;
  png_infop info = nullptr;
  char message[200] = "";

  ~PngState() {
    if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    if (file) std::fclose(file);
  }
};

// Keeps the first message and returns to the setjmp: nothing is printed.
void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message ? message : "unknown error");
  png_longjmp(png, 1);
}

// Warnings (e.g. "iCCP: known incorrect sRGB profile") are about files that still read correctly.
void on_warning(png_structp, png_const_charp) {}

// Reads the header and sets up the transformations OpenImageIO applies.
bool read_header(PngState& state) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  png_init_io(state.png, state.file);
  png_read_info(state.png, state.info);
  png_set_expand(state.png);  // palette to RGB, gray under 8 bits to 8, tRNS to alpha
  if (png_get_bit_depth(state.png, state.info) == 16) png_set_swap(state.png);  // to the host's little-endian
  png_set_interlace_handling(state.png);
  png_read_update_info(state.png, state.info);
  return true;
}

bool read_rows(PngState& state, png_bytepp rows) {
  if (setjmp(png_jmpbuf(state.png))) return false;
  png_read_image(state.png, rows);
  png_read_end(state.png, nullptr);
  return true;
}

// OpenImageIO's names for the color space a PNG declares.
std::string color_space_of(png_structp png, png_infop info) {
  int intent = 0;
  double gamma = 0;
  if (png_get_sRGB(png, info, &intent) || !png_get_gAMA(png, info, &gamma) || gamma <= 0) return "sRGB";
  double exponent = std::round(100 / gamma) / 100;
  if (exponent == 1) return "Linear";
  char name[32];
  std::snprintf(name, sizeof name, "Gamma%.2g", exponent);
  return name;
}

class PngSource final : public ImageSource {
 public:
  explicit PngSource(std::unique_ptr<PngState> state) : state_(std::move(state)) {
    png_structp png = state_->png;
    png_infop info = state_->info;
    header_.width = int(png_get_image_width(png, info));
    header_.height = int(png_get_image_height(png, info));
    header_.channels = png_get_channels(png, info);
    sixteen_bits_ = png_get_bit_depth(png, info) == 16;
    switch (header_.channels) {
      case 1: header_.channel_names = {"Y"}; break;
      case 2: header_.channel_names = {"Y", "A"}, header_.alpha_channel = 1; break;
      case 3: header_.channel_names = {"R", "G", "B"}; break;
      default: header_.channel_names = {"R", "G", "B", "A"}, header_.alpha_channel = 3; break;
    }
    header_.full_width = header_.width, header_.full_height = header_.height;
    header_.channel_types.assign(size_t(header_.channels), sixteen_bits_ ? PixelType::uint16 : PixelType::uint8);
    header_.color_space = color_space_of(png, info);
    // Text chunks (tEXt, zTXt, iTXt) before the pixels: radiant writes its own there.
    png_textp text = nullptr;
    int count = 0;
    png_get_text(png, info, &text, &count);
    for (int i = 0; i < count; ++i)
      header_.metadata.emplace_back(text[i].key, text[i].text ? text[i].text : "");
  }

  const ImageHeader& header() const override { return header_; }

  // Decodes the whole image; libpng reads the file once, so a second call fails.
  bool read(int channels, PixelType type, void* out) override {
    if (channels < 1 || channels > header_.channels || (type != PixelType::float32 && type != PixelType::uint8) || done_) {
      error_ = done_ ? "the pixels were already read" : "unsupported channel count or pixel type";
      return false;
    }
    done_ = true;
    size_t row_bytes = png_get_rowbytes(state_->png, state_->info);
    std::vector<unsigned char> data(row_bytes * size_t(header_.height));
    std::vector<png_bytep> rows(size_t(header_.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = data.data() + y * row_bytes;
    if (!read_rows(*state_, rows.data())) {
      error_ = state_->message;
      return false;
    }
    size_t pixels = size_t(header_.width) * size_t(header_.height);
    for (size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < channels; ++c) {
        size_t from = p * size_t(header_.channels) + size_t(c), to = p * size_t(channels) + size_t(c);
        unsigned value = data[from];
        if (sixteen_bits_) {
          uint16_t wide;
          std::memcpy(&wide, data.data() + from * 2, 2);
          value = wide;
        }
        float full_scale = sixteen_bits_ ? 65535.0f : 255.0f;
        if (type == PixelType::float32) static_cast<float*>(out)[to] = float(value) * (1 / full_scale);  // as OIIO converts
        else static_cast<uint8_t*>(out)[to] = uint8_t(sixteen_bits_ ? (value * 255 + 32767) / 65535 : value);
      }
    return true;
  }

  bool read_channels(int begin, int end, PixelType type, void* out) override {
    if (begin == 0) return read(end, type, out);
    error_ = "channels after the first cannot be read alone from a PNG";
    return false;
  }

  std::string error() override { return error_.empty() ? "unknown error" : error_; }

 private:
  std::unique_ptr<PngState> state_;
  ImageHeader header_;
  bool sixteen_bits_ = false;
  bool done_ = false;
  std::string error_;
};

}  // namespace

bool is_png_file(const std::string& path) {
  unsigned char signature[8];
  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return false;
  bool png = std::fread(signature, 1, sizeof signature, file) == sizeof signature && png_sig_cmp(signature, 0, 8) == 0;
  std::fclose(file);
  return png;
}

// libpng allocates a metadata chunk's declared length before reading it: a 200-byte file
// declaring a 1.7 GB text chunk asked for 1.7 GB (found by the image fuzzer), and libpng's own
// chunk limit does not cover text chunks. So the chunk headers are walked first: metadata (any
// chunk but pixel data, IDAT, which libpng streams) that runs past the end of the file or is
// longer than max_png_metadata_chunk_bytes is refused. Leaves the file at its start.
static bool check_chunk_lengths(FILE* file, std::string& error) {
  long offset = 8;  // after the signature
  if (std::fseek(file, 0, SEEK_END) != 0) return error = std::strerror(errno), false;
  long size = std::ftell(file);
  unsigned char header[8];
  while (offset + 8 <= size) {
    if (std::fseek(file, offset, SEEK_SET) != 0 || std::fread(header, 1, 8, file) != 8) break;
    uint32_t length = uint32_t(header[0]) << 24 | uint32_t(header[1]) << 16 | uint32_t(header[2]) << 8 | header[3];
    std::string type(reinterpret_cast<const char*>(header) + 4, 4);
    bool pixels = type == "IDAT";
    std::string where = "PNG chunk '" + type + "' at byte " + std::to_string(offset) + " declares " +
                        std::to_string(length) + " bytes";
    if (pixels && uint64_t(length) + 12 > uint64_t(size - offset)) break;  // truncated: libpng reports it
    if (uint64_t(length) + 12 > uint64_t(size - offset)) {
      error = where + ", past the end of the file (" + std::to_string(size) + " bytes)";
      return false;
    }
    if (!pixels && length > max_png_metadata_chunk_bytes) {
      error = where + ", more than a metadata chunk may hold (" + std::to_string(max_png_metadata_chunk_bytes) + ")";
      return false;
    }
    if (type == "IEND") break;
    offset += 12 + long(length);
  }
  std::rewind(file);
  return true;
}

std::unique_ptr<ImageSource> open_png(const std::string& path, std::string& error) {
  auto state = std::make_unique<PngState>();
  state->file = std::fopen(path.c_str(), "rb");
  if (!state->file) {
    error = std::strerror(errno);
    return nullptr;
  }
  state->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, state.get(), on_error, on_warning);
  if (state->png) state->info = png_create_info_struct(state->png);
  if (!state->png || !state->info) {
    error = "cannot start libpng";
    return nullptr;
  }
  if (!check_chunk_lengths(state->file, error)) return nullptr;
  if (!read_header(*state)) {
    error = state->message;
    return nullptr;
  }
  return std::make_unique<PngSource>(std::move(state));
}

}  // namespace radiant

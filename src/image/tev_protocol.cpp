#include "image/tev_protocol.h"

#include <cstring>
#include <stdexcept>

namespace radiant {

namespace {

// A message under construction: the length is written last, when it is known.
struct MessageWriter {
  std::vector<uint8_t> bytes;

  explicit MessageWriter(TevMessage type) {
    bytes.resize(4);
    bytes.push_back(uint8_t(type));
  }
  void u8(uint8_t v) { bytes.push_back(v); }
  void i32(int32_t v) { raw(&v, 4); }
  void f32(float v) { raw(&v, 4); }
  void text(const std::string& s) {
    // tev reads up to the first zero byte: a name holding one would shift every later field.
    if (s.find('\0') != std::string::npos) throw std::invalid_argument("display server: a name holds a zero byte");
    raw(s.data(), s.size());
    bytes.push_back(0);
  }
  // Little-endian on the machines radiant builds for (x86-64 and AArch64).
  void raw(const void* data, size_t size) {
    const uint8_t* p = static_cast<const uint8_t*>(data);
    bytes.insert(bytes.end(), p, p + size);
  }
  std::vector<uint8_t> finish() {
    if (bytes.size() > UINT32_MAX) throw std::length_error("display server: message over 4 GiB");
    uint32_t length = uint32_t(bytes.size());
    std::memcpy(bytes.data(), &length, 4);
    return std::move(bytes);
  }
};

}  // namespace

std::vector<uint8_t> tev_create_image(const std::string& name, int width, int height,
                                      const std::vector<std::string>& channels) {
  MessageWriter m(TevMessage::create_image);
  m.u8(1);  // grab focus
  m.text(name);
  m.i32(width);
  m.i32(height);
  m.i32(int32_t(channels.size()));
  for (const std::string& channel : channels) m.text(channel);
  return m.finish();
}

std::vector<uint8_t> tev_update_image(const std::string& name, const std::string& channel, int x, int y, int width,
                                      int height, const float* values) {
  MessageWriter m(TevMessage::update_image);
  m.u8(0);  // an update does not steal the focus from an image the user looks at
  m.text(name);
  m.text(channel);
  m.i32(x);
  m.i32(y);
  m.i32(width);
  m.i32(height);
  m.raw(values, size_t(width) * size_t(height) * sizeof(float));
  return m.finish();
}

std::vector<uint8_t> tev_close_image(const std::string& name) {
  MessageWriter m(TevMessage::close_image);
  m.text(name);
  return m.finish();
}

}  // namespace radiant

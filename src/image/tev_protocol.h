// The messages of tev's display protocol (the HDR viewer github.com/Tom94/tev, as pbrt-v4 and
// Mitsuba 3 send them): a little-endian uint32 length that counts itself, a type byte, then the
// fields; strings end in a zero byte, numbers are little-endian int32 and float32.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace radiant {

enum class TevMessage : uint8_t { close_image = 2, update_image = 3, create_image = 4 };

// Opens an empty image of `width` x `height` with the named channels, taking the viewer's focus.
std::vector<uint8_t> tev_create_image(const std::string& name, int width, int height,
                                      const std::vector<std::string>& channels);
// Replaces the pixels of one channel in the rectangle at (x, y): `values` holds width x height
// floats, top row first.
std::vector<uint8_t> tev_update_image(const std::string& name, const std::string& channel, int x, int y, int width,
                                      int height, const float* values);
std::vector<uint8_t> tev_close_image(const std::string& name);

}  // namespace radiant

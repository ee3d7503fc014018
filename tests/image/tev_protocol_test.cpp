// tev's display protocol as radiant encodes it: lengths that count themselves, zero-ended
// strings, little-endian numbers, and no name that would shift the fields after it.
#include <doctest/doctest.h>

#include <cstring>
#include <stdexcept>

#include "image/tev_protocol.h"

using namespace radiant;

namespace {

uint32_t length_field(const std::vector<uint8_t>& m) {
  uint32_t n = 0;
  std::memcpy(&n, m.data(), 4);
  return n;
}

}  // namespace

TEST_CASE("tev create message: type 4, focus, name, size and channel names") {
  std::vector<uint8_t> m = tev_create_image("a.png", 3, 2, {"R", "G"});
  std::vector<uint8_t> expected = {0, 0, 0, 0, 4, 1, 'a', '.', 'p', 'n', 'g', 0, 3, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0,
                                   'R', 0, 'G', 0};
  expected[0] = uint8_t(expected.size());
  CHECK(m == expected);
  CHECK(length_field(m) == m.size());
}

TEST_CASE("tev update message: one channel's rectangle of floats after its place") {
  float values[2] = {0.5f, -2.0f};
  std::vector<uint8_t> m = tev_update_image("i", "B", 4, 5, 2, 1, values);
  REQUIRE(m.size() == 4 + 1 + 1 + 2 + 2 + 16 + 8);
  CHECK(length_field(m) == m.size());
  CHECK(m[4] == 3);
  CHECK(m[5] == 0);  // updates leave the viewer's focus where it is
  int32_t place[4];
  std::memcpy(place, m.data() + 10, 16);
  CHECK(place[0] == 4);
  CHECK(place[1] == 5);
  CHECK(place[2] == 2);
  CHECK(place[3] == 1);
  float read[2];
  std::memcpy(read, m.data() + 26, 8);
  CHECK(read[0] == 0.5f);
  CHECK(read[1] == -2.0f);
}

TEST_CASE("tev close message: type 2 and the name") {
  std::vector<uint8_t> m = tev_close_image("x");
  CHECK(m == std::vector<uint8_t>{7, 0, 0, 0, 2, 'x', 0});
}

TEST_CASE("tev messages refuse a name with a zero byte") {
  CHECK_THROWS_AS(tev_close_image(std::string("a\0b", 3)), std::invalid_argument);
}

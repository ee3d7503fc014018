// OpenEXR allocates what a header declares while opening a file; exr_header_problem refuses
// headers that cannot fit in the file before OpenEXR sees them (src/image/exr_header_check.h).
#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "image/exr_header_check.h"
#include "image/image_io.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

std::string u32(uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; }

std::string attribute(const std::string& name, const std::string& type, const std::string& value) {
  return name + '\0' + type + '\0' + u32(uint32_t(value.size())) + value;
}

// A scanline header (uncompressed) with this data window, then `payload` bytes.
std::string exr_file(int32_t xmax, int32_t ymax, size_t payload) {
  std::string box = u32(0) + u32(0) + u32(uint32_t(xmax)) + u32(uint32_t(ymax));
  return u32(20000630) + u32(2) + attribute("compression", "compression", std::string(1, '\0')) +
         attribute("dataWindow", "box2i", box) + std::string(1, '\0') + std::string(payload, '\0');
}

}  // namespace

TEST_CASE("exr header: an attribute declaring more bytes than the file holds is refused before OpenEXR allocates it") {
  ScratchDir dir("exr-header");
  // The fuzzer's 27 bytes: a string attribute declaring 2^31 - 1 bytes (2.2 GB and 7 s in OpenEXR).
  std::string bomb = u32(20000630) + u32(2) + std::string("a\0string\0", 9) + u32(0x7fffffff) + "x";
  auto path = dir.write("bomb.exr", bomb);
  CHECK(exr_header_problem(path.string()) == "attribute 'a' declares 2147483647 bytes, the file has 1 left");
  std::string error;
  CHECK(open_image_file(path.string(), error) == nullptr);
  CHECK(error.find("corrupt OpenEXR header") != std::string::npos);
}

TEST_CASE("exr header: a data window of 2^30 scanlines in a small file is refused; one it can index is not") {
  ScratchDir dir("exr-window");
  CHECK(exr_header_problem(dir.write("tall.exr", exr_file(0, (1 << 30) - 1, 64)).string()).find("chunks") !=
        std::string::npos);
  // 4 scanlines, uncompressed: 4 chunks, 32 bytes of offsets.
  CHECK(exr_header_problem(dir.write("small.exr", exr_file(3, 3, 32)).string()).empty());
  CHECK(exr_header_problem(dir.write("short.exr", exr_file(3, 3, 31)).string()).find("chunks") != std::string::npos);
}

TEST_CASE("exr header: files radiant writes pass, and so does anything that is not OpenEXR") {
  ScratchDir dir("exr-real");
  auto exr = dir.file("real.exr");
  write_test_image(exr, 16, 8, {"R", "G", "B", "variance.R"}, std::vector<float>(16 * 8 * 4, 0.25f));
  CHECK(exr_header_problem(exr.string()).empty());
  CHECK(exr_header_problem(dir.write("text.exr", "not an image").string()).empty());
  CHECK(exr_header_problem(dir.file("missing.exr").string()).empty());
}

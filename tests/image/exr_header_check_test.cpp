// OpenEXR allocates what a header declares while opening a file; check_exr_header refuses
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
  CHECK(check_exr_header(path.string()).problem == "attribute 'a' declares 2147483647 bytes, the file has 1 left");
  std::string error;
  CHECK(open_image_file(path.string(), error, nullptr) == nullptr);
  CHECK(error.find("corrupt OpenEXR header") != std::string::npos);
}

TEST_CASE("exr header: a data window of 2^30 scanlines in a small file is refused, one it can index is not") {
  ScratchDir dir("exr-window");
  CHECK(check_exr_header(dir.write("tall.exr", exr_file(0, (1 << 30) - 1, 64)).string()).problem.find("chunks") !=
        std::string::npos);
  // 4 scanlines, uncompressed: 4 chunks, 32 bytes of offsets.
  CHECK(check_exr_header(dir.write("small.exr", exr_file(3, 3, 32)).string()).problem.empty());
  CHECK(check_exr_header(dir.write("short.exr", exr_file(3, 3, 31)).string()).problem.find("chunks") != std::string::npos);
}

TEST_CASE("exr header: files radiant writes pass, and so does anything that is not OpenEXR") {
  ScratchDir dir("exr-real");
  auto exr = dir.file("real.exr");
  write_test_image(exr, 16, 8, {"R", "G", "B", "variance.R"}, std::vector<float>(16 * 8 * 4, 0.25f));
  CHECK(check_exr_header(exr.string()).problem.empty());
  CHECK(check_exr_header(dir.write("text.exr", "not an image").string()).problem.empty());
  CHECK(check_exr_header(dir.file("missing.exr").string()).problem.empty());
}

TEST_CASE("exr header: what OpenEXR allocates to decode a file is charged to the budget before it opens the file") {
  // The image fuzzer's 683 bytes: a zip EXR whose data window is 4,128,776 x 4 RGB float. OpenEXR
  // allocated ~2 GB decoding its one chunk, beyond the 64 MiB the fuzzer allows.
  std::string bomb = test::source_path("tests/fuzz/regressions/image/timeout-exr-data-window-4m-wide-in-683-bytes.exr").string();
  ExrHeaderCheck check = check_exr_header(bomb);
  CHECK(check.problem.empty());
  CHECK(check.decoder_bytes == 3 * uint64_t(4128776) * 4 * 12);  // one chunk of 4 scanlines, three buffers
  MemoryBudget budget(uint64_t(64) << 20);
  std::string error;
  CHECK_THROWS_WITH_AS(open_image_file(bomb, error, &budget),
                       (bomb + ": OpenEXR's buffers for its declared chunks: 567 MiB needed, over the memory limit of "
                               "64.0 MiB (--max-memory)").c_str(),
                       MemoryLimitError);
  CHECK(budget.used() == 0);
  // A file of its own size is charged its chunk and its pixels, for as long as it is open.
  ScratchDir dir("exr-charge");
  auto exr = dir.file("real.exr");
  write_test_image(exr, 16, 8, {"R", "G", "B", "A"}, std::vector<float>(16 * 8 * 4, 0.25f));
  uint64_t decoder = check_exr_header(exr.string()).decoder_bytes;
  CHECK(decoder > 0);
  CHECK(decoder <= 3 * 16 * 8 * 16);
  {
    auto source = open_image_file(exr.string(), error, &budget);
    REQUIRE(source);
    CHECK(budget.used() == decoder + 16 * 8 * 4 * 4 + 8 * 8);
  }
  CHECK(budget.used() == 0);
}

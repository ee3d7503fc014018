// The PNG reader refuses a chunk that runs past the end of the file, or metadata longer than
// max_png_metadata_chunk_bytes, before libpng allocates it: a 60-byte file once asked for 1.7 GB.
#include <doctest/doctest.h>

#include <cstdint>
#include <string>

#include "image/png_reader.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

uint32_t crc32_of(const std::string& bytes) {
  uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string big_endian(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

// A 4x4 grey PNG's signature and IHDR, then a chunk header declaring `length` bytes of `type`.
std::string png_with_declared_chunk(const std::string& type, uint32_t length) {
  std::string ihdr = "IHDR" + big_endian(4) + big_endian(4) + std::string("\x08\x00\x00\x00\x00", 5);
  return std::string("\x89PNG\r\n\x1a\n", 8) + big_endian(13) + ihdr + big_endian(crc32_of(ihdr)) +
         big_endian(length) + type + "only a few bytes follow";
}

}  // namespace

TEST_CASE("png reader: a text chunk declaring 1.7 GB is refused before it is allocated, and so is metadata over 8 MiB") {
  ScratchDir dir("png-huge-chunk");
  std::string error;
  auto huge = open_png(dir.write("huge.png", png_with_declared_chunk("tEXt", 0x65720000u)).string(), error);
  CHECK(huge == nullptr);
  CHECK(error == "PNG chunk 'tEXt' at byte 33 declares 1701969920 bytes, past the end of the file (64 bytes)");
  // Metadata over the limit is refused even when the file holds it.
  std::string over_limit = png_with_declared_chunk("iCCP", uint32_t(max_png_metadata_chunk_bytes) + 1);
  over_limit.resize(over_limit.size() + max_png_metadata_chunk_bytes + 16, '\0');
  auto over = open_png(dir.write("over.png", over_limit).string(), error);
  CHECK(over == nullptr);
  CHECK(error.find("more than a metadata chunk may hold (8388608)") != std::string::npos);
}

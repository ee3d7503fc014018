// A sanity walk over an OpenEXR file's headers before OpenEXR opens it. OpenEXR allocates what a
// header declares while opening the file: a 27-byte file declaring a 2 GiB string attribute cost
// 2.2 GB and seven seconds, and a data window of 2^31 scanlines an offset table as large. The
// walk reads only the headers and refuses a file whose attributes or chunk table cannot fit in
// the bytes it has.
#pragma once

#include <cstdint>
#include <string>

namespace radiant {

struct ExrHeaderCheck {
  // "" when the file is not an OpenEXR file or its headers fit in it; otherwise why not, in words
  // ("attribute 'name' declares 2147483647 bytes, the file has 4 left").
  std::string problem;
  // What OpenEXR allocates to decode it, which a header alone decides (a 683-byte file may
  // declare a data window of 200 MB): a buffer for one chunk's packed bytes and the decompressor's
  // two (three chunks of unpacked size at most, for radiant's one decoding thread), each part's.
  // 0 for other files.
  uint64_t decoder_bytes = 0;
};

ExrHeaderCheck check_exr_header(const std::string& path);

// For a single-part scanline OpenEXR file: "" when its offset table points inside the file and its
// last chunk ends exactly where the file does, else why not, in words. "" for other files. Reads
// the headers, the offset table and one chunk's 8-byte prefix: a cheap check for a file cut short.
std::string exr_extent_problem(const std::string& path);

}  // namespace radiant

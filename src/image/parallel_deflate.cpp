#include "image/parallel_deflate.h"

#include <tbb/parallel_for.h>
#include <zlib.h>

#include <algorithm>
#include <atomic>
#include <utility>

namespace radiant {

namespace {

constexpr size_t window_bytes = size_t(32) << 10;  // deflate's farthest match distance

// Raw deflate of data[begin, end) (negative window bits: the zlib header and checksum are written
// once, around all the pieces) into `out`, after what `out` already holds.
bool deflate_piece(const unsigned char* data, size_t begin, size_t end, bool last, int level, int strategy,
                   std::vector<unsigned char>& out) {
  z_stream stream{};
  if (deflateInit2(&stream, level, Z_DEFLATED, -15, 8, strategy) != Z_OK) return false;
  size_t primed = std::min(begin, window_bytes);
  bool ok = primed == 0 || deflateSetDictionary(&stream, data + begin - primed, uInt(primed)) == Z_OK;
  size_t start = out.size();
  // A sync flush adds an empty stored block (5 bytes) to deflateBound's figure.
  out.resize(start + deflateBound(&stream, uLong(end - begin)) + 16);
  stream.next_in = const_cast<unsigned char*>(data + begin);
  stream.avail_in = uInt(end - begin);
  stream.next_out = out.data() + start;
  stream.avail_out = uInt(out.size() - start);
  if (ok) ok = deflate(&stream, last ? Z_FINISH : Z_SYNC_FLUSH) == (last ? Z_STREAM_END : Z_OK) && stream.avail_in == 0;
  out.resize(out.size() - stream.avail_out);
  deflateEnd(&stream);
  return ok;
}

// One piece, by whichever of two ways suits it. Run-length coding (matches one byte back, then
// Huffman codes) first: on a noisy render's filtered rows it comes within a percent of zlib's
// default level in a sixth of the time, because noise leaves deflate's search for longer matches
// almost nothing to find. Where runs alone already shrink the piece below
// `searched_below` of its size it has structure (flat backgrounds, clean gradients), and there the
// default level's search, with libpng's strategy for filtered rows, is tried too and kept when
// smaller: cheap there, and a clean image up to a quarter smaller than with runs alone.
constexpr double searched_below = 0.4;

bool deflate_piece_adaptively(const unsigned char* data, size_t begin, size_t end, bool last,
                              std::vector<unsigned char>& out) {
  if (!deflate_piece(data, begin, end, last, Z_DEFAULT_COMPRESSION, Z_RLE, out)) return false;
  if (double(out.size()) >= searched_below * double(end - begin)) return true;
  std::vector<unsigned char> searched;
  if (!deflate_piece(data, begin, end, last, Z_DEFAULT_COMPRESSION, Z_FILTERED, searched)) return false;
  if (searched.size() < out.size()) out = std::move(searched);
  return true;
}

}  // namespace

std::vector<std::vector<unsigned char>> deflate_in_pieces(const unsigned char* data, size_t size) {
  size_t count = std::max<size_t>(1, (size + deflate_piece_bytes - 1) / deflate_piece_bytes);
  std::vector<std::vector<unsigned char>> segments(count);
  std::vector<uLong> checksums(count);
  segments[0] = {0x78, 0x9C};  // deflate with a 32 KiB window, no preset dictionary (the level bits only inform)
  std::atomic<bool> failed{false};
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    size_t begin = i * deflate_piece_bytes, end = std::min(size, begin + deflate_piece_bytes);
    std::vector<unsigned char> piece;
    if (!deflate_piece_adaptively(data, begin, end, i + 1 == count, piece)) failed = true;
    segments[i].insert(segments[i].end(), piece.begin(), piece.end());
    checksums[i] = adler32(1, data + begin, uInt(end - begin));
  });
  if (failed) return {};
  uLong adler = checksums[0];
  for (size_t i = 1; i < count; ++i)
    adler = adler32_combine(adler, checksums[i], z_off_t(std::min(size, (i + 1) * deflate_piece_bytes) - i * deflate_piece_bytes));
  for (int shift = 24; shift >= 0; shift -= 8) segments.back().push_back((unsigned char)(adler >> shift));
  return segments;
}

}  // namespace radiant

// One zlib stream compressed in independent pieces on all of the arena's threads (pigz's scheme):
// deflating a large 8-bit image was the longest single-threaded step of a render.
#pragma once

#include <cstddef>
#include <vector>

namespace radiant {

// How many input bytes each piece holds: fixed, so the stream's bytes never depend on how many
// threads compressed it.
constexpr size_t deflate_piece_bytes = size_t(64) << 10;

// `data` as a zlib stream (RFC 1950) in consecutive segments, one per piece of input: the first
// starts with the zlib header, the last ends with the checksum. Each piece is deflated on its own,
// primed with the 32 KiB before it so that matches still reach back across the seam, and ends on
// a byte boundary (a sync flush) so that the segments simply concatenate. A piece is run-length
// coded, and also searched at zlib's default level where runs alone shrink it well (the .cpp
// says why). Empty only when zlib fails (out of memory).
std::vector<std::vector<unsigned char>> deflate_in_pieces(const unsigned char* data, size_t size);

}  // namespace radiant

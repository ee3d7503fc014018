#include "image/hdr_header.h"

#include "image/packed_metadata.h"

namespace radiant {

void add_hdr_header_lines(TemporaryFile& file, const ImageMetadata& metadata) {
  std::string lines;
  for (const auto& [name, value] : metadata) lines += name + "=" + escaped_metadata_value(value) + "\n";
  if (lines.empty()) return;
  char start[64];
  std::string first(start, file.read_at(0, start, sizeof start));
  size_t end = first.find('\n');
  if (first.rfind("#?", 0) != 0 || end == std::string::npos) file.fail("the HDR writer wrote no Radiance header");
  file.insert_at(end + 1, lines.data(), lines.size());
}

}  // namespace radiant

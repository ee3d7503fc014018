// Material names as OBJ and MTL files write them: the whole rest of a `usemtl` or `newmtl` line,
// trimmed, spaces included ("usemtl Hard Shiny Plastic White"). tinyobjloader stops a `usemtl`
// name at its first blank, so both kinds of line reach it with the name encoded without blanks,
// and the parsed names are decoded afterwards.
#pragma once

#include <cstddef>
#include <istream>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

namespace radiant {

// `name` without blanks: '%' -> %25, ' ' -> %20, tab -> %09 (decode_material_name reverses it).
std::string encode_material_name(std::string_view name);
std::string decode_material_name(std::string_view encoded);

// A line naming a material, and where it is (1-based, counted as tinyobjloader counts lines).
struct MaterialNameLine {
  size_t line = 0;
  std::string name;  // as written (decoded)
};

// A stream buffer that hands a file to tinyobjloader line by line (ends: \n, \r\n or \r, as its
// reader splits them), each line starting with `keyword` rewritten as `keyword <encoded name>`.
// It holds one line at a time.
class MaterialNameFilter : public std::streambuf {
 public:
  MaterialNameFilter(std::istream& source, std::string keyword);
  // Every `keyword` line passed on so far, in file order.
  const std::vector<MaterialNameLine>& named_lines() const { return named_lines_; }

 protected:
  int_type underflow() override;

 private:
  std::streambuf* source_;
  std::string keyword_;
  std::string line_;
  size_t line_number_ = 0;
  std::vector<MaterialNameLine> named_lines_;
};

}  // namespace radiant

#include "obj/obj_material_names.h"

namespace radiant {

std::string encode_material_name(std::string_view name) {
  std::string encoded;
  encoded.reserve(name.size());
  for (char c : name) {
    if (c == '%') encoded += "%25";
    else if (c == ' ') encoded += "%20";
    else if (c == '\t') encoded += "%09";
    else encoded += c;
  }
  return encoded;
}

std::string decode_material_name(std::string_view encoded) {
  std::string name;
  name.reserve(encoded.size());
  for (size_t i = 0; i < encoded.size(); ++i) {
    std::string_view code = encoded.substr(i, 3);
    if (code == "%25") name += '%';
    else if (code == "%20") name += ' ';
    else if (code == "%09") name += '\t';
    else {
      name += encoded[i];
      continue;
    }
    i += 2;
  }
  return name;
}

MaterialNameFilter::MaterialNameFilter(std::istream& source, std::string keyword)
    : source_(source.rdbuf()), keyword_(std::move(keyword)) {}

MaterialNameFilter::int_type MaterialNameFilter::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  line_.clear();
  int_type c = source_->sbumpc();
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::eof();
  for (; !traits_type::eq_int_type(c, traits_type::eof()); c = source_->sbumpc()) {
    if (c == '\n') break;
    if (c == '\r') {
      if (source_->sgetc() == '\n') source_->sbumpc();
      break;
    }
    line_ += traits_type::to_char_type(c);
  }
  ++line_number_;
  size_t start = line_.find_first_not_of(" \t");
  size_t after = start == std::string::npos ? start : start + keyword_.size();
  if (start != std::string::npos && line_.compare(start, keyword_.size(), keyword_) == 0 &&
      (after == line_.size() || line_[after] == ' ' || line_[after] == '\t')) {
    size_t first = line_.find_first_not_of(" \t", after);
    std::string name = first == std::string::npos ? "" : line_.substr(first, line_.find_last_not_of(" \t") + 1 - first);
    named_lines_.push_back({line_number_, name});
    if (!name.empty()) line_ = keyword_ + " " + encode_material_name(name);
  }
  line_ += '\n';
  setg(line_.data(), line_.data(), line_.data() + line_.size());
  return traits_type::to_int_type(*gptr());
}

}  // namespace radiant

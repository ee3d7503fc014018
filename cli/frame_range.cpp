#include "frame_range.h"

#include <CLI/CLI.hpp>

#include "sampling/hash.h"

namespace radiant::cli {

namespace {

constexpr long long last_frame = 1000000000;

// A frame number as written: digits only, at most 10^9.
long long frame_number(const std::string& flag, const std::string& text, const std::string& whole) {
  if (text.empty() || text.size() > 10 || text.find_first_not_of("0123456789") != std::string::npos ||
      std::stoll(text) > last_frame)
    throw CLI::ValidationError(flag, "expected frames A-B (whole numbers from 0 to 1000000000, A <= B), got '" + whole + "'");
  return std::stoll(text);
}

}  // namespace

FrameRange parse_frame_range(const std::string& flag, const std::string& text) {
  size_t dash = text.find('-');
  FrameRange range;
  range.first = frame_number(flag, text.substr(0, dash), text);
  range.last = dash == std::string::npos ? range.first : frame_number(flag, text.substr(dash + 1), text);
  if (range.last < range.first)
    throw CLI::ValidationError(flag, "the first frame comes after the last in '" + text + "'");
  return range;
}

bool has_frame_placeholder(const std::string& pattern) { return pattern.find('#') != std::string::npos; }

std::string frame_path(const std::string& pattern, long long frame) {
  size_t end = pattern.rfind('#') + 1;
  size_t begin = pattern.find_last_not_of('#', end - 1) + 1;  // npos + 1 == 0: the run starts the path
  std::string number = std::to_string(frame);
  if (number.size() < end - begin) number.insert(0, end - begin - number.size(), '0');
  return pattern.substr(0, begin) + number + pattern.substr(end);
}

uint32_t frame_seed(uint32_t seed, long long frame) { return hash_combine(mix_bits(seed), uint32_t(frame)); }

}  // namespace radiant::cli

// A libFuzzer custom mutator for the text targets (scene, glTF, render, OBJ, batch): one
// mutation in four swaps a number of the input for a hostile magnitude (past Embree's ray limit
// of about 1.8e18, at the edges of float and int, zero, denormals). Byte-level mutation rarely
// turns "1000" into "2e18", yet whole-render number mutation is what found the Embree abort
// class; the other three mutations are libFuzzer's own.
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string_view>
#include <vector>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

constexpr std::string_view hostile_numbers[] = {
    "2e18", "-2e18", "1e19", "1e30", "-1e30", "3.4e38", "-3.4e38", "1e38", "1e-30", "1e-45", "0", "-0",
    "1e10", "1e6", "-1e7", "65536", "65537", "2147483648", "-2147483649", "4294967296", "1e308"};

bool is_number_char(uint8_t c) { return std::isdigit(c) || c == '.' || c == 'e' || c == 'E' || c == '-' || c == '+'; }

// Start and length of every number in `data`: a digit run with its sign, fraction and exponent,
// not part of a name (TEXCOORD_0, v2).
std::vector<std::pair<size_t, size_t>> find_numbers(const uint8_t* data, size_t size) {
  std::vector<std::pair<size_t, size_t>> numbers;
  for (size_t i = 0; i < size; ++i) {
    bool starts = std::isdigit(data[i]) || ((data[i] == '-' || data[i] == '.') && i + 1 < size && std::isdigit(data[i + 1]));
    if (!starts || (i > 0 && (std::isalnum(data[i - 1]) || data[i - 1] == '_' || data[i - 1] == '.'))) continue;
    size_t end = i + 1;
    while (end < size && is_number_char(data[end])) ++end;
    numbers.emplace_back(i, end - i);
    i = end;
  }
  return numbers;
}

// Replaces one number of `data` by a hostile one; returns the new size, or 0 if there is none
// or it would not fit in `max_size`.
size_t replace_one_number(uint8_t* data, size_t size, size_t max_size, std::minstd_rand& random) {
  std::vector<std::pair<size_t, size_t>> numbers = find_numbers(data, size);
  if (numbers.empty()) return 0;
  auto [at, length] = numbers[random() % numbers.size()];
  std::string_view value = hostile_numbers[random() % std::size(hostile_numbers)];
  size_t new_size = size - length + value.size();
  if (new_size > max_size) return 0;
  std::memmove(data + at + value.size(), data + at + length, size - at - length);
  std::memcpy(data + at, value.data(), value.size());
  return new_size;
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
  std::minstd_rand random(seed);
  if (random() % 4 == 0)
    if (size_t new_size = replace_one_number(data, size, max_size, random)) return new_size;
  return LLVMFuzzerMutate(data, size, max_size);
}

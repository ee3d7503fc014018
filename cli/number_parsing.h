// Numbers on the command line: finite as floats, alone or in comma-separated lists.
#pragma once

#include <CLI/CLI.hpp>

#include <limits>
#include <string>
#include <vector>

#include "math/vec.h"

namespace radiant::cli {

// Validators for numeric flags. CLI11's Range and PositiveNumber let NaN through (every
// comparison with it is false) and check a double, while most flags are stored in a float:
// these take numbers finite in a float and in [low, high], or (0, high] for the positive one.
CLI::Validator number_in(double low, double high);
CLI::Validator positive_number(double high = std::numeric_limits<float>::max());

// The parts of `text` between separators.
std::vector<std::string> split(const std::string& text, char separator);
// A number whose float is finite; `used` is how much of `text` it took (0 when none).
bool read_float_number(const std::string& text, double& value, size_t& used);

// Each throws CLI::ValidationError naming `flag` on bad input.
double parse_number(const std::string& flag, const std::string& text);
vec3 parse_vec3(const std::string& flag, const std::string& text);
// Comma-separated numbers, as many as given.
std::vector<float> parse_numbers(const std::string& flag, const std::string& text);

}  // namespace radiant::cli

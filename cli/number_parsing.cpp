#include "number_parsing.h"

#include <cmath>
#include <functional>
#include <sstream>

namespace radiant::cli {

namespace {

constexpr double largest_float = std::numeric_limits<float>::max();

// A validator accepting numbers finite in a float that `accept` takes; `what` describes them.
CLI::Validator number_validator(std::function<bool(double)> accept, const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        size_t used = 0;
        if (!read_float_number(text, value, used) || !accept(value)) return "must be " + what + ", not " + text;
        return "";
      },
      what);
}

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

bool read_float_number(const std::string& text, double& value, size_t& used) {
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  return used > 0 && used == text.size() && std::abs(value) <= largest_float;
}

double parse_number(const std::string& flag, const std::string& text) {
  double value = 0;
  size_t used = 0;
  if (!read_float_number(text, value, used)) throw CLI::ValidationError(flag, "'" + text + "' is not a finite number");
  return value;
}

CLI::Validator number_in(double low, double high) {
  return number_validator([=](double v) { return v >= low && v <= high; },
                          "a number in [" + number_text(low) + ", " + number_text(high) + "]");
}

CLI::Validator positive_number(double high) {
  return number_validator([=](double v) { return v > 0 && v <= high; },
                          "a number in (0, " + number_text(high) + "]");
}

std::vector<float> parse_numbers(const std::string& flag, const std::string& text) {
  std::vector<float> numbers;
  for (const std::string& part : split(text, ',')) numbers.push_back(float(parse_number(flag, part)));
  return numbers;
}

vec3 parse_vec3(const std::string& flag, const std::string& text) {
  auto parts = split(text, ',');
  if (parts.size() != 3) throw CLI::ValidationError(flag, "expected X,Y,Z (three comma-separated numbers), got '" + text + "'");
  return {float(parse_number(flag, parts[0])), float(parse_number(flag, parts[1])), float(parse_number(flag, parts[2]))};
}

}  // namespace radiant::cli

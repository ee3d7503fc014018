#include "scene_format/scene_format_values.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "scene/enum_names.h"

namespace radiant::scene_format {

// ---------------------------------------------------------------- attribute names

static std::string list_names(const std::vector<AttributeName>& accepted) {
  std::string list;
  for (const AttributeName& name : accepted) list += (list.empty() ? "" : ", ") + name.name;
  return list;
}

static const AttributeName* match(const std::vector<AttributeName>& accepted, const std::string& text) {
  for (const AttributeName& name : accepted)
    if (text == name.name || (!name.alias.empty() && text == name.alias)) return &name;
  return nullptr;
}

Attributes index_attributes(const BuildContext& context, const Block& block,
                            const std::vector<AttributeName>& accepted, const std::string& what) {
  Attributes attributes;
  attributes.block = &block;
  attributes.accepted = accepted;
  for (const Attribute& attribute : block.attributes) {
    const AttributeName* name = match(accepted, attribute.name.text);
    if (!name)
      fail(context, attribute.name, "unknown attribute " + quote(attribute.name.text) + " in " + what +
                                        " (expected " + list_names(accepted) + ")");
    auto [existing, inserted] = attributes.by_name.emplace(name->name, &attribute);
    if (!inserted) {
      const Token& first = existing->second->name;
      std::string as = first.text == attribute.name.text ? "" : " as " + quote(first.text);
      fail(context, attribute.name, "duplicate attribute " + quote(attribute.name.text) +
                                        " (already given at line " + std::to_string(first.line) + as + ")");
    }
  }
  return attributes;
}

const Attribute* find(const Attributes& attributes, const std::string& name) {
  auto found = attributes.by_name.find(name);
  return found == attributes.by_name.end() ? nullptr : found->second;
}

const Attribute& require(const BuildContext& context, const Attributes& attributes,
                         const std::string& name, const std::string& what) {
  const Attribute* attribute = find(attributes, name);
  if (!attribute) {
    const AttributeName* accepted = match(attributes.accepted, name);
    std::string alias = accepted && !accepted->alias.empty() ? " (or " + quote(accepted->alias) + ")" : "";
    fail(context, attributes.block->header, "missing required attribute " + quote(name) + alias + " in " + what);
  }
  return *attribute;
}

void expect_block_arguments(const BuildContext& context, const Block& block, size_t count) {
  if (block.arguments.size() <= count) return;
  const Token& extra = block.arguments[count];
  fail(context, extra, "unexpected " + quote(extra.text) + " after " + quote(block.header.text) +
                           (count == 0 ? " (this block takes no name)" : ""));
}

// ---------------------------------------------------------------- numbers

float parse_number(const BuildContext& context, const Token& token) {
  std::string_view text = token.text;
  // from_chars refuses a leading '+', which people write ("+3").
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range)
    fail(context, token, "number " + quote(token.text) + " is out of range");
  if (error != std::errc() || end != text.data() + text.size())
    fail(context, token, "expected a number, got " + quote(token.text));
  if (std::isnan(value) || std::isinf(value))
    fail(context, token, "expected a finite number, got " + quote(token.text));
  if (!std::isfinite(float(value))) fail(context, token, "number " + quote(token.text) + " is out of range");
  return float(value);
}

void expect_arguments(const BuildContext& context, const Attribute& attribute, size_t count,
                      const std::string& of_what) {
  if (attribute.arguments.size() != count)
    fail(context, attribute.name, quote(attribute.name.text) + " expects " + of_what + ", got " +
                                      std::to_string(attribute.arguments.size()));
}

float read_number(const BuildContext& context, const Attribute& attribute) {
  expect_arguments(context, attribute, 1, "1 number");
  return parse_number(context, attribute.arguments[0]);
}

float read_positive(const BuildContext& context, const Attribute& attribute) {
  float value = read_number(context, attribute);
  if (!(value > 0))
    fail(context, attribute.arguments[0],
         quote(attribute.name.text) + " must be positive, got " + shortened(attribute.arguments[0].text));
  return value;
}

float read_non_negative(const BuildContext& context, const Attribute& attribute) {
  float value = read_number(context, attribute);
  if (value < 0)
    fail(context, attribute.arguments[0],
         quote(attribute.name.text) + " must not be negative, got " + shortened(attribute.arguments[0].text));
  return value;
}

vec3 read_vec3(const BuildContext& context, const Attribute& attribute) {
  expect_arguments(context, attribute, 3, "3 numbers");
  return {parse_number(context, attribute.arguments[0]), parse_number(context, attribute.arguments[1]),
          parse_number(context, attribute.arguments[2])};
}

vec3 read_direction(const BuildContext& context, const Attribute& attribute) {
  vec3 value = read_vec3(context, attribute);
  float scale = max_component(abs(value));
  // Dividing by the largest component first keeps tiny and huge vectors from under/overflowing.
  if (scale == 0) fail(context, attribute.name, quote(attribute.name.text) + " must not be zero-length");
  return normalize(value / scale);
}

color3 read_color(const BuildContext& context, const Attribute& attribute) {
  size_t count = attribute.arguments.size();
  if (count != 1 && count != 3)
    fail(context, attribute.name,
         quote(attribute.name.text) + " expects 1 or 3 numbers, got " + std::to_string(count));
  color3 color;
  for (size_t i = 0; i < 3; ++i) {
    const Token& token = attribute.arguments[count == 1 ? 0 : i];
    color[int(i)] = parse_number(context, token);
    if (color[int(i)] < 0)
      fail(context, token, quote(attribute.name.text) + " must not be negative, got " + shortened(token.text));
  }
  return color;
}

std::vector<float> read_numbers(const BuildContext& context, const Attribute& attribute) {
  if (attribute.arguments.empty())
    fail(context, attribute.name, quote(attribute.name.text) + " expects numbers, got none");
  std::vector<float> numbers;
  for (const Token& token : attribute.arguments) numbers.push_back(parse_number(context, token));
  return numbers;
}

int parse_integer(const BuildContext& context, const Token& token, const std::string& what, int min, int max) {
  std::string_view text = token.text;
  if (text.size() > 1 && text[0] == '+') text.remove_prefix(1);
  int value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc() && end != text.data() + text.size()) error = std::errc::invalid_argument;
  if (error == std::errc::invalid_argument) fail(context, token, "expected a whole number, got " + quote(token.text));
  if (error != std::errc() || value < min || value > max)
    fail(context, token, quote(what) + " must be between " + std::to_string(min) + " and " +
                             std::to_string(max) + ", got " + shortened(token.text));
  return value;
}

int read_integer(const BuildContext& context, const Attribute& attribute, int min, int max) {
  expect_arguments(context, attribute, 1, "1 number");
  return parse_integer(context, attribute.arguments[0], attribute.name.text, min, max);
}

// ---------------------------------------------------------------- words

std::string read_word(const BuildContext& context, const Attribute& attribute) {
  expect_arguments(context, attribute, 1, "1 word");
  return attribute.arguments[0].text;
}

bool read_boolean(const BuildContext& context, const Attribute& attribute) {
  std::string word = read_word(context, attribute);
  // Any case, as the Scala path tracer's reader took them (`s True`, `s FALSE`).
  std::string lower = word;
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (lower != "true" && lower != "false")
    fail(context, attribute.arguments[0], "expected true or false, got " + quote(word));
  return lower == "true";
}

int read_choice(const BuildContext& context, const Attribute& attribute,
                const std::vector<std::string>& choices) {
  std::string word = read_word(context, attribute);
  for (size_t i = 0; i < choices.size(); ++i)
    if (word == choices[i]) return int(i);
  fail(context, attribute.arguments[0],
       "unknown " + attribute.name.text + " " + quote(word) + " (expected " + choices_text(choices) + ")");
}

}  // namespace radiant::scene_format

// Reading attribute arguments of the .scene format: numbers, vectors, colors, words, and the
// check of a block's attribute names. Every failure names the line and column.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "math/vec.h"
#include "scene_format/scene_format_context.h"

namespace radiant::scene_format {

// An attribute name a block accepts, and an optional alias meaning the same (the older
// format's one-letter names, e.g. `p` for `position`).
struct AttributeName {
  std::string name;
  std::string alias;
};

// The attributes of one block by accepted name (aliases resolved).
struct Attributes {
  const Block* block = nullptr;
  std::vector<AttributeName> accepted;
  std::map<std::string, const Attribute*> by_name;
};

// Checks that every attribute of `block` is accepted and given once. `what` names the block in
// messages (e.g. "@sphere" or "@light point").
Attributes index_attributes(const BuildContext& context, const Block& block,
                            const std::vector<AttributeName>& accepted, const std::string& what);
// The attribute, or nullptr when absent.
const Attribute* find(const Attributes& attributes, const std::string& name);
// The attribute; a missing one is an error at the block header.
const Attribute& require(const BuildContext& context, const Attributes& attributes,
                         const std::string& name, const std::string& what);
// Fails unless the block header has at most `count` arguments.
void expect_block_arguments(const BuildContext& context, const Block& block, size_t count);

// A finite number; NaN, infinities, and trailing characters are errors.
float parse_number(const BuildContext& context, const Token& token);

float read_number(const BuildContext& context, const Attribute& attribute);
float read_positive(const BuildContext& context, const Attribute& attribute);
float read_non_negative(const BuildContext& context, const Attribute& attribute);
vec3 read_vec3(const BuildContext& context, const Attribute& attribute);
// A direction or normal: three numbers, not all zero; returned normalised.
vec3 read_direction(const BuildContext& context, const Attribute& attribute);
// One number (grey) or three (per channel), each >= 0.
color3 read_color(const BuildContext& context, const Attribute& attribute);
// Any count of numbers (at least one).
std::vector<float> read_numbers(const BuildContext& context, const Attribute& attribute);
// A whole number in [min, max]; `what` names it in messages.
int parse_integer(const BuildContext& context, const Token& token, const std::string& what, int min, int max);
int read_integer(const BuildContext& context, const Attribute& attribute, int min, int max);
bool read_boolean(const BuildContext& context, const Attribute& attribute);
// One word, which must be one of `choices`; returns its index in `choices`.
int read_choice(const BuildContext& context, const Attribute& attribute,
                const std::vector<std::string>& choices);
std::string read_word(const BuildContext& context, const Attribute& attribute);
// The value `table` (scene/enum_names.h) names by the attribute's one word; fails as read_choice.
template <class Enum, size_t N>
Enum read_named(const BuildContext& context, const Attribute& attribute, const std::pair<Enum, const char*> (&table)[N]) {
  std::vector<std::string> choices;
  for (const auto& entry : table) choices.push_back(entry.second);
  return table[read_choice(context, attribute, choices)].first;
}

// Fails at the attribute name unless it has exactly `count` arguments.
void expect_arguments(const BuildContext& context, const Attribute& attribute, size_t count,
                      const std::string& of_what);

}  // namespace radiant::scene_format

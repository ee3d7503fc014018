// The JSON documents radiant writes (--stats, info --json, compare --json, converge's report),
// built with nlohmann/json rather than by hand, so that each is valid JSON whatever its strings
// hold: quotes, control characters and invalid UTF-8 in file and scene names included.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

#include "math/vec.h"

namespace radiant::cli {

using Json = nlohmann::ordered_json;  // keys in the order they are added

// JSON has no NaN or infinity: a value that is not finite is null.
inline Json json_number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }
inline Json json_vec3(vec3 v) { return Json::array({json_number(v.x), json_number(v.y), json_number(v.z)}); }

// The document as text: indented (or on one line), bytes that are not UTF-8 replaced by U+FFFD,
// and a final newline.
inline std::string json_text(const Json& document, bool one_line = false) {
  return document.dump(one_line ? -1 : 2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace radiant::cli

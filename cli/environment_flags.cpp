#include "environment_flags.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <cmath>
#include <optional>
#include <vector>

#include "number_parsing.h"
#include "render/render_option_names.h"

namespace radiant::cli {

namespace {

std::string lower_case(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

void parse_environment_choice(const std::string& text, RenderOptions& options) {
  if (std::optional<EnvironmentPreset> preset = value_named(environment_preset_names, text)) options.env_preset = *preset;
  else if (text.empty()) throw CLI::ValidationError("--env", "needs studio, white, none or an image file");
  else options.env_map = text;
}

void parse_background(const std::string& text, RenderOptions& options) {
  std::string name = lower_case(text);
  if (name == "env" || name == "environment") options.background = BackgroundKind::environment;
  else if (name == "blur") options.background = BackgroundKind::blur;
  else if (name == "transparent") options.background = BackgroundKind::transparent;
  else if (name.rfind("color:", 0) == 0) {
    vec3 c = parse_vec3("--background", text.substr(6));
    if (min_component(c) < 0) throw CLI::ValidationError("--background", "a colour cannot be negative");
    options.background = BackgroundKind::color;
    options.background_color = c;
  } else {
    throw CLI::ValidationError("--background", "expected env, blur, transparent or color:R,G,B, got '" + text + "'");
  }
}

vec3 parse_up(const std::string& flag, const std::string& text) {
  std::string axis = lower_case(text);
  if (axis.size() == 1) axis = "+" + axis;
  if (axis.size() == 2 && (axis[0] == '+' || axis[0] == '-') && axis[1] >= 'x' && axis[1] <= 'z') {
    vec3 up = {0, 0, 0};
    up[axis[1] - 'x'] = axis[0] == '-' ? -1.0f : 1.0f;
    return up;
  }
  vec3 up = parse_vec3(flag, text);
  if (!(length(up) > 0)) throw CLI::ValidationError(flag, "must be an axis (+Z, -Y ...) or a non-zero vector X,Y,Z");
  return up;
}

Orbit parse_orbit(const std::string& flag, const std::string& text) {
  std::vector<float> numbers = parse_numbers(flag, text);
  if (numbers.size() < 2 || numbers.size() > 3)
    throw CLI::ValidationError(flag, "expected AZIMUTH,ELEVATION[,DISTANCE], got '" + text + "'");
  Orbit orbit{numbers[0], numbers[1], numbers.size() == 3 ? numbers[2] : 1.0f};
  if (!(std::abs(orbit.azimuth_degrees) <= 36000 && std::abs(orbit.elevation_degrees) <= 36000))
    throw CLI::ValidationError(flag, "angles must be in [-36000, 36000] degrees");
  if (!(orbit.distance > 0 && orbit.distance <= 1e6))
    throw CLI::ValidationError(flag, "the distance is a multiple of the framing distance, in (0, 1e6]");
  return orbit;
}

}  // namespace radiant::cli

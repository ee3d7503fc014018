// The value syntaxes of the flags that light and frame a model: --env, --background, --up and
// --orbit (docs/cli.md, "Lighting and framing a model").
#pragma once

#include <string>

#include "render/render_options.h"

namespace radiant::cli {

// --env NAME|FILE: studio, white or none set options.env_preset; anything else is a map file
// (./studio reaches a file of that name).
void parse_environment_choice(const std::string& text, RenderOptions& options);
// --background env|blur|transparent|color:R,G,B
void parse_background(const std::string& text, RenderOptions& options);
// --up: an axis (+Z, -y, x ...) or X,Y,Z.
vec3 parse_up(const std::string& flag, const std::string& text);
// --orbit AZIMUTH,ELEVATION[,DISTANCE] in degrees, and a multiple of the framing distance.
Orbit parse_orbit(const std::string& flag, const std::string& text);

}  // namespace radiant::cli

// Environment maps: read from a file or made (the built-in studio), how a world direction finds
// its texel, and the blurred copy a camera sees behind the scene (--background blur).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/image_io_module.h"
#include "math/vec.h"
#include "memory/memory_budget.h"
#include "sampling/distribution.h"

namespace radiant {

// An equirectangular environment map, importance-sampled by luminance.
struct EnvironmentMap {
  int width = 0, height = 0;
  std::vector<color3> texels;      // linear radiance, top row first (the map's up is the top)
  Distribution2D distribution;     // over (u, v) in [0,1)^2, by luminance * sin(theta) / texel count
  // A small, blurred copy for what camera rays see behind the scene (--background blur).
  int backdrop_width = 0, backdrop_height = 0;
  std::vector<color3> backdrop;
  size_t negative_texels = 0;      // read as 0: tiny negatives are common in saved renders
  float most_negative = 0;
  MemoryCharge memory;             // its texels and tables (and their reading), against the budget
};

// The map's axes in world space: y is the map's up (its top row), x the direction its centre
// faces. With +y up and no rotation, x is +x, as in Blender (after glTF's y-up import) and three.js.
struct EnvironmentFrame {
  vec3 x = {1, 0, 0}, y = {0, 1, 0}, z = {0, 0, 1};
};

// The frame for a world whose up is `up` (unit), turned by `rotation_degrees` about it,
// counterclockwise seen from above: at 90 the map's centre moves from +x to -z (with +y up).
EnvironmentFrame make_environment_frame(vec3 up, float rotation_degrees);
inline vec3 to_environment(const EnvironmentFrame& f, vec3 d) { return {dot(d, f.x), dot(d, f.y), dot(d, f.z)}; }
inline vec3 from_environment(const EnvironmentFrame& f, vec3 d) { return f.x * d.x + f.y * d.y + f.z * d.z; }

// Map coordinates of a unit direction in the map's frame: u = 0.5 faces +x, u = 0.75 faces +z,
// v = 0 is straight up.
vec2 environment_uv(vec3 local);
// The direction of map coordinates `uv`, with the sine of its polar angle (the map's Jacobian).
vec3 environment_direction(vec2 uv, float& sin_theta);

// The texel at `uv` (nearest), and the blurred backdrop there (bilinear).
color3 environment_texel(const EnvironmentMap& map, vec2 uv);
color3 environment_backdrop(const EnvironmentMap& map, vec2 uv);

// Opens an environment map and checks its header (readable, of a usable size): what `batch`
// checks of every view before rendering. Throws std::runtime_error naming the file
// (MemoryLimitError when decoding it needs more than `budget` has; the source holds that charge).
std::unique_ptr<ImageSource> open_environment_map(const std::string& path, MemoryBudget* budget);
// Reads a map, charging `budget` first. NaN and infinite texels are refused (naming the pixel
// and channel); negative ones are read as 0 and counted.
EnvironmentMap load_environment_map(const std::string& path, MemoryBudget* budget);
// The built-in neutral studio (docs/lights.md, "Default lighting"): a grey room with a soft
// overhead key, two side softboxes and a darker floor, made at a fixed size and charged.
EnvironmentMap make_studio_environment(MemoryBudget* budget);

}  // namespace radiant

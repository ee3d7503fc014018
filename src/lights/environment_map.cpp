#include "lights/environment_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "image/image_io.h"

namespace radiant {

namespace {

constexpr int backdrop_width = 64, backdrop_height = 32;
constexpr int studio_width = 512, studio_height = 256;
constexpr float studio_backdrop_dimming = 0.45f;

// Bytes a map of `texels` texels holds: texels, sampling weights and tables, and the backdrop.
uint64_t environment_map_bytes(uint64_t texels, uint64_t read_bytes_per_texel) {
  uint64_t per_texel = read_bytes_per_texel + sizeof(color3) + 5 * sizeof(float);
  return saturating_multiply(texels, per_texel) + 2 * uint64_t(backdrop_width) * backdrop_height * sizeof(color3);
}

// A texel must be finite; a negative one (saved renders carry -1e-5 and the like) reads as 0.
color3 checked_texel(const std::string& path, const ImageHeader& spec, int x, int y, color3 c, EnvironmentMap& map) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(c[k])) {
      std::string channel = spec.channels >= 3 ? spec.channel_names[size_t(k)] : spec.channel_names[0];
      std::ostringstream value;
      value << c[k];
      throw std::runtime_error(path + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): " + channel +
                               " is " + value.str() + ": environment radiance must be finite");
    }
  }
  if (min_component(c) < 0) {
    ++map.negative_texels;
    map.most_negative = std::min(map.most_negative, min_component(c));
    c = max(c, {0, 0, 0});
  }
  return c;
}

// The backdrop: the map averaged down to a small grid, then blurred by three passes of a box
// filter (close to a Gaussian of about 12 degrees), wrapping around in longitude.
void make_backdrop(EnvironmentMap& map) {
  int w = backdrop_width, h = backdrop_height;
  std::vector<color3> grid(size_t(w) * h), pass(grid.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int x0 = x * map.width / w, x1 = std::max(x0 + 1, (x + 1) * map.width / w);
      int y0 = y * map.height / h, y1 = std::max(y0 + 1, (y + 1) * map.height / h);
      color3 sum;
      for (int v = y0; v < y1; ++v)
        for (int u = x0; u < x1; ++u) sum += map.texels[size_t(v) * map.width + u];
      grid[size_t(y) * w + x] = sum / float((x1 - x0) * (y1 - y0));
    }
  constexpr int radius = 2;
  for (int round = 0; round < 3; ++round) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        color3 sum;
        for (int k = -radius; k <= radius; ++k) sum += grid[size_t(y) * w + size_t((x + k + w) % w)];
        pass[size_t(y) * w + x] = sum / float(2 * radius + 1);
      }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        color3 sum;
        for (int k = -radius; k <= radius; ++k) sum += pass[size_t(std::clamp(y + k, 0, h - 1)) * w + x];
        grid[size_t(y) * w + x] = sum / float(2 * radius + 1);
      }
  }
  map.backdrop_width = w, map.backdrop_height = h;
  map.backdrop = std::move(grid);
}

// Importance weights by luminance and solid angle; divided by the texel count, so that their sum
// (the distribution's total, a float) is the map's mean and cannot overflow.
void finish_map(EnvironmentMap& map) {
  std::vector<float> weights(map.texels.size());
  for (int y = 0; y < map.height; ++y) {
    float sin_theta = std::sin(pi * (float(y) + 0.5f) / float(map.height));
    for (int x = 0; x < map.width; ++x) {
      size_t i = size_t(y) * map.width + x;
      weights[i] = float(double(luminance(map.texels[i])) * sin_theta / double(map.texels.size()));
    }
  }
  map.distribution = make_distribution_2d(weights, map.width, map.height);
  make_backdrop(map);
}

// 1 inside a cap of `radius` radians around unit `axis`, falling smoothly to 0 over `soft`.
float softbox(vec3 d, vec3 axis, float radius, float soft) {
  float angle = std::acos(std::clamp(dot(d, axis), -1.0f, 1.0f));
  float t = std::clamp((radius + soft - angle) / (2 * soft), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

// The studio's radiance along a direction of its own frame (y up, the camera's side +z).
color3 studio_radiance(vec3 d) {
  constexpr float degree = pi / 180;
  // Walls brighten towards the ceiling; the floor is darker; the horizon is a soft step.
  float elevation = std::asin(std::clamp(d.y, -1.0f, 1.0f));
  float above = std::clamp((elevation + 4 * degree) / (8 * degree), 0.0f, 1.0f);
  float wall = 0.38f + 0.16f * std::max(d.y, 0.0f);
  float radiance = 0.145f + (wall - 0.145f) * above * above * (3 - 2 * above);
  // A large key overhead, towards the camera and to its right; a fill to the left; a rim behind.
  radiance += 2.9f * softbox(d, normalize(vec3{0.35f, 1.3f, 0.8f}), 22 * degree, 5 * degree);
  radiance += 1.45f * softbox(d, normalize(vec3{-1.0f, 0.35f, 0.35f}), 18 * degree, 5 * degree);
  radiance += 1.45f * softbox(d, normalize(vec3{0.7f, 0.75f, -1.0f}), 14 * degree, 4 * degree);
  return {radiance, radiance, radiance};
}

}  // namespace

EnvironmentFrame make_environment_frame(vec3 up, float rotation_degrees) {
  EnvironmentFrame f;
  f.y = normalize(up);
  // The map's centre faces +x when +x is level; otherwise -z, then +y, level with `up`.
  vec3 centre = {1, 0, 0};
  if (std::abs(dot(centre, f.y)) > 0.999f) centre = {0, 0, -1};
  f.x = normalize(centre - f.y * dot(centre, f.y));
  f.z = cross(f.x, f.y);
  float turn = rotation_degrees * pi / 180, c = std::cos(turn), s = std::sin(turn);
  vec3 x = f.x * c - f.z * s, z = f.x * s + f.z * c;  // counterclockwise about y seen from above
  f.x = x, f.z = z;
  return f;
}

vec2 environment_uv(vec3 d) {
  return {0.5f + std::atan2(d.z, d.x) / (2 * pi), std::acos(std::clamp(d.y, -1.0f, 1.0f)) / pi};
}

vec3 environment_direction(vec2 uv, float& sin_theta) {
  float phi = (uv.x - 0.5f) * 2 * pi, theta = uv.y * pi;
  sin_theta = std::sin(theta);
  return {sin_theta * std::cos(phi), std::cos(theta), sin_theta * std::sin(phi)};
}

color3 environment_texel(const EnvironmentMap& map, vec2 uv) {
  int x = std::clamp(int(uv.x * float(map.width)), 0, map.width - 1);
  int y = std::clamp(int(uv.y * float(map.height)), 0, map.height - 1);
  return map.texels[size_t(y) * map.width + x];
}

color3 environment_backdrop(const EnvironmentMap& map, vec2 uv) {
  int w = map.backdrop_width, h = map.backdrop_height;
  float fx = uv.x * float(w) - 0.5f, fy = std::clamp(uv.y * float(h) - 0.5f, 0.0f, float(h - 1));
  int x0 = int(std::floor(fx)), y0 = std::min(int(fy), h - 1), y1 = std::min(y0 + 1, h - 1);
  float tx = fx - float(x0), ty = fy - float(y0);
  auto at = [&](int x, int y) { return map.backdrop[size_t(y) * w + size_t(((x % w) + w) % w)]; };
  return lerp(lerp(at(x0, y0), at(x0 + 1, y0), tx), lerp(at(x0, y1), at(x0 + 1, y1), tx), ty);
}

std::unique_ptr<ImageSource> open_environment_map(const std::string& path, MemoryBudget* budget) {
  std::string error;
  auto input = open_image_file(path, error, budget);
  if (!input) throw std::runtime_error(path + ": cannot read environment map: " + error);
  const ImageHeader& spec = input->header();
  if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0 ||
      size_t(spec.width) * spec.height > (size_t(1) << 28))
    throw std::runtime_error(path + ": environment map has an unusable size");
  return input;
}

EnvironmentMap load_environment_map(const std::string& path, MemoryBudget* budget) {
  std::unique_ptr<ImageSource> input = open_environment_map(path, budget);
  const ImageHeader& spec = input->header();
  // The float pixels read (OpenImageIO's copy is the source's charge), then texels, weights,
  // the sampling tables and the backdrop.
  uint64_t texels = uint64_t(spec.width) * uint64_t(spec.height);
  MemoryCharge memory(budget, environment_map_bytes(texels, 4 * uint64_t(spec.channels)),
                      path + ": a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                          " environment map");
  std::vector<float> pixels(size_t(spec.width) * spec.height * spec.channels);
  if (!input->read(spec.channels, PixelType::float32, pixels.data()))
    throw std::runtime_error(path + ": cannot read environment map: " + input->error());
  EnvironmentMap map;
  map.memory = std::move(memory);
  map.width = spec.width;
  map.height = spec.height;
  map.texels.resize(size_t(map.width) * map.height);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      size_t i = size_t(y) * map.width + x;
      const float* p = &pixels[i * spec.channels];
      color3 c = spec.channels >= 3 ? color3{p[0], p[1], p[2]} : color3{p[0], p[0], p[0]};
      map.texels[i] = checked_texel(path, spec, x, y, c, map);
    }
  finish_map(map);
  return map;
}

EnvironmentMap make_studio_environment(MemoryBudget* budget) {
  EnvironmentMap map;
  map.memory = MemoryCharge(budget, environment_map_bytes(uint64_t(studio_width) * studio_height, 0),
                            "the built-in studio environment");
  map.width = studio_width, map.height = studio_height;
  map.texels.resize(size_t(map.width) * map.height);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      float sin_theta;
      vec3 d = environment_direction({(float(x) + 0.5f) / float(map.width), (float(y) + 0.5f) / float(map.height)}, sin_theta);
      map.texels[size_t(y) * map.width + x] = studio_radiance(d);
    }
  finish_map(map);
  // Seen behind the model, the walls are darker than they light it, so that a white or grey
  // model stands out from them (as a photographer's backdrop is lit less than the subject).
  for (color3& c : map.backdrop) c = c * studio_backdrop_dimming;
  return map;
}

}  // namespace radiant

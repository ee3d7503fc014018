#include "render/settings_hash.h"

#include <bit>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "math/fnv_hash.h"
#include "sampling/sampler.h"

namespace radiant {

namespace {

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// Floats by their bits: two settings that print alike but differ in the last bit differ here.
void put(std::ostream& out, float value) { out << std::bit_cast<uint32_t>(value) << ' '; }
void put(std::ostream& out, vec3 v) { put(out, v.x), put(out, v.y), put(out, v.z); }

}  // namespace

std::string files_hash(const std::vector<std::string>& paths) {
  uint64_t hash = fnv_offset;
  std::vector<char> buffer(1 << 16);
  for (const std::string& path : paths) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot be read to hash the scene");
    while (in) {
      in.read(buffer.data(), std::streamsize(buffer.size()));
      hash = fnv1a(hash, buffer.data(), size_t(in.gcount()));
    }
    if (in.bad()) throw std::runtime_error(path + ": a read failed while hashing the scene");
  }
  return hex(hash);
}

std::string text_hash(const std::string& text) { return hex(fnv1a(fnv_offset, text.data(), text.size())); }

std::string settings_hash(const ResolvedSettings& s, const RenderOptions& options) {
  std::ostringstream text;
  text << s.width << ' ' << s.height << ' ' << int(s.mode) << ' ' << s.max_depth << ' ' << int(s.sampler) << ' '
       << options.seed << ' ' << (sampler_extends(s.sampler) ? 0 : s.spp) << ' ';
  if (s.indirect_paths != 1) text << "indirect-paths " << s.indirect_paths << ' ';  // earlier hashes unchanged
  const CameraDesc& c = s.camera;
  text << int(c.projection) << ' ';
  put(text, c.position), put(text, c.forward), put(text, c.up);
  put(text, c.vertical_fov_degrees), put(text, c.ortho_height), put(text, c.aspect);
  const EnvironmentSpec& e = s.environment;
  put(text, e.color);
  text << e.map_path << '\n' << s.effects << ' ' << s.compiled_variant << ' ';
  // Only what differs from a plain uniform or file environment, so that their hashes stay.
  if (e.studio) text << "studio ";
  if (e.map_scale != 1) put(text, e.map_scale);
  if (e.frame.x.x != 1 || e.frame.y.y != 1) put(text, e.frame.x), put(text, e.frame.y);
  if (s.background != BackgroundKind::blur) text << "background " << int(s.background) << ' ', put(text, s.background_color);
  put(text, options.contribution_cutoff);
  text << int(options.texture_filter) << ' ';
  // Only when changed from the default 1 pixel, so that earlier hashes stay.
  if (options.line_width.value != 1 || !options.line_width.in_pixels)
    text << "line-width " << (options.line_width.in_pixels ? "px " : "world "), put(text, options.line_width.value);
  text << (options.aovs.empty() ? "no-aov-sums" : "aov-sums");
  text << (s.transparent ? " transparent " : " opaque ") << int(s.filter) << ' ';
  put(text, s.filter_radius);
  return text_hash(text.str());
}

}  // namespace radiant

#include "image/render_metadata.h"

#include <charconv>
#include <cstdio>
#include <stdexcept>

namespace radiant {

namespace {

constexpr const char* software_prefix = "radiant ";

std::string format_number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

template <typename Number>
Number parse_number(const std::string& name, const std::string& text) {
  Number value{};
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty())
    throw std::runtime_error(name + " '" + text + "' is not a number");
  return value;
}

}  // namespace

ImageMetadata render_metadata(const RenderRecord& r) {
  double rays_per_second = r.render_seconds > 0 ? double(r.rays) / r.render_seconds : 0;
  ImageMetadata metadata = {
      {"Software", software_prefix + r.version},
      {"Comment", r.command_line},
      {"radiant:scene", r.scene},
      {"radiant:mode", r.mode},
      {"radiant:sampler", r.sampler},
      {"radiant:spp", std::to_string(r.spp)},
      {"radiant:seed", std::to_string(r.seed)},
      {"radiant:render_seconds", format_number("%.6g", r.render_seconds)},
      {"radiant:rays", std::to_string(r.rays)},
      {"radiant:rays_per_second", format_number("%.0f", rays_per_second)},
  };
  // Only a denoised image says so: every other image keeps the attributes it always had.
  if (r.denoised) metadata.emplace_back("radiant:denoised", "yes");
  return metadata;
}

std::optional<std::string> find_attribute(const ImageMetadata& metadata, const std::string& name) {
  for (const auto& [key, value] : metadata)
    if (key == name) return value;
  return std::nullopt;
}

std::optional<RenderRecord> parse_render_metadata(const ImageMetadata& metadata) {
  std::optional<std::string> software = find_attribute(metadata, "Software");
  if (!software || software->rfind(software_prefix, 0) != 0) return std::nullopt;
  auto required = [&](const std::string& name) {
    std::optional<std::string> value = find_attribute(metadata, name);
    if (!value) throw std::runtime_error("no " + name + " attribute");
    return *value;
  };
  RenderRecord r;
  r.version = software->substr(std::string(software_prefix).size());
  r.command_line = required("Comment");
  r.scene = required("radiant:scene");
  r.mode = required("radiant:mode");
  r.sampler = required("radiant:sampler");
  r.spp = parse_number<uint32_t>("radiant:spp", required("radiant:spp"));
  r.seed = parse_number<uint32_t>("radiant:seed", required("radiant:seed"));
  r.render_seconds = parse_number<double>("radiant:render_seconds", required("radiant:render_seconds"));
  if (!(r.render_seconds >= 0)) throw std::runtime_error("radiant:render_seconds is negative");
  r.rays = parse_number<uint64_t>("radiant:rays", required("radiant:rays"));
  if (std::optional<std::string> denoised = find_attribute(metadata, "radiant:denoised")) {
    if (*denoised != "yes") throw std::runtime_error("radiant:denoised '" + *denoised + "' is not 'yes'");
    r.denoised = true;
  }
  return r;
}

RenderRecord combined_record(const std::vector<RenderRecord>& records) {
  RenderRecord combined = records.at(0);
  combined.render_seconds = 0, combined.rays = 0;
  for (const RenderRecord& r : records) combined.render_seconds += r.render_seconds, combined.rays += r.rays;
  return combined;
}

ImageMetadata radiant_attributes(const ImageMetadata& metadata) {
  std::optional<std::string> software = find_attribute(metadata, "Software");
  bool ours = software && software->rfind(software_prefix, 0) == 0;
  ImageMetadata found;
  for (const auto& [key, value] : metadata)
    if (key.rfind("radiant:", 0) == 0 || (ours && (key == "Software" || key == "Comment"))) found.emplace_back(key, value);
  return found;
}

void add_missing_attributes(ImageMetadata& metadata, const ImageMetadata& extra) {
  for (const auto& [key, value] : extra)
    if (!find_attribute(metadata, key)) metadata.emplace_back(key, value);
}

}  // namespace radiant

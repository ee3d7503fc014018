#include "render_report.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "option_parsing.h"

namespace radiant::cli {

size_t peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return size_t(usage.ru_maxrss) * 1024;
}

std::string json_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buffer[8];
          std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
          out += buffer;
        } else {
          out += c;
        }
    }
  }
  return out;
}

std::string render_summary(const std::string& output, const RenderResult& r, const PhaseTimes& times) {
  const ResolvedSettings& s = r.settings;
  double rays_per_second = r.stats.render_seconds > 0 ? double(r.stats.rays.total()) / r.stats.render_seconds : 0;
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "wrote %s: %dx%d, %d spp (%s), %s, %.2f s, %.2f M rays/s", output.c_str(),
                r.film.width, r.film.height, s.spp, sampler_name(s.sampler), mode_name(s.mode),
                times.load + times.build + times.render + times.write, rays_per_second * 1e-6);
  std::string line = buffer;
  if (r.stats.rays.nonfinite_samples)
    line += ", " + std::to_string(r.stats.rays.nonfinite_samples) + " non-finite samples dropped";
  if (r.stats.untraceable_rays)
    line += ", " + std::to_string(r.stats.untraceable_rays) + " rays beyond the traceable range taken as misses";
  if (r.stats.min_pixel_samples != r.stats.max_pixel_samples) {
    std::snprintf(buffer, sizeof buffer, ", %u-%u spp per pixel (median %u), estimated relative error %.2f%%",
                  r.stats.min_pixel_samples, r.stats.max_pixel_samples, r.stats.median_pixel_samples,
                  100.0 * r.stats.estimated_relative_error);
    line += buffer;
  }
  if (r.stats.stopped_by_time_limit)
    line += ", time limit reached at " + std::to_string(r.stats.samples / std::max<size_t>(1, r.film.pixels.size())) + " spp";
  if (r.stats.interrupted) line += ", interrupted: partial image";
  return line;
}

std::string render_stats_json(const std::string& scene_path, const std::string& output, const RenderResult& r,
                              const PhaseTimes& t) {
  const ResolvedSettings& s = r.settings;
  const RayCounts& rays = r.stats.rays;
  double rays_per_second = r.stats.render_seconds > 0 ? double(rays.total()) / r.stats.render_seconds : 0;
  std::ostringstream j;
  j.precision(6);
  j << "{\n"
    << "  \"scene\": \"" << json_escape(scene_path) << "\",\n"
    << "  \"output\": \"" << json_escape(output) << "\",\n"
    << "  \"width\": " << r.film.width << ", \"height\": " << r.film.height << ",\n"
    << "  \"mode\": \"" << mode_name(s.mode) << "\", \"mode_reason\": \"" << json_escape(s.mode_reason) << "\",\n"
    << "  \"sampler\": \"" << sampler_name(s.sampler) << "\", \"light_sampler\": \""
    << (s.light_sampler == LightSampler::bvh ? "bvh" : "power") << "\", \"spp\": " << s.spp << ", \"max_depth\": " << s.max_depth << ",\n"
    << "  \"effects\": \"" << effect_names(s.effects) << "\",\n"
    << "  \"compiled_variant\": \"" << effect_names(s.compiled_variant) << "\",\n"
    << "  \"seconds\": {\"load\": " << t.load << ", \"build\": " << t.build << ", \"render\": " << t.render
    << ", \"write\": " << t.write << ", \"total\": " << (t.load + t.build + t.render + t.write) << "},\n"
    << "  \"rays\": {\"camera\": " << rays.camera << ", \"shadow\": " << rays.shadow << ", \"reflection\": " << rays.reflection
    << ", \"refraction\": " << rays.refraction << ", \"indirect\": " << rays.indirect << ", \"total\": " << rays.total() << "},\n"
    << "  \"rays_per_second\": " << rays_per_second << ",\n"
    << "  \"samples\": " << r.stats.samples << ", \"passes\": " << r.stats.passes << ",\n"
    << "  \"pixel_samples\": {\"min\": " << r.stats.min_pixel_samples << ", \"median\": " << r.stats.median_pixel_samples
    << ", \"p90\": " << r.stats.p90_pixel_samples << ", \"max\": " << r.stats.max_pixel_samples << ", \"mean\": "
    << double(r.stats.samples) / double(std::max<size_t>(1, r.film.pixels.size())) << "},\n"
    << "  \"estimated_relative_error\": " << r.stats.estimated_relative_error << ",\n"
    << "  \"stopped_by_time_limit\": " << (r.stats.stopped_by_time_limit ? "true" : "false") << ",\n"
    << "  \"interrupted\": " << (r.stats.interrupted ? "true" : "false") << ",\n"
    << "  \"nonfinite_samples_dropped\": " << rays.nonfinite_samples << ",\n"
    << "  \"untraceable_rays\": " << r.stats.untraceable_rays << ",\n"
    << "  \"peak_memory_bytes\": " << peak_memory_bytes() << "\n"
    << "}\n";
  return j.str();
}

}  // namespace radiant::cli

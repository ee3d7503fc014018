#include "render_report.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>

#include "interrupts.h"
#include "json_output.h"
#include "option_parsing.h"
#include "scene/enum_names.h"
#include "sampling/pixel_filter.h"

namespace radiant::cli {

size_t peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return size_t(usage.ru_maxrss) * 1024;
}

std::string render_summary(const std::string& output, const RenderResult& r, const PhaseTimes& times) {
  const ResolvedSettings& s = r.settings;
  double rays_per_second = r.stats.render_seconds > 0 ? double(r.stats.rays.total()) / r.stats.render_seconds : 0;
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, "wrote %s: %dx%d, %d spp (%s), %s, %.2f s, %.2f M rays/s", output.c_str(),
                r.film.width, r.film.height, s.spp, sampler_name(s.sampler), mode_name(s.mode),
                times.load + times.build + times.render + times.denoise + times.write, rays_per_second * 1e-6);
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
  if (r.stats.stopped_by_time_limit) line += ", time limit reached at " + std::to_string(r.stats.samples_reached) + " spp";
  if (r.stats.interrupted) line += ", interrupted: partial image";
  return line;
}

std::string partial_reason(const RenderResult& r) {
  std::string reached = " at " + std::to_string(r.stats.samples_reached) + " of " +
                        std::to_string(r.settings.samples.end - r.settings.samples.begin) + " samples per pixel";
  if (r.stats.interrupted) return std::string("interrupted by ") + signal_name(interrupt_signal()) + reached;
  if (r.stats.stopped_by_time_limit) return "time limit reached" + reached;
  return "";
}

RenderRecord render_record(const std::string& scene_path, const std::string& command_line, uint32_t seed,
                           const RenderResult& r) {
  RenderRecord record;
  record.version = RADIANT_VERSION;
  record.command_line = command_line;
  record.scene = scene_path;
  record.mode = mode_name(r.settings.mode);
  record.sampler = sampler_name(r.settings.sampler);
  // A stopped render records what every pixel reached: the image is that many samples' worth.
  bool stopped = r.stats.stopped_by_time_limit || r.stats.interrupted;
  record.spp = stopped ? r.stats.samples_reached : uint32_t(r.settings.spp);
  record.seed = seed;
  record.render_seconds = r.stats.render_seconds;
  record.rays = r.stats.rays.total();
  return record;
}

std::string render_stats_json(const std::string& scene_path, const std::string& output, const RenderResult& r,
                              const PhaseTimes& t, const FrameNote* frame) {
  const ResolvedSettings& s = r.settings;
  const RayCounts& rays = r.stats.rays;
  double rays_per_second = r.stats.render_seconds > 0 ? double(rays.total()) / r.stats.render_seconds : 0;
  Json j;
  j["scene"] = scene_path;
  j["output"] = output;
  if (frame)
    j["frame"] = {{"number", frame->frame},
                  {"scene_reads", frame->scene_reads},
                  {"accelerator", frame->accelerator_updated ? "updated" : "built"}};
  j["width"] = r.film.width;
  j["height"] = r.film.height;
  j["mode"] = mode_name(s.mode);
  j["mode_reason"] = s.mode_reason;
  j["sampler"] = sampler_name(s.sampler);
  j["light_sampler"] = name_of(light_sampler_names, s.light_sampler);
  j["filter"] = {{"name", pixel_filter_name(s.filter)}, {"width", 2 * s.filter_radius}};
  j["transparent"] = s.transparent;
  j["spp"] = s.spp;
  j["max_depth"] = s.max_depth;
  j["indirect_paths"] = s.indirect_paths;
  j["effects"] = effect_names(s.effects);
  j["compiled_variant"] = effect_names(s.compiled_variant);
  j["seconds"] = {{"load", t.load},       {"build", t.build}, {"render", t.render}, {"denoise", t.denoise},
                  {"write", t.write},     {"total", t.load + t.build + t.render + t.denoise + t.write}};
  j["rays"] = {{"camera", rays.camera},         {"shadow", rays.shadow},         {"reflection", rays.reflection},
               {"refraction", rays.refraction}, {"indirect", rays.indirect}, {"total", rays.total()}};
  j["rays_per_second"] = rays_per_second;
  j["samples"] = r.stats.samples;
  j["passes"] = r.stats.passes;
  j["pixel_samples"] = {{"min", r.stats.min_pixel_samples},
                        {"median", r.stats.median_pixel_samples},
                        {"p90", r.stats.p90_pixel_samples},
                        {"max", r.stats.max_pixel_samples},
                        {"mean", double(r.stats.samples) / double(std::max<size_t>(1, r.film.pixels.size()))}};
  j["estimated_relative_error"] = json_number(r.stats.estimated_relative_error);
  j["stopped_by_time_limit"] = r.stats.stopped_by_time_limit;
  j["interrupted"] = r.stats.interrupted;
  j["nonfinite_samples_dropped"] = rays.nonfinite_samples;
  j["untraceable_rays"] = r.stats.untraceable_rays;
  j["peak_memory_bytes"] = peak_memory_bytes();
  return json_text(j);
}

}  // namespace radiant::cli

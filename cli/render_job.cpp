#include "render_job.h"

#include <chrono>
#include <iostream>

#include "option_parsing.h"
#include "output/output_set.h"

namespace radiant::cli {

std::vector<NamedFile> render_job_outputs(const RenderJob& job) {
  std::vector<NamedFile> outputs = {{"-o", job.output}};
  if (!job.stats_path.empty()) outputs.push_back({"--stats", job.stats_path});
  return outputs;
}

void check_render_job_outputs(const RenderJob& job) {
  check_image_output(job.output);
  for (const NamedFile& output : render_job_outputs(job)) check_output_place(output.path);
}

void run_render_job(const std::string& scene_path, const PreparedScene& prepared, const RenderJob& job, PhaseTimes& times) {
  using Clock = std::chrono::steady_clock;
  times.build = prepared.build_seconds;
  RenderResult result = render_prepared(prepared, job.options);
  times.render = result.stats.render_seconds;
  const ResolvedSettings& s = result.settings;
  if (!job.options.quiet) {
    if (s.camera_framed) std::cerr << "radiant: the scene has no camera; using one that frames the whole scene\n";
    if (!s.mode_reason.empty()) std::cerr << "radiant: mode " << mode_name(s.mode) << ": " << s.mode_reason << "\n";
  }
  auto write_start = Clock::now();
  OutputSet outputs;
  write_image(outputs.create(job.output), film_to_image(result.film, job.options.aovs));
  times.write = std::chrono::duration<double>(Clock::now() - write_start).count();
  if (!job.stats_path.empty())
    outputs.create(job.stats_path).write(render_stats_json(scene_path, job.output, result, times));
  outputs.commit();
  if (!job.options.quiet) std::cerr << "radiant: " << render_summary(job.output, result, times) << "\n";
}

}  // namespace radiant::cli

#include "render_job.h"

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "option_parsing.h"

namespace radiant::cli {

void write_text_file_atomically(const std::string& path, const std::string& text) {
  std::string temporary = path + ".tmp-" + std::to_string(getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.good()) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error("cannot write '" + path + "'");
    }
  }
  std::filesystem::rename(temporary, path);
}

std::string out_of_memory_message(const std::string& scene_path, const std::string& doing, const MemoryBudget& budget) {
  return scene_path + ": out of memory while " + doing + " (the memory limit is " + format_bytes(budget.limit()) +
         "; a --max-memory below what this machine can give refuses such work before it allocates)";
}

void run_render_job(const std::string& scene_path, const PreparedScene& prepared, const RenderJob& job, PhaseTimes& times) {
  using Clock = std::chrono::steady_clock;
  times.build = prepared.build_seconds;
  prepare_image_writer(job.output);
  RenderResult result = render_prepared(prepared, job.options);
  times.render = result.stats.render_seconds;
  const ResolvedSettings& s = result.settings;
  if (!job.options.quiet) {
    if (s.camera_framed) std::cerr << "radiant: the scene has no camera; using one that frames the whole scene\n";
    if (!s.mode_reason.empty()) std::cerr << "radiant: mode " << mode_name(s.mode) << ": " << s.mode_reason << "\n";
  }
  auto write_start = Clock::now();
  write_image(job.output, film_to_image(result.film, job.options.aovs));
  times.write = std::chrono::duration<double>(Clock::now() - write_start).count();
  if (!job.stats_path.empty())
    write_text_file_atomically(job.stats_path, render_stats_json(scene_path, job.output, result, times));
  if (!job.options.quiet) std::cerr << "radiant: " << render_summary(job.output, result, times) << "\n";
}

}  // namespace radiant::cli

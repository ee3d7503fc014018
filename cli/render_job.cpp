#include "render_job.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <iostream>

#include "denoise/denoise.h"
#include "denoise/denoise_channels.h"
#include "image/image_io.h"
#include "interrupts.h"
#include "option_parsing.h"
#include "output/output_set.h"
#include "scene/scene_summary.h"
#include "shard_output.h"

namespace radiant::cli {

std::vector<NamedFile> render_job_outputs(const RenderJob& job) {
  std::vector<NamedFile> outputs = {{"-o", job.output}};
  if (!job.stats_path.empty()) outputs.push_back({"--stats", job.stats_path});
  return outputs;
}

std::string out_of_memory_message(const std::string& scene_path, const std::string& doing, const MemoryBudget& budget) {
  return scene_path + ": out of memory while " + doing + " (the memory limit is " + format_bytes(budget.limit()) +
         "; a --max-memory below what this machine can give refuses such work before it allocates)";
}

std::string image_format_name(const RenderJob& job) {
  return is_standard_output(job.output) ? "-." + job.format : job.output;
}

void check_render_job_outputs(const RenderJob& job) {
  std::string format = image_format_name(job);
  check_image_output(format);
  // A shard holds exact sums whatever the encoding: it records --half and --bit-depth for merge.
  bool shard = writes_shard(job.options);
  if (job.options.half_float && !is_exr_format(format) && !shard)
    throw std::invalid_argument("--half needs an EXR output (got '" + format + "')");
  if (job.options.bit_depth == 16 && !image_format_of(format).sixteen_bit && !shard)
    throw std::invalid_argument("--bit-depth 16 needs a PNG or TIFF output (got '" + format + "')");
  if (job.options.transparent.value_or(false) && !stores_alpha(format))
    throw std::invalid_argument("--transparent needs an output with alpha: PNG, TIFF or EXR (got '" + format + "')");
  for (const NamedFile& output : render_job_outputs(job)) check_output_place(output.path);
  if (!shard) charge_image_output(job.options.memory, format, job.options.bit_depth);
}

void check_outputs_spare_inputs(const std::string& scene_path, const std::string& env_map,
                                const std::vector<std::string>& scene_files, const std::vector<NamedFile>& outputs) {
  DistinctFiles files;
  if (!scene_path.empty()) files.add_input({"the scene", scene_path});
  if (!env_map.empty()) files.add_input({"--env", env_map});
  for (const std::string& path : scene_files) files.add_input({"a file the scene reads", path});
  for (const NamedFile& output : outputs) files.add_output(output);
}

namespace {

// The record the render's image or shard carries, or nothing with --no-metadata.
ImageMetadata job_metadata(const std::string& scene_path, const RenderJob& job, const RenderResult& result) {
  if (!job.write_metadata) return {};
  RenderRecord record = render_record(scene_path, job.command_line, job.options.seed, result);
  record.denoised = job.options.denoise;
  return render_metadata(record);
}

// The image to write: what the film holds with its record, denoised with --denoise, marked
// partial when a signal or the time limit stopped the render, and in EXR with the per-pixel
// sample counts, which say how far each pixel got (an HDR file has no room for them, and asking
// would lose the image).
OutputImage output_image(const std::string& scene_path, const RenderJob& job, const RenderResult& result,
                         double& denoise_seconds) {
  std::vector<std::string> aovs = job.options.aovs;
  std::string partial = partial_reason(result);
  if (!partial.empty() && is_exr_format(image_format_name(job)) && std::find(aovs.begin(), aovs.end(), "spp") == aovs.end())
    aovs.push_back("spp");
  OutputImage image = film_to_image(result.film, aovs);
  if (job.options.denoise) {
    auto start = std::chrono::steady_clock::now();
    set_image_color(image, denoise_film(result.film, job.options.memory, scene_path));
    denoise_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  set_output_encoding(image, job.options, result.settings);
  image.metadata = job_metadata(scene_path, job, result);
  if (!partial.empty()) image.metadata.emplace_back("radiant:partial", partial);
  return image;
}

// The temporary for `target`, or for standard output in `format`.
TemporaryFile& output_file(OutputSet& outputs, const std::string& target, const std::string& format) {
  return is_standard_output(target) ? outputs.create_standard_output(format) : outputs.create(target);
}

// What the mode leaves out of the light the scene has, or "" (docs/lights.md's table).
std::string dropped_light(const SceneDesc& scene, const ResolvedSettings& s) {
  bool ambient = false, delta = false, emitters = false;
  for (const LightDesc& l : scene.lights) (l.kind == LightKind::ambient ? ambient : delta) = true;
  for (const MaterialDesc& m : scene.materials) emitters |= is_lamp(m);
  std::vector<std::string> lost;
  if (s.mode == RenderMode::whitted) {
    if (emitters) lost.push_back("emissive surfaces are only seen, they light nothing");
    if (s.environment.exists()) lost.push_back("the environment is only seen behind the scene, it lights nothing");
  } else {
    if (ambient) lost.push_back("the ambient light is ignored (only the Whitted model defines it)");
    if (delta && s.mode == RenderMode::naive)
      lost.push_back("point, spot and directional lights cannot be hit by naive paths and add nothing");
  }
  std::string text;
  for (const std::string& part : lost) text += (text.empty() ? "" : "; ") + part;
  return text;
}

}  // namespace

void print_render_notes(const std::string& scene_path, const PreparedScene& prepared, const ResolvedSettings& s,
                        const RenderOptions& options) {
  // A mode the flags or the file chose may leave out light the scene has (auto never does).
  if (std::string dropped = s.mode_reason.empty() ? dropped_light(*prepared.scene, s) : ""; !dropped.empty() && !options.quiet_warnings)
    std::cerr << "radiant: warning: mode " << mode_name(s.mode) << ": " << dropped << "\n";
  if (options.quiet) return;
  if (s.camera_framed && prepared.world.cameras.empty())
    std::cerr << "radiant: the scene has no camera; using one that frames the whole scene\n";
  if (!s.mode_reason.empty()) std::cerr << "radiant: mode " << mode_name(s.mode) << ": " << s.mode_reason << "\n";
  if (s.default_environment)
    std::cerr << "radiant: " << scene_path
              << ": nothing in the file lights it; using the built-in studio environment (--env none for black)\n";
}

void run_render_job(const std::string& scene_path, PreparedScene& prepared, const RenderJob& job, PhaseTimes& times) {
  using Clock = std::chrono::steady_clock;
  DeferredInterrupts deferred;  // a signal stops the render; what it rendered is still written
  RenderOptions options = job.options;
  options.stop_request = &interrupt_signal();
  check_outputs_spare_scene_files(prepared.scene->input_files, render_job_outputs(job));
  // Before the render: a batch line's budget is made just now.
  if (!writes_shard(options)) charge_image_output(job.options.memory, image_format_name(job), job.options.bit_depth);
  prepare_view(prepared, job.options);
  times.build = prepared.build_seconds;
  if (job.skip_existing) {
    ShardInfo expected = make_shard_info(prepared, resolve_settings(prepared, options), options, job.shard_request_hash);
    if (shard_already_rendered(job.output, expected, job.options.memory)) {
      report_shard_skipped(job.output, job.options.quiet);
      return;
    }
  }
  if (job.notes) print_render_notes(scene_path, prepared, resolve_settings(prepared, job.options), job.options);
  auto render_start = std::chrono::steady_clock::now();
  std::optional<ResolvedSettings> watched;
  if (job.watchers.any()) {
    watched = resolve_settings(prepared, options);
    options.on_pass = [&](const Film& film, uint32_t samples) {
      double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count();
      job.watchers.show(job.output, film, samples, uint32_t(watched->samples.end), elapsed,
                        {options.exposure, watched->view}, options.quiet_warnings);
    };
  }
  RenderResult result = render_prepared(prepared, options);
  if (watched) {
    // A stopped render ends before its pass is reported: the watchers still get what was rendered.
    if (result.stats.interrupted || result.stats.stopped_by_time_limit)
      job.watchers.show(job.output, result.film, uint32_t(result.stats.max_pixel_samples), uint32_t(watched->samples.end),
                        result.stats.render_seconds, {options.exposure, watched->view}, options.quiet_warnings);
    job.watchers.finished();
  }
  if (!job.options.quiet_warnings)
    for (const std::string& warning : result.warnings) std::cerr << "radiant: warning: " << warning << "\n";
  if (result.stats.interrupted && result.stats.samples == 0) throw_if_interrupted();  // nothing to save
  times.render = result.stats.render_seconds;
  auto write_start = Clock::now();
  OutputSet outputs;
  // Resolving and encoding the image run on the render's threads, no more.
  tbb::task_arena(worker_threads(options.threads)).execute([&] {
    if (writes_shard(options)) {
      ShardInfo info = make_shard_info(prepared, result.settings, options, job.shard_request_hash);
      info.partial = partial_reason(result);
      write_shard(outputs.create(job.output), result.film, info, job_metadata(scene_path, job, result), options.memory);
    } else {
      write_image(output_file(outputs, job.output, job.format), output_image(scene_path, job, result, times.denoise));
    }
  });
  times.write = std::chrono::duration<double>(Clock::now() - write_start).count() - times.denoise;
  if (!job.stats_path.empty())
    output_file(outputs, job.stats_path, "json").write(render_stats_json(scene_path, job.output, result, times, job.frame ? &*job.frame : nullptr));
  outputs.commit();
  std::string written = is_standard_output(job.output) ? "standard output" : job.output;
  if (!job.options.quiet) std::cerr << "radiant: " << render_summary(written, result, times) << "\n";
  if (int signal = interrupt_signal())
    std::cerr << "radiant: interrupted by " << signal_name(signal) << "; wrote " << written
              << (result.stats.interrupted ? " with what was rendered, marked partial\n" : "\n");
  throw_if_interrupted();
}

}  // namespace radiant::cli

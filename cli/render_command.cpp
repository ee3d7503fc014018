// `radiant render SCENE -o OUT [options]`
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <new>

#include "animation_flags.h"
#include "command_line.h"
#include "commands.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "render_frames.h"
#include "render_job.h"
#include "watch_flags.h"
#include "shard_output.h"
#include "shard_request.h"
#include "image/image_io.h"

namespace radiant::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const char* render_examples =
    "\nExamples:\n"
    "  radiant render assets/cornell.gltf -o cornell.png\n"
    "  radiant render assets/first-render.scene -o sphere.png --spp 81 --sampler jittered\n"
    "  radiant render assets/models/textured-cube.obj -o cube.exr --env-color 1,1,1 --aov albedo,normal,variance\n"
    "  radiant render assets/showcase.scene -o preview.png --effects=-shadows,-indirect --width 320\n"
    "  cat assets/room-older-format.scene | radiant render - -o room.png --mode path --spp 256 --threads 2\n"
    "  radiant render assets/cornell.gltf -o - --format exr --stats stats.json | gzip > cornell.exr.gz\n"
    "  radiant render assets/models/turntable.gltf -o blue.png --variant blue --time 0.5 --camera-type orthographic\n"
    "  radiant render assets/cornell.gltf -o shard-3.exr --shard 3/8 --split both   # then the other 7, and radiant merge\n"
    "  mkdir -p spin && radiant render assets/models/turntable.gltf --frames 0-11 --fps 6 -o spin/frame-##.png\n";

// What is wrong with --frames and the outputs, or "".
std::string frames_usage_problem(const std::string& output, const std::string& stats_path, const RenderOptions& options) {
  if (!has_frame_placeholder(output))
    return "--frames writes one image a frame: -o needs a run of # for the frame number (e.g. out/frame-####.png), got '" +
           output + "'";
  if (!stats_path.empty() && !has_frame_placeholder(stats_path))
    return "--frames writes --stats once a frame: it needs a run of # too (e.g. stats-####.json), got '" + stats_path + "'";
  if (writes_shard(options))
    return "--frames renders whole frames and cannot be combined with --shard or --sample-range: give each job its own "
           "frames (--frames A-B, or --frame N with --shard)";
  return "";
}

// What is wrong with the shard flags, or "".
std::string shard_usage_problem(const std::string& scene_path, const std::string& output, const RenderOptions& options,
                                bool skip_existing) {
  if (!writes_shard(options)) return skip_existing ? "--skip-existing needs --shard or --sample-range" : "";
  if (!is_exr_format(output))
    return "--shard and --sample-range write a shard EXR for `radiant merge`: -o must end in .exr (got '" + output + "')";
  if (scene_path == "-") return "--shard and --sample-range need a scene file (merge checks its hash), not standard input";
  return "";
}

}  // namespace

int render_main(int argc, char** argv) {
  auto start = Clock::now();
  CLI::App app{"Render a scene (.scene, .gltf, .glb, .obj; - reads a .scene from stdin) to an image."};
  app.footer(render_examples);
  std::string scene_path, output, stats_path;
  LoadOptions load_options;
  RenderFlags flags;
  AnimationFlags animation;
  app.add_option("SCENE", scene_path, "Scene file, or - for a .scene on standard input")->required();
  app.add_option("-o,--output", output, "Output image (.png is 8-bit sRGB, .exr linear float; - for standard output)")
      ->required();
  flags.bind(app, true);
  animation.bind(app);
  app.add_option("--time-limit", flags.options.time_limit_seconds, "Stop after this many seconds (loading included)")
      ->check(time_limit_range());
  app.add_option("--noise-threshold", flags.options.noise_threshold, "Adaptive sampling: stop pixels under this relative error")
      ->check(positive_number());
  app.add_option("--min-spp", flags.options.min_spp,
                 "Adaptive sampling: samples every pixel takes before it may stop (default: from the threshold, "
                 "as Cycles)")
      ->check(CLI::Range(1, 1 << 24));
  std::string progress = "auto";
  app.add_option("--progress", progress,
                 "auto (a bar on a terminal, lines in a log), bar, lines (one every 10% or 30 s) or none");
  app.add_option("--crop", flags.crop, "Render only pixels X0,Y0,X1,Y1 (half-open)");
  app.add_option("--aov", flags.aovs, "Extra EXR channels: albedo,normal,depth,variance,spp");
  app.add_option("--stats", stats_path, "Write render statistics as JSON (- for standard output)");
  std::string format;
  app.add_option("--format", format, "The image format of -o - (png, exr, tif, jpg, ...; default png)");
  bool skip_existing = false;
  app.add_option("--shard", flags.shard, "Render shard I of K (from 0) to a shard EXR for `radiant merge`");
  app.add_option("--split", flags.split, "How --shard cuts the work: tiles (default), samples or both");
  app.add_option("--sample-range", flags.sample_range, "Render samples A:B of each pixel (of --spp) to a shard EXR");
  app.add_flag("--skip-existing", skip_existing, "Exit at once when -o already holds this shard, complete");
  WatchFlags watch;
  watch.bind(app, true);
  app.set_version_flag("--version", "radiant " RADIANT_VERSION);
  Watchers watchers;
  try {
    parse_arguments(app, argc, argv);
    flags.finish();
    animation.finish(load_options);
    flags.options.progress = parse_progress("--progress", progress, flags.options.quiet);
    watchers = make_watchers(watch);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant render: " << e.what() << "\n";
    return exit_usage;
  } catch (const std::exception& e) {  // the page's port cannot be listened on
    std::cerr << "radiant render: " << e.what() << "\n";
    return exit_failure;
  }
  RenderOptions& options = flags.options;
  if (options.time_limit_seconds > 0)
    options.deadline = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.time_limit_seconds));
  RenderJob job;
  job.options = options;
  job.output = output;
  job.stats_path = stats_path;
  job.command_line = command_line_text(argc, argv);
  job.write_metadata = !flags.no_metadata;
  job.watchers = watchers;
  if (!format.empty()) {
    if (!is_standard_output(output)) {
      std::cerr << "radiant render: --format is for -o - (the extension of '" << output << "' names its format)\n";
      return exit_usage;
    }
    job.format = format;
  }
  if (!options.aovs.empty() && !is_exr_format(image_format_name(job))) {
    std::cerr << "radiant render: --aov needs an EXR output (got '" << image_format_name(job) << "')\n";
    return exit_usage;
  }
  if (animation.frames) {
    if (std::string problem = frames_usage_problem(output, stats_path, options); !problem.empty()) {
      std::cerr << "radiant render: " << problem << "\n";
      return exit_usage;
    }
    job.output = frame_path(output, animation.frames->first);  // checked like one render's outputs
    if (!stats_path.empty()) job.stats_path = frame_path(stats_path, animation.frames->first);
  }
  if (std::string problem = shard_usage_problem(scene_path, output, options, skip_existing); !problem.empty()) {
    std::cerr << "radiant render: " << problem << "\n";
    return exit_usage;
  }
  if (*animation.frame_option) {
    job.options.seed = animation.seed_of_frame(options.seed, animation.frame);
    job.frame = FrameNote{animation.frame, 1};
  }

  MemoryBudget budget = flags.memory_budget();
  options.memory = &budget;
  job.options.memory = &budget;
  job.skip_existing = skip_existing;
  if (writes_shard(options)) job.shard_request_hash = shard_request_hash(app, scene_path);
  PhaseTimes times;
  const char* doing = "loading";
  try {
    DistinctFiles files;
    if (scene_path != "-") files.add_input({"the scene", scene_path});
    if (!options.env_map.empty()) files.add_input({"--env", options.env_map});
    for (const NamedFile& file : render_job_outputs(job)) files.add_output(file);
    check_render_job_outputs(job);
  } catch (const std::invalid_argument& e) {
    std::cerr << "radiant render: " << e.what() << "\n";
    return exit_usage;
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  // A finished array task run again exits here, before the scene is loaded and its BVH built.
  if (skip_existing && shard_unchanged_before_load(output, scene_path, job.shard_request_hash, &budget)) {
    report_shard_skipped(output, options.quiet);
    return exit_ok;
  }
  load_options.allow_external_files = flags.allow_external_files;
  load_options.budget = &budget;
  load_options.gltf_scene = flags.gltf_scene;
  load_options.material_variant = flags.variant;
  if (animation.frames) return render_frames({scene_path, output, stats_path, job, load_options, start}, animation);
  try {
    SceneDesc scene = load_scene(scene_path, load_options);
    times.load = seconds_since(start);
    if (!options.quiet_warnings)
      for (const std::string& warning : scene.warnings) std::cerr << "radiant: warning: " << warning << "\n";

    doing = "building its accelerator";
    try {
      // At an animation's moment, the layout --frames renders in: a BVH's layout can decide
      // which of two surfaces hit at the same distance is taken, and frame N must be one image.
      AccelLayout layout = load_options.animation_time ? AccelLayout::two_level : AccelLayout::single_level;
      PreparedScene prepared = prepare_scene(std::move(scene), options, layout);
      doing = "rendering";
      run_render_job(scene_path, prepared, job, times);
    } catch (const std::invalid_argument& e) {
      std::cerr << "radiant render: " << e.what() << "\n";
      return exit_usage;
    }
  } catch (const std::bad_alloc&) {
    std::cerr << "radiant: " << out_of_memory_message(scene_path, doing, budget) << "\n";
    return exit_failure;
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli

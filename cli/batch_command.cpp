// `radiant batch FILE|-`: a command script that loads a scene once and renders many views.
//
//   # comments and blank lines are ignored
//   scene assets/cornell.gltf                 # load (relative to the script's folder)
//   scene shoe.gltf --variant "red shoe"      # glTF: --scene N and --variant NAME choose what loads
//   render -o views/front.png --spp 16
//   render -o views/side.png --look-from 600,273,-400 --look-at 278,273,279
//
// The whole script is checked before anything renders; an error names `script:line`. A line may
// be at most max_command_line characters long. `--max-memory` caps the whole script (the scene
// loaded and each render); on a render line it caps that render instead.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <sstream>

#include "batch_script.h"
#include "command_line.h"
#include "commands.h"
#include "lights/light_table.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "render_job.h"
#include "watch_flags.h"
#include "render_frames.h"
#include "render_line.h"

namespace radiant::cli {

namespace fs = std::filesystem;

namespace {

// `scene PATH [--scene N] [--variant NAME]` into `step`. Throws CLI::ParseError.
void parse_scene_line(const std::vector<std::string>& words, BatchStep& step) {
  CLI::App app{"scene"};
  app.add_option("PATH", step.scene, "Scene file")->required();
  app.add_option("--scene", step.gltf_scene, "glTF scene index")->check(CLI::NonNegativeNumber);
  app.add_option("--variant", step.material_variant, "glTF material variant by name");
  parse_arguments(app, words);
}

}  // namespace

std::vector<BatchStep> parse_script(std::istream& in, const std::string& name, const fs::path& base) {
  std::vector<BatchStep> steps;
  std::string line;
  bool have_scene = false;
  for (int number = 1;; ++number) {
    try {
      if (!read_command_line(in, line)) break;
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + ":" + std::to_string(number) + ": " + e.what());
    }
    line = line.substr(0, line.find('#'));
    try {
      std::vector<std::string> words = split_words(line);
      if (words.empty()) continue;
      BatchStep step;
      step.line = number;
      size_t first = line.find_first_not_of(" \t"), last = line.find_last_not_of(" \t\r");
      step.text = line.substr(first, last + 1 - first);  // words.empty() above: the line has some
      if (words[0] == "scene") {
        parse_scene_line(words, step);
        if (fs::path(step.scene).is_relative()) step.scene = (base / step.scene).string();
        have_scene = true;
      } else if (words[0] == "render") {
        if (!have_scene) throw std::invalid_argument("'render' before any 'scene' line");
        step.job = parse_render_line(words, base, true);
      } else {
        throw std::invalid_argument("unknown command '" + words[0] + "' (expected scene or render)");
      }
      steps.push_back(step);
    } catch (const CLI::ParseError& e) {
      throw std::invalid_argument(name + ":" + std::to_string(number) + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + ":" + std::to_string(number) + ": " + e.what());
    }
  }
  return steps;
}

namespace {

// A scene of the script, loaded and prepared while the script is checked, and kept until its
// views are done. When a view samples the animation at a moment of its own (--time, --frame),
// the file is kept read and parsed too, so that every such view reuses it.
struct LoadedScene {
  std::string path;
  std::unique_ptr<PreparedScene> prepared;  // its accelerator holds its own charge
  std::unique_ptr<SceneFile> file;          // kept for views at moments of their own
  FrameScene moment;                        // the latest such view's scene, which the next updates
  int file_reads = 0;                       // how often the file was read and parsed (stats)
  uint64_t scene_memory = 0;                // what loading charged to the budget
  double load_seconds = 0;                  // loading and building, paid by its first view

  void release(MemoryBudget& budget) {
    moment.prepared.reset();
    prepared.reset();
    file.reset();
    budget.release(scene_memory);
    scene_memory = 0;
  }
};

LoadedScene load_batch_scene(const BatchStep& step, bool allow_external, bool keep_file, MemoryBudget& budget) {
  auto start = std::chrono::steady_clock::now();
  LoadOptions options;
  options.allow_external_files = allow_external;
  options.budget = &budget;
  options.gltf_scene = step.gltf_scene;
  options.material_variant = step.material_variant;
  const std::string& path = step.scene;
  LoadedScene loaded;
  loaded.path = path;
  uint64_t used_before = budget.used();
  SceneDesc scene;
  loaded.file_reads = 1;
  if (keep_file) {
    loaded.file = std::make_unique<SceneFile>(read_scene_file(path, options));
    scene = scene_from_file(*loaded.file, options);
  } else {
    scene = load_scene(path, options);
  }
  loaded.scene_memory = budget.used() - used_before;
  RenderOptions render_options;
  render_options.memory = &budget;
  loaded.prepared = std::make_unique<PreparedScene>(prepare_scene(std::move(scene), render_options));
  loaded.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return loaded;
}

// True when a render line after scene step `index` (and before the next scene) has a moment of
// its own.
bool views_sample_animation(const std::vector<BatchStep>& steps, size_t index) {
  for (size_t i = index + 1; i < steps.size() && steps[i].scene.empty(); ++i)
    if (steps[i].job.animation_time) return true;
  return false;
}

// Renders `job` at its own moment of `loaded`'s file: the scene made from the parsed file at that
// time, prepared from the previous such view's (render/prepare_frame.h), and rendered.
void render_at_moment(LoadedScene& loaded, RenderJob job, PhaseTimes& times) {
  auto start = std::chrono::steady_clock::now();
  LoadOptions options;
  options.budget = job.options.memory;
  options.animation_time = job.animation_time;
  options.animation = job.animation;
  FramePreparation how = loaded.moment.prepare_next(*loaded.file, options, job.options);
  if (job.frame) {
    job.frame->scene_reads = loaded.file_reads;
    job.frame->accelerator_updated = how == FramePreparation::updated;
  }
  PreparedScene& prepared = *loaded.moment.prepared;
  times.load += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - prepared.build_seconds;
  run_render_job(loaded.path, prepared, job, times);
}

// Everything about a view that can be known before rendering: its settings (size, crop, camera,
// field of view, mode) and that its environment map can be read.
void check_view(const LoadedScene& loaded, const RenderJob& job, MemoryBudget& budget) {
  check_outputs_spare_scene_files(loaded.prepared->scene->input_files, render_job_outputs(job));
  ResolvedSettings settings = resolve_settings(*loaded.prepared, job.options);
  if (!settings.environment.map_path.empty()) open_environment_map(settings.environment.map_path, &budget);
}

// Every output of the script, checked before anything loads: formats and places, and no file
// written twice or over an input (the script, a scene, an environment map).
void check_script_outputs(const std::vector<BatchStep>& steps, const std::string& name, const std::string& script_path) {
  DistinctFiles files;
  if (script_path != "-") files.add_input({"the script", script_path});
  for (const BatchStep& step : steps) {
    if (!step.scene.empty()) files.add_input({"the scene", step.scene});
    else if (!step.job.options.env_map.empty()) files.add_input({"--env", step.job.options.env_map});
  }
  for (const BatchStep& step : steps) {
    if (!step.scene.empty()) continue;
    try {
      for (NamedFile output : render_job_outputs(step.job)) {
        output.name += " (line " + std::to_string(step.line) + ")";
        files.add_output(output);
      }
      check_render_job_outputs(step.job);
    } catch (const std::exception& e) {
      throw std::invalid_argument(name + ":" + std::to_string(step.line) + ": " + e.what());
    }
  }
}

}  // namespace

void run_script(const std::vector<BatchStep>& steps, const std::string& script_name, const BatchSettings& settings) {
  auto at_line = [&](const BatchStep& step, const std::string& message) {
    return std::runtime_error(script_name + ":" + std::to_string(step.line) + ": " + message);
  };
  std::vector<RenderJob> jobs;
  for (const BatchStep& step : steps) {
    jobs.push_back(settings.adjust_job ? settings.adjust_job(step.job) : step.job);
    // A shell line that runs the script again, with the line that made the image as its comment.
    jobs.back().command_line = command_line_text({"batch", script_name}) + " # line " + std::to_string(step.line) + ": " + step.text;
  }
  MemoryBudget budget = command_memory_budget(settings.max_memory_bytes);
  // Every scene is loaded and every view resolved before the first render: a bad later line
  // must stop the script before anything is written. Scenes stay loaded (and charged) until
  // their views are done.
  std::vector<LoadedScene> scenes;
  for (size_t i = 0; i < steps.size(); ++i) {
    const BatchStep& step = steps[i];
    try {
      if (!step.scene.empty())
        scenes.push_back(load_batch_scene(step, settings.allow_external_files, views_sample_animation(steps, i), budget));
      else check_view(scenes.back(), jobs[i], budget);
    } catch (const std::bad_alloc&) {
      throw at_line(step, out_of_memory_message(step.scene.empty() ? scenes.back().path : step.scene, "loading", budget));
    } catch (const std::exception& e) {
      throw at_line(step, e.what());
    }
  }

  size_t scene_index = 0;
  double load_seconds = 0;
  for (size_t i = 0; i < steps.size(); ++i) {
    const BatchStep& step = steps[i];
    if (!step.scene.empty()) {
      if (scene_index > 0) scenes[scene_index - 1].release(budget);  // its views are done
      load_seconds = scenes[scene_index++].load_seconds;
      continue;
    }
    LoadedScene& loaded = scenes[scene_index - 1];
    try {
      RenderJob job = jobs[i];
      job.options.quiet = job.options.quiet || !shows(settings.log_level, LogLevel::info);
      job.options.quiet_warnings = job.options.quiet_warnings || !shows(settings.log_level, LogLevel::warning);
      job.options.progress = job.options.quiet ? ProgressStyle::none : settings.progress;
      // A render line's own cap holds what is loaded and this render.
      std::optional<MemoryBudget> line_budget;
      if (job.max_memory_bytes) {
        line_budget.emplace(*job.max_memory_bytes, "--max-memory on this line");
        line_budget->charge(budget.used(), loaded.path + ": the loaded scenes and their accelerators");
      }
      job.options.memory = line_budget ? &*line_budget : &budget;
      PhaseTimes times;
      times.load = load_seconds;
      load_seconds = 0;  // the load is paid once, by the first view
      if (job.animation_time) render_at_moment(loaded, job, times);
      else run_render_job(loaded.path, *loaded.prepared, job, times);
    } catch (const std::bad_alloc&) {
      throw at_line(step, out_of_memory_message(loaded.path, "rendering", budget));
    } catch (const std::exception& e) {
      throw at_line(step, e.what());
    }
  }
}

std::vector<BatchStep> shard_steps(const std::vector<BatchStep>& steps, const ShardSpec& shard) {
  std::vector<BatchStep> share;
  const BatchStep* scene = nullptr;  // the scene step not yet kept
  int render = 0;
  for (const BatchStep& step : steps) {
    if (!step.scene.empty()) {
      scene = &step;
    } else if (render++ % shard.count == shard.index) {
      if (scene) share.push_back(*scene), scene = nullptr;
      share.push_back(step);
    }
  }
  return share;
}

int batch_main(int argc, char** argv) {
  CLI::App app{"Run a command script: load a scene once, render many views (docs/cli.md)."};
  app.footer(
      "\nA script has 'scene PATH [--scene N] [--variant NAME]' lines and 'render -o OUT [render flags]' lines;\n"
      "# starts a comment.\n"
      "\nExamples:\n"
      "  printf 'scene assets/cornell.gltf\\nrender -o a.png --width 64 --spp 16\\nrender -o b.png --width 64 --fov 30\\n' > views.txt\n"
      "  radiant batch views.txt\n"
      "  radiant batch views.txt --max-memory 4 --quiet\n"
      "  printf 'scene assets/cornell.gltf\\nrender -o a.png --width 64 --spp 16\\n' | radiant batch -\n");
  std::string script_path;
  bool allow_external = false;
  LogLevelFlags log;
  app.add_option("SCRIPT", script_path, "Command script, or - for standard input")->required();
  log.bind(app);
  app.add_flag("--allow-external-files", allow_external, "Let scene files refer to files outside their folder");
  std::string max_memory;
  app.add_option("--max-memory", max_memory,
                 "Memory cap in GiB for the scenes loaded and every render (default 1/4 of RAM)");
  std::string shard_text;
  app.add_option("--shard", shard_text, "Render only render lines I, I+K, I+2K, ... (from 0) of the script: I/K");
  std::string progress = "auto";
  app.add_option("--progress", progress,
                 "auto (a bar on a terminal, lines in a log), bar, lines (one every 10% or 30 s) or none");
  WatchFlags watch;
  watch.bind(app, false);
  std::optional<uint64_t> max_memory_bytes;
  std::optional<ShardSpec> shard;
  Watchers watchers;
  LogLevel log_level = LogLevel::info;
  ProgressStyle progress_style = ProgressStyle::none;
  try {
    parse_arguments(app, argc, argv);
    log_level = log.level();
    progress_style = parse_progress("--progress", progress, !shows(log_level, LogLevel::info));
    if (!max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", max_memory);
    if (!shard_text.empty()) shard = parse_shard("--shard", shard_text);
    watchers = make_watchers(watch);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant batch: " << e.what() << "\n";
    return exit_usage;
  }
  std::vector<BatchStep> steps;
  try {
    if (script_path == "-") {
      steps = parse_script(std::cin, "<stdin>", fs::current_path());
      check_script_outputs(steps, "<stdin>", script_path);
    } else {
      std::ifstream in(script_path);
      if (!in) throw std::runtime_error(script_path + ": cannot open the script");
      steps = parse_script(in, script_path, fs::absolute(script_path).parent_path());
      check_script_outputs(steps, script_path, script_path);
    }
  } catch (const std::exception& e) {
    std::cerr << "radiant batch: " << e.what() << "\n";
    return exit_failure;
  }

  if (shard) steps = shard_steps(steps, *shard);
  try {
    std::function<RenderJob(RenderJob)> watch_each;
    if (watchers.any()) watch_each = [&](RenderJob job) {
      job.watchers = watchers;
      return job;
    };
    run_script(steps, script_path, {log_level, allow_external, progress_style, max_memory_bytes, watch_each});
  } catch (const std::exception& e) {
    std::cerr << "radiant batch: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli

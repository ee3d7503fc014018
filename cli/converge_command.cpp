// `radiant converge SCENE [--out DIR]`: what accuracy costs in time. Renders a reference, then a
// ladder of samples per pixel per mode (or, with --supersampling, per sampler), and writes the
// table, converge.csv, converge.json and a log-log chart of error against time.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <sstream>

#include "command_line.h"
#include "commands.h"
#include "converge_report.h"
#include "interrupts.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "output/output_paths.h"
#include "output/output_set.h"
#include "render_job.h"

namespace radiant::cli {

namespace {

namespace fs = std::filesystem;

const char* converge_examples =
    "\nExamples:\n"
    "  radiant converge assets/cornell.gltf --mode path,naive --out report\n"
    "  radiant converge assets/cornell.gltf --spp-ladder 1,4,16,64 --target-error 0.01\n"
    "  radiant converge assets/cornell.gltf --mode path --denoise --max-spp 64\n"
    "  radiant converge assets/showcase.scene --supersampling --width 96 --height 54\n"
    "  radiant render assets/cornell.gltf -o converged.exr --width 64 --height 64 --spp 4096\n"
    "  radiant converge assets/cornell.gltf --reference converged.exr --mode path\n";

constexpr int default_max_spp = 256;
constexpr int supersampling_timing_runs = 3;
constexpr int max_reference_spp = 4096;  // the default reference's cap (16x the ladder's top)
constexpr int default_converge_size = 128;  // the larger side when no size is given

struct ConvergeFlags {
  RenderFlags render;
  std::string out = ".", reference_file, spp_ladder, samplers = "grid,random,jittered,sobol";
  int width = 0, height = 0, max_spp = default_max_spp, reference_spp = 0;
  double target_error = 0, edge_fraction = default_edge_fraction;
  TimingPolicy timing;
  bool supersampling = false;
  bool denoise = false;  // a denoised ladder beside each mode's raw one
};

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, ','))
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::vector<int> parse_spp_list(const std::string& flag, const std::string& text) {
  std::vector<int> list;
  for (const std::string& part : split_list(text)) {
    size_t used = 0;
    int value = 0;
    try {
      value = std::stoi(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != part.size() || value < 1 || value > (1 << 24))
      throw CLI::ValidationError(flag, "'" + part + "' is not a sample count (1 to 16777216)");
    list.push_back(value);
  }
  if (list.empty()) throw CLI::ValidationError(flag, "expected a comma-separated list of sample counts");
  std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());
  return list;
}

// --mode as a comma-separated list; "auto" becomes the mode auto picks for the scene.
std::vector<RenderMode> parse_modes(const std::string& text) {
  std::vector<RenderMode> modes;
  for (const std::string& part : split_list(text)) {
    RenderMode mode = parse_mode("--mode", part);
    if (std::find(modes.begin(), modes.end(), mode) == modes.end()) modes.push_back(mode);
  }
  return modes;
}

std::vector<SamplerKind> parse_samplers(const std::string& text) {
  std::vector<SamplerKind> samplers;
  for (const std::string& part : split_list(text)) samplers.push_back(parse_sampler("--samplers", part));
  if (samplers.empty()) throw CLI::ValidationError("--samplers", "expected a comma-separated list of samplers");
  return samplers;
}

// The scene's own image size scaled down so its larger side is default_converge_size.
void choose_default_size(const PreparedScene& prepared, RenderOptions& options) {
  ResolvedSettings s = resolve_settings(prepared, options);
  double scale = double(default_converge_size) / std::max(s.width, s.height);
  if (scale >= 1) return;
  options.width = std::max(1, int(std::lround(s.width * scale)));
  options.height = std::max(1, int(std::lround(s.height * scale)));
}

// The modes in the order given, auto resolved to the mode it picks, each once; none = auto.
std::vector<RenderMode> resolve_modes(const PreparedScene& prepared, RenderOptions options, std::vector<RenderMode> given) {
  if (given.empty()) given.push_back(RenderMode::auto_select);
  std::vector<RenderMode> modes;
  for (RenderMode mode : given) {
    options.mode = mode;
    RenderMode resolved = resolve_settings(prepared, options).mode;
    if (std::find(modes.begin(), modes.end(), resolved) == modes.end()) modes.push_back(resolved);
  }
  return modes;
}

std::string scene_title(const std::string& scene_path) { return fs::path(scene_path).filename().string(); }

// The name of a mode's denoised series.
std::string denoised_name(RenderMode mode) { return std::string(mode_name(mode)) + "+denoise"; }

ConvergeSeries make_series(std::string name, std::vector<LadderStep> steps, double target_error) {
  ConvergeSeries series{std::move(name), std::move(steps), {}, {}};
  Prediction prediction = predict_target(series.steps, target_error);
  series.error_by_spp = prediction.error_by_spp;
  if (target_error > 0) series.prediction = prediction;
  return series;
}

ReferenceNote note_for(const Reference& reference, RenderMode mode, const std::string& file) {
  return {file.empty() ? mode_name(mode) : "file", file, reference.spp, reference.seconds};
}

void progress(const RenderOptions& options, const std::string& text) {
  if (options.progress != ProgressStyle::none) std::cerr << "converge: " << text << "\n";
}

// One series per mode; path and naive share the path tracer's reference, Whitted has its own.
ConvergeReport ladder_report(const PreparedScene& prepared, const RenderOptions& options, const ConvergeFlags& flags,
                             const std::vector<RenderMode>& modes, const std::vector<int>& ladder,
                             const std::optional<Reference>& file_reference) {
  ConvergeReport report;
  report.kind = "ladder";
  report.metric = "rmse";
  std::map<RenderMode, Reference> rendered;  // without a reference file: one per reference mode
  std::set<RenderMode> noted;
  for (RenderMode mode : modes) {
    RenderOptions mode_options = options;
    mode_options.mode = mode;
    RenderMode key = reference_mode(mode);
    if (!file_reference && !rendered.count(key)) {
      progress(options, std::string("rendering the ") + mode_name(key) + " reference");
      rendered[key] = render_reference(prepared, mode_options, flags.reference_spp, flags.edge_fraction);
    }
    // The file's image is shared, not copied: its pixels are charged to the budget once.
    const Reference& reference = file_reference ? *file_reference : rendered.at(key);
    if (noted.insert(key).second) report.references.push_back(note_for(reference, key, flags.reference_file));
    progress(options, std::string("ladder of ") + mode_name(mode));
    std::vector<LadderStep> steps = run_ladder(prepared, mode_options, ladder, reference, flags.timing);
    // Without a target, --denoise asks what the raw ladder's best error costs with the denoiser.
    double target = flags.target_error > 0 || !flags.denoise ? flags.target_error : steps.back().error.rmse;
    report.target_error = std::max(report.target_error, target);
    report.series.push_back(make_series(mode_name(mode), std::move(steps), report.target_error));
    if (!flags.denoise) continue;
    progress(options, std::string("denoised ladder of ") + mode_name(mode));
    mode_options.denoise = true;
    report.series.push_back(make_series(denoised_name(mode),
                                        run_ladder(prepared, mode_options, ladder, reference, flags.timing),
                                        report.target_error));
  }
  return report;
}

// One series per sampler, one mode, measured at edges against one high-sample reference.
ConvergeReport supersampling_report(const PreparedScene& prepared, const RenderOptions& options,
                                    const ConvergeFlags& flags, RenderMode mode, const std::vector<int>& ladder,
                                    const std::optional<Reference>& file_reference) {
  ConvergeReport report;
  report.kind = "supersampling";
  report.metric = "edge_rmse";
  RenderOptions mode_options = options;
  mode_options.mode = mode;
  RenderOptions reference_options = mode_options;
  reference_options.sampler = SamplerKind::jittered;  // stratified: the fastest to converge at edges
  progress(options, "rendering the reference");
  std::optional<Reference> rendered;
  if (!file_reference) rendered = render_reference(prepared, reference_options, flags.reference_spp, flags.edge_fraction);
  const Reference& reference = file_reference ? *file_reference : *rendered;
  report.references.push_back(note_for(reference, mode, flags.reference_file));
  for (SamplerKind sampler : parse_samplers(flags.samplers)) {
    progress(options, std::string("ladder of the ") + sampler_name(sampler) + " sampler");
    mode_options.sampler = sampler;
    report.series.push_back(
        make_series(sampler_name(sampler), run_ladder(prepared, mode_options, ladder, reference, flags.timing), flags.target_error));
  }
  return report;
}

// The plotting script: beside the executable's tree (build/radiant → scripts/), else in the
// source tree this file was compiled from.
std::optional<fs::path> find_plot_script() {
  std::vector<fs::path> roots;
  std::error_code error;
  fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) roots.push_back(exe.parent_path().parent_path());
  roots.push_back(fs::path(__FILE__).parent_path().parent_path());
  for (const fs::path& root : roots)
    if (fs::exists(root / "scripts" / "plot_convergence.py")) return root / "scripts" / "plot_convergence.py";
  return std::nullopt;
}

// Runs `program` with `arguments` and waits for it; its exit code, 127 when it cannot be run, or
// -1 when a signal ended it. Not std::system: that ignores SIGINT while it waits, and a ^C meant
// for radiant would be lost.
int run_program(const std::string& program, const std::vector<std::string>& arguments) {
  std::vector<std::string> words = {program};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGXFSZ);  // radiant ignores it; the child need not
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t child = 0;
  int spawned = posix_spawnp(&child, program.c_str(), nullptr, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) return 127;
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs the script with python3, then with the system's python3 (a virtualenv or pyenv
// python3 may lack matplotlib). Returns "" when the chart was written, else why not.
std::string plot_chart(const fs::path& json, const fs::path& png) {
  std::optional<fs::path> script = find_plot_script();
  if (!script) return "scripts/plot_convergence.py not found";
  std::string why = "python3 not found";
  for (const char* python : {"python3", "/usr/bin/python3"}) {
    int code = run_program(python, {script->string(), json.string(), png.string()});
    if (code == 0) return "";
    if (code == 3) why = "python3 has no matplotlib (apt-get install python3-matplotlib)";
    else if (code != 127) return "the plotting script failed (exit " + std::to_string(code) + ")";
  }
  return why;
}

// The report's files: the folder, then NAME.csv, NAME.json and NAME.png in it.
struct ReportFiles {
  fs::path folder, csv, json, chart;
};

ReportFiles report_files(const ConvergeFlags& flags) {
  std::string stem = flags.supersampling ? "supersampling" : "converge";
  fs::path folder = flags.out;
  return {folder, folder / (stem + ".csv"), folder / (stem + ".json"), folder / (stem + ".png")};
}

// Before any work: the report's folder can be written in (or created), and no report file is a
// folder or an input. std::invalid_argument for usage errors.
void check_report_files(const ReportFiles& report, const std::string& scene_path, const ConvergeFlags& flags) {
  DistinctFiles files;
  if (scene_path != "-") files.add_input({"the scene", scene_path});
  if (!flags.reference_file.empty()) files.add_input({"--reference", flags.reference_file});
  if (!flags.render.options.env_map.empty()) files.add_input({"--env", flags.render.options.env_map});
  check_output_folder(report.folder.string());
  for (const fs::path& file : {report.csv, report.json, report.chart}) {
    files.add_output({"the report file", file.string()});
    if (fs::exists(report.folder)) check_output_place(file.string());
  }
}

// The CSV, the JSON and the chart, committed together (a chart that cannot be drawn is left out
// with a warning). A first signal while they are written lets them be committed, then exits.
void write_outputs(const ConvergeReport& report, const ReportFiles& files, bool quiet) {
  DeferredInterrupts deferred;
  fs::create_directories(files.folder);
  OutputSet outputs;
  outputs.create(files.csv.string()).write(converge_csv(report));
  TemporaryFile& json = outputs.create(files.json.string());
  json.write(converge_json(report));
  TemporaryFile& chart = outputs.create(files.chart.string());
  std::string why = plot_chart(json.path(), chart.path());
  if (!why.empty()) outputs.remove(chart);
  outputs.commit();
  if (!quiet) std::cout << converge_table(report) << std::flush;
  if (!why.empty())
    std::cerr << "radiant converge: warning: no chart " << files.chart.string() << ": " << why
              << "; wrote the CSV and JSON\n";
  else if (!quiet)
    std::cerr << "radiant: wrote " << files.csv.string() << ", .json and .png\n";
  throw_if_interrupted();
}

void bind_flags(CLI::App& app, ConvergeFlags& flags) {
  flags.render.bind(app, false);
  app.add_option("--width", flags.width, "Image width (default: the scene's, scaled to 128 on the larger side)")
      ->check(CLI::Range(1, 65536));
  app.add_option("--height", flags.height, "Image height")->check(CLI::Range(1, 65536));
  app.add_option("--out", flags.out, "Folder for converge.csv/.json/.png (supersampling.* with --supersampling)");
  app.add_option("--reference", flags.reference_file, "Measure against this image instead of rendering a reference");
  app.add_option("--reference-spp", flags.reference_spp, "Samples per pixel of the rendered reference (default 16x the ladder's top, at most 4096)")
      ->check(CLI::Range(1, 1 << 24));
  app.add_option("--max-spp", flags.max_spp, "Top of the default ladder 1, 2, 4, ... (default 256)")->check(CLI::Range(1, 1 << 24));
  app.add_option("--spp-ladder", flags.spp_ladder, "The ladder as a list, e.g. 1,4,16,64");
  app.add_option("--target-error", flags.target_error, "Predict the spp and time that reach this RMSE")->check(positive_number());
  app.add_option("--edge-fraction", flags.edge_fraction, "Fraction of pixels counted as edges (default 0.1)")
      ->check(number_in(0.001, 1.0));
  app.add_option("--timing-runs", flags.timing.min_runs,
                 "Time each step as the median of at least N runs (default 1, 3 with --supersampling; short steps run more)")
      ->check(CLI::Range(1, 100));
  app.add_flag("--denoise", flags.denoise,
               "Also a denoised ladder per mode (the denoiser's time counted), and the time each needs to reach "
               "--target-error (default: the raw ladder's last error)");
  app.add_flag("--supersampling", flags.supersampling, "The anti-aliasing table: 1, 81 and 324 spp for each sampler, edge error");
  app.add_option("--samplers", flags.samplers, "Samplers of --supersampling (default grid,random,jittered,sobol)");
}

// Loads the scene, settles size and modes, runs the ladders and writes the report. Throws
// std::invalid_argument for settings that contradict each other (usage), else std::exception.
void run_converge(const std::string& scene_path, ConvergeFlags& flags, std::vector<RenderMode> modes,
                  const std::vector<int>& ladder, const std::string& command_line) {
  RenderOptions& options = flags.render.options;
  ReportFiles files = report_files(flags);
  check_report_files(files, scene_path, flags);
  MemoryBudget budget = flags.render.memory_budget();
  options.memory = &budget;
  std::optional<Reference> file_reference;
  if (!flags.reference_file.empty()) {
    file_reference = load_reference(flags.reference_file, &budget, flags.edge_fraction);
    if (!flags.width && !flags.height) flags.width = file_reference->image.width, flags.height = file_reference->image.height;
  }
  LoadOptions load_options;
  load_options.allow_external_files = flags.render.allow_external_files;
  load_options.budget = &budget;
  load_options.gltf_scene = flags.render.gltf_scene;
  load_options.material_variant = flags.render.variant;
  PreparedScene prepared = prepare_scene(load_scene(scene_path, load_options), options);
  check_outputs_spare_scene_files(prepared.scene->input_files, {{"the report file", files.csv.string()},
                                                                {"the report file", files.json.string()},
                                                                {"the report file", files.chart.string()}});

  if (flags.width) options.width = flags.width;
  if (flags.height) options.height = flags.height;
  if (!flags.width && !flags.height) choose_default_size(prepared, options);
  modes = resolve_modes(prepared, options, modes);
  ResolvedSettings size = resolve_settings(prepared, options);
  if (file_reference && (size.width != file_reference->image.width || size.height != file_reference->image.height))
    throw std::invalid_argument("--reference " + flags.reference_file + " is " + std::to_string(file_reference->image.width) +
                                "x" + std::to_string(file_reference->image.height) + " but the renders are " +
                                std::to_string(size.width) + "x" + std::to_string(size.height));
  bool whitted = std::count(modes.begin(), modes.end(), RenderMode::whitted) > 0;
  if (file_reference && whitted && modes.size() > 1)
    throw std::invalid_argument("--reference is one converged answer, but Whitted and path/naive converge to different ones");

  ConvergeReport report = flags.supersampling
                              ? supersampling_report(prepared, options, flags, modes.front(), ladder, file_reference)
                              : ladder_report(prepared, options, flags, modes, ladder, file_reference);
  report.scene = scene_path;
  report.width = size.width;
  report.height = size.height;
  report.edge_fraction = flags.edge_fraction;
  if (flags.target_error > 0) report.target_error = flags.target_error;
  report.title = scene_title(scene_path) + (flags.supersampling ? ": anti-aliasing error at edges against render time"
                                                                : ": RMSE against render time");
  report.chart_metadata = converge_chart_metadata(report, command_line, options.seed);
  write_outputs(report, files, options.quiet);
}

}  // namespace

int converge_main(int argc, char** argv) {
  CLI::App app{"Accuracy against time: a reference, a ladder of spp per mode, error and render time of each step."};
  app.footer(converge_examples);
  std::string scene_path;
  ConvergeFlags flags;
  app.add_option("SCENE", scene_path, "Scene file (.scene, .gltf, .glb, .obj)")->required();
  bind_flags(app, flags);
  std::vector<RenderMode> modes;
  std::vector<int> ladder;
  try {
    parse_arguments(app, argc, argv);
    modes = parse_modes(flags.render.mode);  // a list here: finish() parses only one mode
    flags.render.mode.clear();
    flags.render.finish();
    parse_samplers(flags.samplers);
    if (flags.supersampling && modes.size() > 1)
      throw CLI::ValidationError("--mode", "--supersampling compares samplers of one mode");
    if (flags.supersampling && flags.denoise)
      throw CLI::ValidationError("--denoise", "adds denoised ladders of modes: not with --supersampling");
    ladder = !flags.spp_ladder.empty() ? parse_spp_list("--spp-ladder", flags.spp_ladder)
             : flags.supersampling     ? std::vector<int>{1, 81, 324}
                                       : doubling_ladder(flags.max_spp);
    if (!flags.reference_spp) flags.reference_spp = std::min(max_reference_spp, 16 * ladder.back());
    // Its multiples of the 1-spp time are the answer: one slow run on a busy machine must not move them.
    if (flags.supersampling && !app.count("--timing-runs")) flags.timing.min_runs = supersampling_timing_runs;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant converge: " << e.what() << "\n";
    return exit_usage;
  }
  flags.render.options.progress =
      isatty(STDERR_FILENO) && !flags.render.options.quiet ? ProgressStyle::bar : ProgressStyle::none;
  try {
    run_converge(scene_path, flags, modes, ladder, command_line_text(argc, argv));
  } catch (const std::invalid_argument& e) {
    std::cerr << "radiant converge: " << e.what() << "\n";
    return exit_usage;
  } catch (const std::bad_alloc&) {
    std::cerr << "radiant: " << out_of_memory_message(scene_path, "measuring convergence", flags.render.memory_budget())
              << "\n";
    return exit_failure;
  } catch (const std::exception& e) {
    std::cerr << "radiant: " << e.what() << "\n";
    return exit_failure;
  }
  return exit_ok;
}

}  // namespace radiant::cli

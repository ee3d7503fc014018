// `radiant batch FILE|-`: a command script that loads a scene once and renders many views.
//
//   # comments and blank lines are ignored
//   scene assets/cornell.gltf                 # load (relative to the script's folder)
//   render -o views/front.png --spp 16
//   render -o views/side.png --look-from 600,273,-400 --look-at 278,273,279
//
// The whole script is checked before anything renders; an error names `script:line`.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "batch_script.h"
#include "commands.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "render_job.h"

namespace radiant::cli {

namespace {

namespace fs = std::filesystem;

// Splits a line into words; double quotes group words with spaces.
std::vector<std::string> split_words(const std::string& line) {
  std::vector<std::string> words;
  std::string word;
  bool quoted = false, any = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted, any = true;
    } else if (!quoted && (c == ' ' || c == '\t' || c == '\r')) {
      if (any) words.push_back(word), word.clear(), any = false;
    } else {
      word += c, any = true;
    }
  }
  if (quoted) throw std::invalid_argument("unterminated quote");
  if (any) words.push_back(word);
  return words;
}

RenderJob parse_render_line(std::vector<std::string> words, const fs::path& base) {
  CLI::App app{"render"};
  RenderFlags flags;
  RenderJob job;
  app.add_option("-o,--output", job.output)->required();
  flags.bind(app, true);
  app.add_option("--stats", job.stats_path);
  app.add_option("--aov", flags.aovs);
  app.add_option("--crop", flags.crop);
  app.add_option("--noise-threshold", flags.options.noise_threshold)->check(CLI::PositiveNumber);
  std::reverse(words.begin(), words.end());
  words.pop_back();  // "render"
  app.parse(words);
  flags.finish();
  job.options = flags.options;
  if (fs::path(job.output).is_relative()) job.output = (base / job.output).string();
  if (!job.stats_path.empty() && fs::path(job.stats_path).is_relative()) job.stats_path = (base / job.stats_path).string();
  if (!job.options.aovs.empty() && !is_float_format(job.output)) throw std::invalid_argument("--aov needs an EXR output");
  return job;
}

}  // namespace

std::vector<BatchStep> parse_script(std::istream& in, const std::string& name, const fs::path& base) {
  std::vector<BatchStep> steps;
  std::string line;
  bool have_scene = false;
  for (int number = 1; std::getline(in, line); ++number) {
    line = line.substr(0, line.find('#'));
    try {
      std::vector<std::string> words = split_words(line);
      if (words.empty()) continue;
      BatchStep step;
      step.line = number;
      if (words[0] == "scene") {
        if (words.size() != 2) throw std::invalid_argument("expected 'scene PATH'");
        step.scene = fs::path(words[1]).is_relative() ? (base / words[1]).string() : words[1];
        have_scene = true;
      } else if (words[0] == "render") {
        if (!have_scene) throw std::invalid_argument("'render' before any 'scene' line");
        step.job = parse_render_line(words, base);
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

int batch_main(int argc, char** argv) {
  CLI::App app{"Run a command script: load a scene once, render many views (docs/cli.md)."};
  std::string script_path;
  bool quiet = false, allow_external = false;
  app.add_option("SCRIPT", script_path, "Command script, or - for standard input")->required();
  app.add_flag("--quiet,-q", quiet, "Print nothing but errors");
  app.add_flag("--allow-external-files", allow_external, "Let scene files refer to files outside their folder");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant batch: " << e.what() << "\n";
    return exit_usage;
  }
  std::vector<BatchStep> steps;
  try {
    if (script_path == "-") {
      steps = parse_script(std::cin, "<stdin>", fs::current_path());
    } else {
      std::ifstream in(script_path);
      if (!in) throw std::runtime_error(script_path + ": cannot open the script");
      steps = parse_script(in, script_path, fs::absolute(script_path).parent_path());
    }
  } catch (const std::exception& e) {
    std::cerr << "radiant batch: " << e.what() << "\n";
    return exit_failure;
  }

  std::unique_ptr<SceneDesc> scene;
  std::unique_ptr<PreparedScene> prepared;
  std::string scene_path;
  double load_seconds = 0;
  for (const BatchStep& step : steps) {
    try {
      if (!step.scene.empty()) {
        auto start = std::chrono::steady_clock::now();
        LoadOptions options;
        options.allow_external_files = allow_external;
        prepared.reset();
        scene = std::make_unique<SceneDesc>(load_scene(step.scene, options));
        prepared = std::make_unique<PreparedScene>(prepare_scene(*scene));
        scene_path = step.scene;
        load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        continue;
      }
      RenderJob job = step.job;
      job.options.quiet = job.options.quiet || quiet;
      PhaseTimes times;
      times.load = load_seconds;
      load_seconds = 0;  // the load is paid once, by the first view
      run_render_job(scene_path, *prepared, job, times);
    } catch (const std::exception& e) {
      std::cerr << "radiant batch: " << script_path << ":" << step.line << ": " << e.what() << "\n";
      return exit_failure;
    }
  }
  return exit_ok;
}

}  // namespace radiant::cli

// `radiant session [SCENE] -o OUT [render flags]`: commands typed (or piped) while a render
// thread renders, as the seed path tracer was driven (docs/cli.md, "Sessions"):
//
//   render [FILE]        load FILE (or keep the scene) and render
//   moveto X Y Z         stand at X,Y,Z            move DX DY DZ     step along the world axes
//   turnto DX DY DZ      look along DX,DY,DZ       turn AX AY AZ     rotate by degrees about x, y, z
//   set NAME [VALUE...]  any render flag           unset NAME        back to its default
//   size W H             image size                save FILE         the last finished image
//   wait                 until the render is done  info, help, quit
//
// Every command that changes the image cancels the render under way at its next tile and starts
// the new one. The image is rewritten after each progressive pass (on a terminal, a status line
// above the prompt shows the pass and spp reached: session_console.h); each finished render prints
// one line on stdout. A bad command is reported with its line number and the session goes on;
// `quit` (or the end of the input, after the last render finishes) exits with the code of the
// last failure.
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>

#include "command_line.h"
#include "commands.h"
#include "load_scene.h"
#include "option_parsing.h"
#include "output/output_set.h"
#include "render_line.h"
#include "session_console.h"
#include "session_input.h"
#include "session_renderer.h"
#include "session_settings.h"
#include "session_view.h"
#include "watch_flags.h"

namespace radiant::cli {

namespace {

namespace fs = std::filesystem;

const char* session_help =
    "Commands (units are the scene's, angles degrees, axes the world's):\n"
    "  render [FILE]        load FILE (or keep the current scene) and render it\n"
    "  moveto X Y Z         stand at (X, Y, Z), looking the same way\n"
    "  move DX DY DZ        step by (DX, DY, DZ) along the world axes\n"
    "  turnto DX DY DZ      look along the direction (DX, DY, DZ)\n"
    "  turn AX AY AZ        turn by AX degrees about the world x axis, then AY about y, then AZ about z\n"
    "  set NAME [VALUE...]  set a render flag: set spp 64, set mode path, set env-color 1,1,1\n"
    "  unset NAME           a render flag back to its default\n"
    "  size W H             image width and height in pixels\n"
    "  save FILE            write the last finished image to FILE (waits for the render under way)\n"
    "  wait                 wait until the render under way has finished\n"
    "  info                 the scene, the view as render flags, the settings, the last render\n"
    "  help                 this list\n"
    "  quit                 stop rendering and leave (end of input waits for the render instead)\n";

// "1.5,2,-3" with every float's digits.
std::string format_vec3(vec3 v) {
  char text[96];
  std::snprintf(text, sizeof text, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
  return text;
}

std::string view_flags(const CameraOverride& o) {
  return "--look-from " + format_vec3(*o.look_from) + " --look-at " + format_vec3(*o.look_at) + " --up " + format_vec3(*o.up);
}

vec3 parse_numbers(const std::vector<std::string>& words) {
  if (words.size() != 4) throw std::invalid_argument("'" + words[0] + "' needs three numbers");
  return parse_vec3(words[0], words[1] + "," + words[2] + "," + words[3]);
}

class Session {
  SessionConsole console_;  // first: the render thread's reports use it until the thread stops

 public:
  void show_renders_in(Watchers watchers) { watchers_ = std::move(watchers); }
  Session(std::string output, SessionSettings settings, uint64_t memory_limit, std::string memory_source,
          bool allow_external, ProgressStyle progress)
      : console_(progress),
        output_(std::move(output)),
        settings_(std::move(settings)),
        budget_(memory_limit, std::move(memory_source)),
        allow_external_(allow_external),
        renderer_(
            [this](int line, const std::string& error, const FinishedRender* finished) {
              console_.render_ended();
              if (!error.empty()) fail(line, exit_failure, error);
              else print_line(finished->summary);
            },
            [this](const PassProgress* pass) {
              if (!pass) console_.render_ended();
              else console_.show_pass(pass->output, pass->pass, pass->samples, pass->total, pass->seconds);
            }) {}

  // Runs one command; false for `quit`. Throws std::invalid_argument for a bad command.
  bool run(int line, const std::vector<std::string>& words) {
    const std::string& command = words[0];
    if (command == "quit" || command == "exit") {
      renderer_.cancel();
      renderer_.wait_idle();
      return false;
    }
    if (command == "help") {
      print_line(session_help);
    } else if (command == "render") {
      if (words.size() > 2) throw std::invalid_argument("expected 'render [FILE]'");
      if (words.size() == 2) load(words[1]);
      render(line);
    } else if (command == "moveto" || command == "move" || command == "turnto" || command == "turn") {
      vec3 v = parse_numbers(words);
      SessionView& view = current_view();
      if (command == "moveto") move_to(view, v);
      else if (command == "move") move_by(view, v);
      else if (command == "turnto") turn_to(view, v);
      else turn_by(view, v);
      render(line);
    } else if (command == "set" || command == "unset") {
      if (words.size() < 2) throw std::invalid_argument("expected '" + command + " NAME" + (command == "set" ? " [VALUE...]'" : "'"));
      std::string name = words[1];
      SessionSettings trial = settings_;
      if (command == "set") trial.set(name, {words.begin() + 2, words.end()});
      else if (!trial.unset(name)) throw std::invalid_argument(name + " is not set");
      check_outputs(job_of(trial));  // a refused setting is not kept
      settings_ = trial;
      if (name == "camera" || name == "--camera") view_.reset();  // another camera: its own view
      if (scene_) render(line);
    } else if (command == "size") {
      if (words.size() != 3) throw std::invalid_argument("expected 'size WIDTH HEIGHT'");
      SessionSettings trial = settings_;
      trial.set("width", {words[1]});
      trial.set("height", {words[2]});
      check_outputs(job_of(trial));
      settings_ = trial;
      if (scene_) render(line);
    } else if (command == "save") {
      if (words.size() != 2) throw std::invalid_argument("expected 'save FILE'");
      save(words[1]);
    } else if (command == "wait") {
      renderer_.wait_idle();
    } else if (command == "info") {
      print_line(info());
    } else {
      throw std::invalid_argument("unknown command '" + command + "' (help lists them)");
    }
    return true;
  }

  // A failure of command `line` (0: the command line): reported, and the exit code from now on.
  void fail(int line, int code, const std::string& message) {
    console_.print_error("radiant session: " + (line ? "line " + std::to_string(line) + ": " : std::string()) + message);
    last_failure_ = code;
  }

  // On a terminal: the prompt, until a line is read; lines printed meanwhile go above it.
  void show_prompt() { console_.show_prompt(); }
  void prompt_answered() { console_.prompt_answered(); }

  // Waits for the render under way (the end of the input).
  void finish() { renderer_.wait_idle(); }
  int exit_code() const { return last_failure_; }

 private:
  void print_line(const std::string& text) { console_.print_out(text); }

  // Replaces the scene only once the new one has loaded: a file that fails keeps the old one.
  void load(const std::string& path) {
    renderer_.cancel();
    renderer_.wait_idle();  // the render thread no longer uses the scene or the budget
    LoadOptions options;
    options.allow_external_files = allow_external_;
    options.budget = &budget_;
    uint64_t used_before = budget_.used();
    SceneDesc scene;
    try {
      scene = load_scene(path, options);
    } catch (...) {
      budget_.release(budget_.used() - used_before);  // what the failed load charged
      throw;
    }
    // The load's charge, held by an object so that a failure below gives it back (it cannot be
    // refused: the same bytes were just released).
    uint64_t scene_memory = budget_.used() - used_before;
    budget_.release(scene_memory);
    MemoryCharge loaded(&budget_, scene_memory, path + ": the scene");
    RenderOptions render_options = current_job().options;
    if (!render_options.quiet_warnings)
      for (const std::string& warning : scene.warnings) std::cerr << "radiant: warning: " << warning << "\n";
    auto prepared = std::make_shared<PreparedScene>(prepare_scene(std::move(scene), render_options));
    scene_ = std::move(prepared);
    scene_memory_ = std::move(loaded);
    scene_path_ = path;
    view_.reset();
  }

  RenderJob current_job() { return job_of(settings_); }

  // Render and batch's checks of a job's outputs, against the loaded scene's every file.
  void check_outputs(const RenderJob& job) {
    check_outputs_spare_inputs(scene_path_, job.options.env_map, scene_files(), render_job_outputs(job));
    check_render_job_outputs(job);
  }

  std::vector<std::string> scene_files() const { return scene_ ? scene_->scene->input_files : std::vector<std::string>{}; }

  // The job `settings` describe, from the current view.
  RenderJob job_of(const SessionSettings& settings) {
    RenderJob job = settings.job(output_, fs::current_path());
    job.options.memory = &budget_;
    job.watchers = watchers_;
    job.options.progress = ProgressStyle::none;  // the session's console shows each pass instead
    // The image records the `render` command that makes it again.
    std::vector<std::string> words = {"render", scene_path_, "-o", output_};
    for (const std::string& word : settings.flag_words()) words.push_back(word);
    if (view_) {
      CameraOverride placed = camera_override(*view_);
      job.options.camera_override.look_from = placed.look_from;
      job.options.camera_override.look_at = placed.look_at;
      job.options.camera_override.up = placed.up;
      words.insert(words.end(), {"--look-from", format_vec3(*placed.look_from), "--look-at",
                                 format_vec3(*placed.look_at), "--up", format_vec3(*placed.up)});
    }
    job.command_line = command_line_text(words);
    return job;
  }

  // The view the next move or turn starts from: the current camera's until one moved it.
  SessionView& current_view() {
    if (!scene_) throw std::invalid_argument("no scene yet: 'render FILE' loads one");
    if (!view_) {
      bool framed = false;
      view_ = view_of(world_view_camera(*scene_, current_job().options, framed));
    }
    return *view_;
  }

  void render(int line) {
    if (!scene_) throw std::invalid_argument("no scene yet: 'render FILE' loads one");
    SessionRequest request{line, scene_, scene_path_, current_job()};
    check_outputs(request.job);
    if (!request.job.options.quiet) console_.render_started(request.job.output);
    renderer_.start(std::move(request));
  }

  // The last image, also onto -o, never onto the scene's files or the statistics.
  void save(const std::string& path) {
    check_image_output(path);
    RenderJob job = current_job();
    charge_image_output(&budget_, path, job.options.bit_depth);
    std::vector<NamedFile> written = {{"save", path}};
    if (!job.stats_path.empty()) written.push_back({"--stats", job.stats_path});
    check_outputs_spare_inputs(scene_path_, job.options.env_map, scene_files(), written);
    check_output_place(path);
    renderer_.wait_idle();
    std::optional<FinishedRender> last = renderer_.last_finished();
    if (!last) throw std::runtime_error("nothing has finished rendering yet");
    OutputSet outputs;
    write_image(outputs.create(path), last->image);
    outputs.commit();
  }

  std::string info() {
    std::string text = "scene: " + (scene_ ? scene_path_ : std::string("(none)")) + "\n";
    text += "image: " + output_ + "\n";
    if (scene_) {
      bool framed = false;
      text += "view: " + view_flags(view_ ? camera_override(*view_) : camera_override(view_of(world_view_camera(
                                                                            *scene_, current_job().options, framed)))) +
              "\n";
    }
    text += "settings: " + settings_.flags() + "\n";
    if (std::optional<FinishedRender> last = renderer_.last_finished()) text += "last render: " + last->summary + "\n";
    return text;
  }

  std::string output_;
  SessionSettings settings_;
  MemoryBudget budget_;
  bool allow_external_ = false;
  std::shared_ptr<PreparedScene> scene_;
  std::string scene_path_;
  MemoryCharge scene_memory_;  // what loading the scene charged to the budget
  std::optional<SessionView> view_;  // set once a command moved or turned the camera
  Watchers watchers_;  // --display-server, --serve: every view shown as it converges
  std::atomic<int> last_failure_{exit_ok};
  SessionRenderer renderer_;  // last: its thread stops before the rest goes
};

}  // namespace

int session_main(int argc, char** argv) {
  CLI::App app{"Render while taking commands from standard input (docs/cli.md, \"Sessions\")."};
  app.footer(std::string("\n") + session_help +
             "\nExamples:\n"
             "  radiant session assets/cornell.gltf -o view.png --spp 64\n"
             "  printf 'render assets/cornell.gltf\\nturn 0 10 0\\nsave turned.png\\n' | radiant session -o view.png\n");
  std::string scene_path, output;
  app.add_option("SCENE", scene_path, "Scene to load and render first (else: 'render FILE')");
  app.add_option("-o,--output", output, "The image each render rewrites (.png, .exr, ...)")->required();
  // The render flags, parsed as `render` parses them (a value flag takes the next word, wherever
  // the scene stands); each becomes a setting, checked as `set` checks it.
  RenderFlags flags;
  RenderJob parsed_job;
  bind_render_line_flags(app, flags, parsed_job);
  SessionSettings settings;
  std::optional<uint64_t> max_memory_bytes;
  bool allow_external = false;
  std::string progress = "auto";
  app.add_option("--progress", progress,
                 "Each pass's spp on stderr: auto (a status line above the prompt on a terminal, else none), "
                 "bar, lines or none");
  ProgressStyle progress_style = ProgressStyle::none;
  WatchFlags watch;
  watch.bind(app, true);
  std::unique_ptr<SessionInput> input;  // before the page that pushes to it, which stops first
  Watchers watchers;
  try {
    parse_arguments(app, argc, argv);
    input = std::make_unique<SessionInput>(!watch.serve.empty());
    watchers = make_watchers(watch, [&input](const std::string& line) { input->push(line); });
    if (is_standard_output(output)) throw std::invalid_argument("-o -: a session rewrites its image after every pass; name a file");
    if (!flags.max_memory.empty()) max_memory_bytes = parse_memory_limit("--max-memory", flags.max_memory);
    allow_external = flags.allow_external_files;
    // Off a terminal a session is driven by a program that reads its stdout: no progress unless asked.
    progress_style = progress == "auto" && !isatty(STDERR_FILENO) ? ProgressStyle::none
                                                                  : parse_progress("--progress", progress, false);
    settings.set_output(output);
    settings.set_from_command_line(app, {"output", "max-memory", "allow-external-files", "display-server", "serve", "progress"});
    RenderJob job = settings.job(output, fs::current_path());
    check_outputs_spare_inputs(scene_path, job.options.env_map, {}, render_job_outputs(job));
    check_render_job_outputs(job);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::cerr << "radiant session: " << e.what() << "\n";
    return exit_usage;
  } catch (const std::invalid_argument& e) {
    std::cerr << "radiant session: " << e.what() << "\n";
    return exit_usage;
  } catch (const std::exception& e) {
    std::cerr << "radiant session: " << e.what() << "\n";
    return exit_failure;
  }

  Session session(output, settings, max_memory_bytes.value_or(default_memory_limit()),
                  max_memory_bytes ? "--max-memory" : default_memory_limit_source, allow_external, progress_style);
  session.show_renders_in(watchers);
  std::vector<std::string> first;
  if (!scene_path.empty()) first = {"render", scene_path};
  bool interactive = isatty(STDIN_FILENO);
  std::string text;
  for (int line = 0;; ++line) {
    std::vector<std::string> words = first;
    if (line > 0) {
      if (interactive) session.show_prompt();
      try {
        bool read = input->next(text);
        session.prompt_answered();
        if (!read) break;
        words = split_words(text.substr(0, text.find('#')));
      } catch (const std::invalid_argument& e) {
        session.prompt_answered();
        session.fail(line, exit_usage, e.what());
        continue;
      }
    }
    if (words.empty()) continue;
    try {
      if (!session.run(line, words)) return session.exit_code();
    } catch (const std::invalid_argument& e) {
      session.fail(line, exit_usage, e.what());
    } catch (const CLI::ParseError& e) {
      session.fail(line, exit_usage, e.what());
    } catch (const std::bad_alloc&) {
      session.fail(line, exit_failure, "out of memory");
    } catch (const std::exception& e) {
      session.fail(line, exit_failure, e.what());
    }
  }
  session.finish();
  return session.exit_code();
}

}  // namespace radiant::cli

// `radiant session` driven through a pipe, as a script or another program drives it.
#include <doctest/doctest.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "support/child_process.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;


// first-render.scene: a camera at (0, 0, 1000) looking down -z with +y up.
fs::path copy_scene(ScratchDir& dir) {
  fs::copy_file(source_path("assets/first-render.scene"), dir.file("s.scene"));
  return dir.file("s.scene");
}

std::vector<std::string> session_args(ScratchDir& dir, std::vector<std::string> more) {
  std::vector<std::string> args = {"session", copy_scene(dir).string(), "-o", dir.file("view.png").string(),
                                   "--width", "32", "--height", "32"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

ChildSetup piped() {
  ChildSetup setup;
  setup.piped_stdin = true;
  return setup;
}

}  // namespace

TEST_CASE("session: moves and turns give the pixels of the equivalent render line, whose command the image records") {
  ScratchDir dir("session-same");
  RadiantProcess session(session_args(dir, {"--spp", "4", "--mode", "path"}), piped());
  session.write_stdin("moveto 300 0 1000\nturnto -300 0 -1200\n");
  session.close_stdin();  // the end of input waits for the last render
  CommandResult r = session.wait(120);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("wrote ") != std::string::npos);
  CommandResult line = run_radiant("render " + quoted(dir.file("s.scene")) + " -o " + quoted(dir.file("line.png")) +
                                   " --width 32 --height 32 --spp 4 --mode path --look-from 300,0,1000 --look-at 0,0,-200");
  REQUIRE(line.exit_code == 0);
  fs::path view = dir.file("view.png");
  CHECK(same_pixels(view, dir.file("line.png")));
  for (const char* field : {"radiant:scene", "radiant:mode", "radiant:sampler", "radiant:spp", "radiant:seed", "radiant:rays"})
    CHECK(image_attribute(view, field) == image_attribute(dir.file("line.png"), field));
  // The image records the render command that makes it again.
  std::string recorded = image_attribute(view, "Comment");
  REQUIRE(recorded.rfind("radiant render ", 0) == 0);
  size_t at = recorded.find(" -o " + view.string() + " ");
  REQUIRE(at != std::string::npos);
  recorded.replace(at + 4, view.string().size(), dir.file("again.png").string());
  CommandResult again = run_radiant(recorded.substr(std::string("radiant ").size()) + " --quiet");
  REQUIRE_MESSAGE(again.exit_code == 0, recorded << "\n" << again.err);
  CHECK(same_pixels(dir.file("again.png"), view));
}

TEST_CASE("session: with set no-metadata the image is the equivalent render line's, byte for byte") {
  ScratchDir dir("session-bytes");
  RadiantProcess session(session_args(dir, {"--spp", "4", "--mode", "path"}), piped());
  session.write_stdin("set no-metadata\nmoveto 300 0 1000\nturnto -300 0 -1200\n");
  session.close_stdin();
  CommandResult r = session.wait(120);
  REQUIRE_MESSAGE(r.exit_code == 0, r.err);
  CommandResult line = run_radiant("render " + quoted(dir.file("s.scene")) + " -o " + quoted(dir.file("line.png")) +
                                   " --width 32 --height 32 --spp 4 --mode path --look-from 300,0,1000 --look-at 0,0,-200"
                                   " --no-metadata --quiet");
  REQUIRE(line.exit_code == 0);
  CHECK(read_bytes(dir.file("view.png")) == read_bytes(dir.file("line.png")));
}

TEST_CASE("session: info prints the view as render flags that reproduce it after turns") {
  ScratchDir dir("session-info");
  RadiantProcess session(session_args(dir, {"--spp", "2"}), piped());
  session.write_stdin("turn 0 7 0\nmove 10 -5 0\nturn 3 0 0\nwait\ninfo\nsave " + dir.file("saved.png").string() + "\n");
  session.close_stdin();
  CommandResult r = session.wait(120);
  REQUIRE(r.exit_code == 0);
  size_t at = r.out.find("view: ");
  REQUIRE(at != std::string::npos);
  std::string flags = r.out.substr(at + 6, r.out.find('\n', at) - at - 6);
  CHECK(flags.find("--look-from 10,-5,1000 ") == 0);
  CommandResult line = run_radiant("render " + quoted(dir.file("s.scene")) + " -o " + quoted(dir.file("line.png")) +
                                   " --width 32 --height 32 --spp 2 " + flags);
  REQUIRE(line.exit_code == 0);
  CHECK(same_pixels(dir.file("view.png"), dir.file("line.png")));
  CHECK(same_pixels(dir.file("saved.png"), dir.file("line.png")));  // save: the last finished image
}

TEST_CASE("session: a change mid-render cancels the stale render within a bounded time") {
  ScratchDir dir("session-cancel");
  // 2^24 samples per pixel would take hours: only a cancelled render lets the session go on.
  RadiantProcess session(session_args(dir, {"--spp", "16777216", "--mode", "path"}), piped());
  auto deadline = Clock::now() + std::chrono::seconds(60);
  while (!fs::exists(dir.file("view.png")) && Clock::now() < deadline)  // the first pass was written
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  REQUIRE(fs::exists(dir.file("view.png")));
  auto asked = Clock::now();
  session.write_stdin("set spp 2\n");
  REQUIRE(session.wait_for_stdout("wrote ", 1, 30));
  double seconds = std::chrono::duration<double>(Clock::now() - asked).count();
  CHECK(seconds < 10);
  session.write_stdin("quit\n");
  CommandResult r = session.wait(30);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("2 spp") != std::string::npos);
  CHECK(r.out.find("wrote ", r.out.find("wrote ") + 1) == std::string::npos);  // the stale render printed nothing
  CommandResult line = run_radiant("render " + quoted(dir.file("s.scene")) + " -o " + quoted(dir.file("line.png")) +
                                   " --width 32 --height 32 --spp 2 --mode path");
  CHECK(same_pixels(dir.file("view.png"), dir.file("line.png")));
}

TEST_CASE("session: a bad command names its line, the session goes on, and quit returns the last failure") {
  ScratchDir dir("session-errors");
  RadiantProcess session(session_args(dir, {"--spp", "1"}), piped());
  session.write_stdin("jump 1 2 3\nmoveto 1 2\nset spp banana\nset output x.png\nsave nowhere.xyz\nmove 0 0 -10\nwait\nquit\n");
  CommandResult r = session.wait(120);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("line 1: unknown command 'jump'") != std::string::npos);
  CHECK(r.err.find("line 2: 'moveto' needs three numbers") != std::string::npos);
  CHECK(r.err.find("line 3: ") != std::string::npos);
  CHECK(r.err.find("line 4: --output: ") != std::string::npos);
  CHECK(r.err.find("line 5: ") != std::string::npos);
  CHECK(r.out.find("wrote ") != std::string::npos);  // line 6 still rendered
  CHECK_FALSE(fs::exists(dir.file("nowhere.xyz")));
}

TEST_CASE("session: without a scene, commands that need one say so, the end of input exits cleanly") {
  ScratchDir dir("session-empty");
  RadiantProcess session({"session", "-o", dir.file("view.png").string()}, piped());
  session.write_stdin("turn 0 10 0\nrender " + copy_scene(dir).string() + "\nset width 16\nset height 16\nset spp 1\n");
  session.close_stdin();
  CommandResult r = session.wait(120);
  CHECK(r.exit_code == 2);  // the failed turn
  CHECK(r.err.find("line 1: no scene yet") != std::string::npos);
  CHECK(fs::exists(dir.file("view.png")));
}

TEST_CASE("session: set without a value names the setting and what it needs, and a flag that takes none is set") {
  ScratchDir dir("session-set-empty");
  RadiantProcess session(session_args(dir, {"--spp", "1", "--view", "filmic"}), piped());
  session.write_stdin("set spp\nset env\nset no-metadata\nwait\nquit\n");
  CommandResult r = session.wait(120);
  CHECK(r.err.find("line 1: set spp needs a value: --spp") != std::string::npos);
  CHECK(r.err.find("line 2: set env needs a value: --env") != std::string::npos);
  CHECK(r.err.find("--view") == std::string::npos);  // not the next setting's name
  CHECK(r.err.find("line 3") == std::string::npos);
}

TEST_CASE("session: set aov is taken when the session writes an EXR, refused for a PNG") {
  ScratchDir dir("session-aov");
  std::vector<std::string> args = {"session", copy_scene(dir).string(), "-o", dir.file("view.exr").string(),
                                   "--width", "8", "--height", "8", "--spp", "1"};
  RadiantProcess exr(args, piped());
  exr.write_stdin("set aov albedo\nwait\nquit\n");
  CommandResult r = exr.wait(120);
  CHECK(r.exit_code == 0);
  CHECK(read_image(dir.file("view.exr")).channel_names.size() == 6);  // R, G, B and albedo.R/G/B
  args[3] = dir.file("view.png").string();
  RadiantProcess png(args, piped());
  png.write_stdin("set aov albedo\nquit\n");
  CHECK(png.wait(120).err.find("line 1: ") != std::string::npos);
}

TEST_CASE("session: value flags parse as render's, before or after the scene") {
  ScratchDir dir("session-flag-order");
  std::string scene = copy_scene(dir).string(), view = dir.file("view.png").string();
  // The scene last, after value flags; then no scene at all, loaded by the first command.
  RadiantProcess scene_last({"session", "-o", view, "--spp", "2", "--width", "16", "--height", "8", scene}, piped());
  scene_last.close_stdin();
  CommandResult r = scene_last.wait(120);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("16x8, 2 spp") != std::string::npos);
  fs::remove(view);
  RadiantProcess no_scene({"session", "-o", view, "--spp", "2", "--width", "16", "--height", "8", "-q"}, piped());
  no_scene.write_stdin("render " + scene + "\ninfo\n");
  no_scene.close_stdin();
  r = no_scene.wait(120);
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("16x8, 2 spp") != std::string::npos);
  CHECK(r.out.find("settings: --height 8 --log-level warning --spp 2 --width 16\n") != std::string::npos);
}

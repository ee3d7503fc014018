// SIGINT and SIGTERM sent to a real radiant process mid-render: it stops at the next pixel once
// every pixel has its first sample, writes what it rendered as a valid image marked partial,
// removes every temporary and exits 130 (SIGINT) or 143 (SIGTERM). A second signal aborts at
// once, still removing temporaries.
#include <doctest/doctest.h>

#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "support/child_process.h"
#include "support/test_scenes.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// closed_sphere_scene at 256 spp takes minutes: a signal always finds it rendering.
const std::vector<std::string> slow_render = {"--width", "32", "--height", "32", "--mode", "path", "--max-depth",
                                              "1000", "--spp", "256", "--threads", "1"};

ChildSetup with_terminal() {
  ChildSetup setup;
  setup.terminal_stderr = true;  // radiant prints its progress, so the test sees the render start
  return setup;
}

std::vector<std::string> hidden_files(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().filename().string()[0] == '.') names.push_back(entry.path().string());
  return names;
}

// Starts `args`, waits until it prints `started` (its render began) and a little longer, sends
// `signal` and waits for the exit.
CommandResult interrupt(const std::vector<std::string>& args, int signal, const std::string& started = "rendering") {
  RadiantProcess child(args, with_terminal());
  REQUIRE(child.wait_for_stderr(started, 60));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  child.send(signal);
  return child.wait(30);
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

std::vector<std::string> args_with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("interrupt: SIGINT mid-render writes the PNG so far marked partial, the stats too, and exits 130") {
  ScratchDir dir("sigint-png");
  fs::path scene = dir.write("closed.scene", closed_sphere_scene);
  fs::path out = dir.write("out.png", "old image"), stats = dir.file("stats.json");
  CommandResult r = interrupt(args_with({"render", scene, "-o", out, "--stats", stats}, slow_render), SIGINT);
  CHECK(r.exit_code == 130);
  CHECK(r.err.find("interrupted by SIGINT") != std::string::npos);
  CHECK(starts_with(image_attribute(out, "radiant:partial"), "interrupted by SIGINT at "));
  CHECK(read_image(out).width == 32);
  CHECK(read_bytes(stats).find("\"interrupted\": true") != std::string::npos);
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("interrupt: SIGTERM mid-render writes the EXR so far with its per-pixel sample counts and exits 143") {
  ScratchDir dir("sigterm-exr");
  fs::path scene = dir.write("closed.scene", closed_sphere_scene);
  fs::path out = dir.file("out.exr");
  CommandResult r = interrupt(args_with({"render", scene, "-o", out}, slow_render), SIGTERM);
  CHECK(r.exit_code == 143);
  // "interrupted by SIGTERM at N of 256 samples per pixel", N what every pixel reached.
  std::string partial = image_attribute(out, "radiant:partial");
  CHECK(starts_with(partial, "interrupted by SIGTERM at "));
  CHECK(partial.find(" of 256 samples per pixel") != std::string::npos);
  TestImage image = read_image(out);
  REQUIRE(image.channel_names.back() == "spp");
  float fewest = 1e9f;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      fewest = std::min(fewest, image.at(x, y, image.channels - 1));
    }
  CHECK(fewest >= 1);  // the first pass is whole: no black pixel
  CHECK(fewest < 256);  // it did stop
  CHECK(image_attribute(out, "radiant:spp") == std::to_string(int(fewest)));
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("interrupt: SIGTERM mid-render to HDR writes the image so far, three channels (no room for the counts)") {
  ScratchDir dir("sigterm-hdr");
  fs::path scene = dir.write("closed.scene", closed_sphere_scene);
  fs::path out = dir.file("out.hdr");
  CommandResult r = interrupt(args_with({"render", scene, "-o", out}, slow_render), SIGTERM);
  CHECK(r.exit_code == 143);
  TestImage image = read_image(out);
  CHECK(image.width == 32);
  CHECK(image.channels == 3);
  CHECK(hidden_files(dir.path).empty());
  // The mark is a line of the Radiance header, before the blank line that ends it.
  std::string bytes = read_bytes(out);
  std::string header = bytes.substr(0, bytes.find("\n\n"));
  CHECK(header.rfind("#?RADIANCE\n", 0) == 0);
  CHECK(header.find("\nradiant:partial=interrupted by SIGTERM at ") != std::string::npos);
}

TEST_CASE("interrupt: SIGHUP, SIGUSR1 and SIGALRM end a render as SIGINT does: partial image, no temporary, 128 + signal") {
  for (int signal : {SIGHUP, SIGUSR1, SIGALRM}) {
    CAPTURE(signal);
    ScratchDir dir("other-signals");
    fs::path scene = dir.write("closed.scene", closed_sphere_scene);
    fs::path out = dir.file("out.png"), stats = dir.file("stats.json");
    CommandResult r = interrupt(args_with({"render", scene, "-o", out, "--stats", stats}, slow_render), signal);
    CHECK(r.exit_code == 128 + signal);
    std::string name = std::string("SIG") + sigabbrev_np(signal);
    CHECK(image_attribute(out, "radiant:partial").rfind("interrupted by " + name + " at ", 0) == 0);
    CHECK(hidden_files(dir.path).empty());
  }
}

TEST_CASE("interrupt: SIGPIPE on standard output (-o - | head -c 10) ends the render at once and leaves no temporary") {
  ScratchDir dir("sigpipe");
  fs::path scene = dir.write("sphere.scene", lit_sphere_scene);
  fs::create_directory(dir.file("tmp"));
  // Noise and its variance (about 190 kB of EXR), far more than a pipe's buffer: head has gone
  // long before the last write.
  fs::path script = dir.write("pipe.sh", "TMPDIR=" + quoted(dir.file("tmp")) + " '" RADIANT_EXE "' render " + quoted(scene) +
                                             " -o - --format exr --mode path --env-color 1,1,1 --aov variance --width 256 --height 256 --spp 2 --quiet"
                                             " | head -c 10 > /dev/null\n"
                                             "echo \"${PIPESTATUS[0]}\" > " + quoted(dir.file("status.txt")) + "\n");
  REQUIRE(std::system(("bash " + quoted(script)).c_str()) == 0);
  CHECK(read_bytes(dir.file("status.txt")) == "141\n");
  CHECK(fs::is_empty(dir.file("tmp")));
}

TEST_CASE("interrupt: SIGINT during a batch writes the view in progress as partial and renders no further line") {
  ScratchDir dir("sigint-batch");
  dir.write("closed.scene", closed_sphere_scene);
  std::string flags;
  for (const std::string& word : slow_render) flags += " " + word;
  fs::path script = dir.write("views.txt", "scene closed.scene\nrender -o a.png" + flags + "\nrender -o b.png" + flags + "\n");
  CommandResult r = interrupt({"batch", script}, SIGINT);
  CHECK(r.exit_code == 130);
  CHECK(starts_with(image_attribute(dir.file("a.png"), "radiant:partial"), "interrupted by SIGINT at "));
  CHECK_FALSE(fs::exists(dir.file("b.png")));
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("interrupt: SIGINT mid-ladder ends converge with 130, its old report untouched and no temporary left") {
  ScratchDir dir("sigint-converge");
  fs::path scene = dir.write("closed.scene", closed_sphere_scene);
  fs::path csv = dir.write("report/converge.csv", "old csv");
  CommandResult r = interrupt({"converge", scene, "--out", dir.file("report"), "--width", "32", "--height", "32", "--mode",
                               "path", "--max-depth", "1000", "--threads", "1", "--spp-ladder", "1,64", "--reference-spp", "4"},
                              SIGINT, "ladder of");
  CHECK(r.exit_code == 130);
  CHECK(read_bytes(csv) == "old csv");
  CHECK_FALSE(fs::exists(dir.file("report/converge.json")));
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("interrupt: a second signal while the outputs are being written aborts at once and removes the temporaries") {
  ScratchDir dir("sigint-twice");
  fs::path scene = dir.write("closed.scene", closed_sphere_scene);
  fs::path csv = dir.write("report/converge.csv", "old csv");
  // A python3 that only says it started and then sleeps: converge's chart step, with the CSV
  // and JSON temporaries written, lasts as long as the test needs.
  fs::path marker = dir.file("chart-started");
  fs::path python = dir.write("bin/python3", "#!/bin/sh\ntouch '" + marker.string() + "'\nexec sleep 20\n");
  fs::permissions(python, fs::perms::owner_all);
  std::string path = getenv("PATH");
  setenv("PATH", (dir.file("bin").string() + ":" + path).c_str(), 1);
  RadiantProcess child({"converge", scene, "--out", dir.file("report"), "--width", "8", "--height", "8", "--mode", "path",
                        "--spp-ladder", "1", "--reference-spp", "2", "--quiet"});
  setenv("PATH", path.c_str(), 1);
  auto start = std::chrono::steady_clock::now();
  while (!fs::exists(marker) && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  REQUIRE(fs::exists(marker));
  CHECK(hidden_files(dir.file("report")).size() == 3);  // the CSV, JSON and chart temporaries
  child.send(SIGINT);  // deferred: the outputs are being written
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  child.send(SIGINT);  // aborts
  auto sent = std::chrono::steady_clock::now();
  CommandResult r = child.wait(30);
  CHECK(std::chrono::steady_clock::now() - sent < std::chrono::seconds(5));  // not after the 20 s sleep
  CHECK(r.exit_code == 130);
  CHECK(read_bytes(csv) == "old csv");
  CHECK(hidden_files(dir.path).empty());
}

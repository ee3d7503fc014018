// Every file radiant writes is checked to its end (write, flush, close): on a full disk the
// command exits 1 naming the file, replaces nothing and leaves no temporary behind. The disk is
// "full" through RLIMIT_FSIZE in the child (tests/support/child_process.h).
#include <doctest/doctest.h>

#include <filesystem>

#include "image/compare_test_images.h"
#include "support/child_process.h"
#include "support/test_scenes.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

// An 8x8 PNG of the plane without metadata (--no-metadata) takes about 190 bytes and its --stats
// JSON about 870.
constexpr rlim_t room_for_the_image_only = 500;

ChildSetup full_disk(rlim_t bytes) {
  ChildSetup setup;
  setup.file_size_limit = bytes;
  return setup;
}

// Names in `dir` that start with a dot: radiant's temporaries are hidden files.
std::vector<std::string> hidden_files(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().filename().string()[0] == '.') names.push_back(entry.path().string());
  return names;
}

}  // namespace

TEST_CASE("checked writes: --stats on a full disk exits 1, and neither the stats file nor -o is replaced") {
  ScratchDir dir("full-stats");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path image = dir.write("out.png", "old image"), stats = dir.write("stats.json", "old stats");
  CommandResult r = run_radiant_with({"render", scene, "-o", image, "--stats", stats, "--width", "8", "--height", "8",
                                      "--spp", "1", "--quiet", "--no-metadata"},
                                     full_disk(room_for_the_image_only));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("stats.json") != std::string::npos);
  CHECK(r.err.find("File too large") != std::string::npos);
  CHECK(read_bytes(stats) == "old stats");
  CHECK(read_bytes(image) == "old image");
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("checked writes: an image on a full disk exits 1 naming it, for PNG (libpng) and EXR (OpenImageIO)") {
  for (std::string extension : {".png", ".exr"}) {
    CAPTURE(extension);
    ScratchDir dir("full-image");
    fs::path scene = dir.write("plane.scene", lit_plane_scene);
    fs::path image = dir.write("out" + extension, "old image");
    CommandResult r = run_radiant_with({"render", scene, "-o", image, "--width", "32", "--height", "32", "--spp", "1", "--quiet"},
                                       full_disk(100));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("out" + extension) != std::string::npos);
    CHECK(read_bytes(image) == "old image");
    CHECK(hidden_files(dir.path).empty());
  }
}

TEST_CASE("checked writes: a file size limit is a write error, not a death by SIGXFSZ that leaves a temporary") {
  ScratchDir dir("full-signal");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  ChildSetup setup = full_disk(100);
  setup.keep_file_size_signal = true;
  CommandResult r = run_radiant_with({"render", scene, "-o", dir.file("out.exr"), "--width", "32", "--height", "32",
                                      "--spp", "1", "--quiet"},
                                     setup);
  CHECK(r.exit_code == 1);
  CHECK_FALSE(fs::exists(dir.file("out.exr")));
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("checked writes: a batch line's --stats on a full disk stops the batch with exit 1 naming script:line") {
  ScratchDir dir("full-batch");
  dir.write("plane.scene", lit_plane_scene);
  fs::path stats = dir.write("stats.json", "old stats");
  fs::path script = dir.write("views.txt",
                              "scene plane.scene\n"
                              "render -o a.png --width 8 --height 8 --spp 1 --quiet --no-metadata --stats stats.json\n");
  CommandResult r = run_radiant_with({"batch", script}, full_disk(room_for_the_image_only));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("views.txt:2:") != std::string::npos);
  CHECK(read_bytes(stats) == "old stats");
  CHECK_FALSE(fs::exists(dir.file("a.png")));
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("checked writes: compare --diff on a full disk is an error (exit 2) and leaves the old file") {
  ScratchDir dir("full-diff");
  fs::path a = dir.file("a.exr"), b = dir.file("b.exr");
  write_rgb(a, 8, 4, ramp_rgb(8, 4));
  write_rgb(b, 8, 4, scaled(ramp_rgb(8, 4), 1.05f));
  fs::path diff = dir.write("diff.exr", "old diff");
  CommandResult r = run_radiant_with({"compare", a, b, "--diff", diff}, full_disk(100));
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("diff.exr") != std::string::npos);
  CHECK(read_bytes(diff) == "old diff");
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("checked writes: converge on a full disk exits 1 and replaces none of its report files") {
  ScratchDir dir("full-converge");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path csv = dir.write("report/converge.csv", "old csv"), json = dir.write("report/converge.json", "old json");
  // The CSV (about 250 bytes) fits, the JSON (over 1 KB) does not.
  CommandResult r = run_radiant_with({"converge", scene, "--out", dir.file("report"), "--width", "8", "--height", "8",
                                      "--spp-ladder", "1,2", "--reference-spp", "4", "--mode", "path", "--quiet"},
                                     full_disk(600));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("converge.json") != std::string::npos);
  CHECK(read_bytes(csv) == "old csv");
  CHECK(read_bytes(json) == "old json");
  CHECK(hidden_files(dir.path).empty());
}

TEST_CASE("checked writes: standard output that cannot be written (a redirect to a full disk) exits 1") {
  ScratchDir dir("full-stdout");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  // The JSON takes over 500 bytes; the limit leaves room for the error on stderr.
  CommandResult r = run_radiant_with({"info", scene, "--json"}, full_disk(200));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("cannot write to standard output") != std::string::npos);
}

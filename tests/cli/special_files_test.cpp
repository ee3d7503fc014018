// Special files given where radiant reads or writes images: a device or FIFO as an output is
// streamed through (never replaced by a regular file), a read-only file is refused, and a FIFO
// or device given as an image to read is refused before it is opened, where reading would block
// or never end.
#include <doctest/doctest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "image/compare_test_images.h"
#include "support/fifo_reader.h"
#include "support/test_scenes.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

bool mentions(const CommandResult& r, const std::string& text) { return r.err.find(text) != std::string::npos; }

std::string render_flags() { return " --width 8 --height 8 --spp 1 --quiet"; }

}  // namespace

TEST_CASE("special outputs: --stats through a symlink to /dev/null leaves the link and the device as they are") {
  ScratchDir dir("stats-null");
  fs::path scene = dir.write("plane.scene", lit_plane_scene), link = dir.file("null.json");
  fs::create_symlink("/dev/null", link);
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("out.png")) + " --stats " +
                                quoted(link) + render_flags());
  CHECK(r.exit_code == 0);
  CHECK(fs::is_symlink(link));
  struct stat status;
  REQUIRE(stat("/dev/null", &status) == 0);
  CHECK(S_ISCHR(status.st_mode));
  CHECK(fs::exists(dir.file("out.png")));
}

TEST_CASE("special outputs: -o a FIFO streams the image to its reader, as -o - does, and the FIFO stays") {
  ScratchDir dir("image-fifo");
  fs::path scene = dir.write("plane.scene", lit_plane_scene), fifo = dir.file("view.png");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  FifoReader reader(fifo);
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(fifo) + render_flags());
  std::string received = reader.finish();
  CHECK(r.exit_code == 0);
  CHECK(received.substr(0, 8) == "\x89PNG\r\n\x1a\n");
  CHECK(fs::is_fifo(fifo));
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 2);  // no temporary left
}

TEST_CASE("special outputs: a read-only -o or compare --diff is refused with one line, exit 1, untouched") {
  ScratchDir dir("read-only-output");
  fs::path scene = dir.write("plane.scene", lit_plane_scene), golden = dir.write("golden.png", "golden");
  REQUIRE(chmod(golden.c_str(), 0444) == 0);
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(golden) + render_flags());
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: cannot write '" + golden.string() + "': it is read-only\n");
  CHECK(read_bytes(golden) == "golden");
  write_rgb(dir.file("a.exr"), 2, 2, ramp_rgb(2, 2));
  CommandResult diff = run_radiant("compare " + quoted(dir.file("a.exr")) + " " + quoted(dir.file("a.exr")) + " --diff " +
                                   quoted(golden));
  CHECK(diff.exit_code == 2);
  CHECK(mentions(diff, "it is read-only"));
  CHECK(read_bytes(golden) == "golden");
}

TEST_CASE("special inputs: compare, --variance, merge, info and converge --reference refuse a FIFO or /dev/zero at once") {
  ScratchDir dir("special-inputs");
  write_rgb(dir.file("a.exr"), 2, 2, ramp_rgb(2, 2));
  fs::path fifo = dir.file("pipe.exr"), zero = dir.file("zero.exr");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  fs::create_symlink("/dev/zero", zero);
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  std::string a = quoted(dir.file("a.exr"));
  for (const fs::path& special : {fifo, zero}) {
    CAPTURE(special);
    std::string s = quoted(special);
    for (const std::string& command :
         {"compare " + s + " " + a, "compare " + a + " " + s, "compare " + a + " " + a + " --variance " + s + " --spp 4",
          "merge " + s + " -o " + quoted(dir.file("merged.exr")), "info " + s,
          "converge " + quoted(scene) + " --reference " + s + " --spp-ladder 1 --out " + quoted(dir.file("report"))}) {
      CAPTURE(command);
      CommandResult r = run_radiant(command, "", 20);  // a read that blocks is killed: exit 124
      CHECK((r.exit_code == 1 || r.exit_code == 2));
      CHECK(mentions(r, special.filename().string()));
      CHECK(mentions(r, "is not a regular file"));
    }
  }
  CHECK(fs::is_fifo(fifo));
}

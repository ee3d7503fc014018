// `--max-memory` on the command line: validated, honoured by `render` and `batch` (and by batch
// render lines), charged for the film, the output image and environment maps; huge inputs are
// refused before they are read, and running out of memory anyway is one clear line.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "support/hostile_files.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A tiny scene and the start of a command that renders it into `dir`.
std::string render_command(const ScratchDir& dir, const std::string& output = "out.png") {
  return "render " + quoted(source_path("assets/first-render.scene")) + " -o " + quoted(dir.file(output)) +
         " --spp 1 -q";
}

constexpr uint64_t GiB = uint64_t(1) << 30;

}  // namespace

TEST_CASE("max-memory flag: a cap that is not a positive finite number of at least one byte is a usage error") {
  ScratchDir dir("max-memory-values");
  for (const char* value : {"0", "-1", "nan", "inf", "1e-10", "abc"}) {
    CAPTURE(value);
    CommandResult r = run_radiant(render_command(dir) + " --width 8 --height 8 --max-memory " + value);
    CHECK(r.exit_code == 2);
    CHECK(contains(r.err, "--max-memory"));
    CHECK_FALSE(fs::exists(dir.file("out.png")));
  }
  CommandResult tiny = run_radiant(render_command(dir) + " --width 8 --height 8 --max-memory 1e-10");
  CHECK(tiny.err == "radiant render: --max-memory: 1e-10 GiB is less than one byte\n");
  // Beyond what 64 bits count is no cap at all, not undefined behaviour.
  CommandResult huge = run_radiant(render_command(dir) + " --width 8 --height 8 --max-memory 1e30");
  CHECK(huge.exit_code == 0);
  CHECK(fs::exists(dir.file("out.png")));
}

TEST_CASE("max-memory flag: the film and output image are charged before the render allocates them") {
  ScratchDir dir("max-memory-film");
  MeasuredRun run = run_radiant_measured(render_command(dir, "big.exr") +
                                             " --width 4096 --height 4096 --aov albedo,normal,depth,variance,spp"
                                             " --max-memory 0.25",
                                         60, built_with_address_sanitizer ? 0 : 2 * GiB);
  CHECK(run.result.exit_code == 1);
  CHECK(contains(run.result.err, "first-render.scene: a 4096x4096 render with 14 channels (film, AOVs and output "
                                 "image): "));
  CHECK(contains(run.result.err, "over the memory limit of 256 MiB (--max-memory)"));
  CHECK_FALSE(fs::exists(dir.file("big.exr")));
  // The largest image the flags allow is refused the same way, not with std::bad_alloc.
  MeasuredRun largest = run_radiant_measured(render_command(dir) + " --width 65536 --height 65536", 60,
                                             built_with_address_sanitizer ? 0 : 2 * GiB);
  CHECK(largest.result.exit_code == 1);
  CHECK(contains(largest.result.err, "a 65536x65536 render with 3 channels"));
  CHECK(contains(largest.result.err, "(a quarter of RAM; raise it with --max-memory)"));
}

TEST_CASE("max-memory flag: an environment map is charged by its declared size before it is decoded") {
  ScratchDir dir("max-memory-env");
  fs::path map = dir.write("big.hdr", hdr_header_only(20000, 10000));
  MeasuredRun run = run_radiant_measured(render_command(dir) + " --width 8 --height 8 --mode path --env " +
                                             quoted(map) + " --max-memory 0.25",
                                         60, built_with_address_sanitizer ? 0 : 2 * GiB);
  CHECK(run.result.exit_code == 1);
  CHECK(contains(run.result.err, "big.hdr: decoding its 20000x10000 pixels: 2.24 GiB needed"));
  CHECK(contains(run.result.err, "over the memory limit of 256 MiB (--max-memory)"));
  REQUIRE(mkfifo(dir.file("pipe.hdr").c_str(), 0600) == 0);
  CommandResult pipe = run_radiant(render_command(dir) + " --width 8 --height 8 --env " + quoted(dir.file("pipe.hdr")),
                                   "", 20);
  CHECK(pipe.exit_code == 1);
  CHECK(contains(pipe.err, "pipe.hdr: cannot read environment map: is not a regular file"));
}

TEST_CASE("max-memory flag: batch takes it for the whole script and render lines for their render") {
  ScratchDir dir("max-memory-batch");
  fs::copy_file(source_path("assets/first-render.scene"), dir.file("s.scene"));
  fs::path script = dir.write("views.txt", "scene s.scene\nrender -o a.png --width 1024 --height 1024 --spp 1\n");
  CommandResult capped = run_radiant("batch --max-memory 0.01 -q " + quoted(script));
  CHECK(capped.exit_code == 1);
  CHECK(contains(capped.err, "views.txt:2: "));
  CHECK(contains(capped.err, "a 1024x1024 render with 3 channels"));
  CHECK(contains(capped.err, "over the memory limit of 10.2 MiB (--max-memory)"));
  CHECK_FALSE(fs::exists(dir.file("a.png")));

  fs::path lines = dir.write("lines.txt",
                             "scene s.scene\n"
                             "render -o b.png --width 8 --height 8 --spp 1 -q\n"
                             "render -o c.png --width 1024 --height 1024 --spp 1 --max-memory 0.01\n");
  CommandResult line = run_radiant("batch " + quoted(lines));
  CHECK(line.exit_code == 1);
  CHECK(contains(line.err, "lines.txt:3: "));
  CHECK(contains(line.err, "over the memory limit of 10.2 MiB (--max-memory on this line)"));
  CHECK_FALSE(fs::exists(dir.file("c.png")));
}

TEST_CASE("max-memory flag: a batch line over the documented maximum length is an error naming it") {
  ScratchDir dir("max-memory-batch-line");
  fs::copy_file(source_path("assets/first-render.scene"), dir.file("s.scene"));
  std::string long_line = "render -o a.png --width 8 --height 8 --spp 1" + std::string(70000, ' ') + "\n";
  fs::path script = dir.write("long.txt", "scene s.scene\n" + long_line);
  CommandResult r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant batch: " + script.string() + ":2: line is longer than 65536 characters\n");
  CHECK_FALSE(fs::exists(dir.file("a.png")));
}

TEST_CASE("max-memory flag: a glTF over 4 GB is refused by its size, before it is read") {
  ScratchDir dir("max-memory-4gb");
  fs::path huge = dir.file("huge.gltf");
  std::ofstream(huge) << "{";
  fs::resize_file(huge, (uint64_t(9) << 29));  // 4.5 GiB, sparse: no disk space used
  MeasuredRun run = run_radiant_measured("render " + quoted(huge) + " -o " + quoted(dir.file("out.png")) +
                                             " --max-memory 100",
                                         60, built_with_address_sanitizer ? 0 : 2 * GiB);
  CHECK(run.result.exit_code == 1);
  CHECK(run.result.err == "radiant: " + huge.string() + ": files over 4 GB are not supported\n");
}

TEST_CASE("max-memory flag: running out of memory below the cap names the file and what was being done") {
  if (built_with_address_sanitizer) return;  // RLIMIT_AS and the sanitizer's shadow memory do not mix
  ScratchDir dir("max-memory-bad-alloc");
  MeasuredRun run = run_radiant_measured(render_command(dir) + " --width 16384 --height 16384 --max-memory 1000", 60,
                                         GiB);
  CHECK(run.result.exit_code == 1);
  std::string scene = source_path("assets/first-render.scene").string();
  CHECK(run.result.err == "radiant: " + scene +
                              ": out of memory while rendering (the memory limit is 1000 GiB; a --max-memory below "
                              "what this machine can give refuses such work before it allocates)\n");
}

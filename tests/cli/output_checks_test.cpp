// Every output is checked before any work: an extension that names no image format is a usage
// error (exit 2), a place where the file cannot be created exits 1, and an output that is the
// same file as another output or as an input is refused (exit 2). A missing scene shows the
// order: the output's error comes first, so nothing was loaded.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>

#include "image/compare_test_images.h"
#include "support/child_process.h"
#include "support/test_scenes.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {


bool mentions(const CommandResult& r, const std::string& text) { return r.err.find(text) != std::string::npos; }

}  // namespace

TEST_CASE("output checks: -o without an image format's extension is a usage error before the scene is read") {
  ScratchDir dir("check-format");
  for (std::string name : {"out.xyz", "out", "out.pfm"}) {
    CAPTURE(name);
    CommandResult r = run_radiant("render " + quoted(dir.file("missing.scene")) + " -o " + quoted(dir.file(name)));
    CHECK(r.exit_code == 2);
    CHECK(mentions(r, name));
    CHECK_FALSE(mentions(r, "missing.scene"));
  }
  CHECK(fs::is_empty(dir.path));
}

TEST_CASE("output checks: a missing folder, a file as a folder and a folder as the file exit 1 before the scene is read") {
  ScratchDir dir("check-place");
  dir.write("file.txt", "a file");
  fs::create_directory(dir.file("folder.png"));
  fs::path scene = dir.file("missing.scene");
  for (fs::path out : {dir.file("no/such/folder/out.png"), dir.file("file.txt/out.png"), dir.file("folder.png")}) {
    CAPTURE(out);
    CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(out));
    CHECK(r.exit_code == 1);
    CHECK(mentions(r, out.string()));
    CHECK_FALSE(mentions(r, "missing.scene"));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
}

TEST_CASE("output checks: a read-only folder exits 1 before the scene is read (as nobody when the tests run as root)") {
  ScratchDir dir("check-readonly");
  fs::create_directory(dir.file("ro"));
  chmod(dir.file("ro").c_str(), 0555);
  ChildSetup unprivileged;
  unprivileged.unprivileged = true;
  CommandResult r = run_radiant_with({"render", dir.file("missing.scene"), "-o", dir.file("ro/out.png")}, unprivileged);
  CHECK(r.exit_code == 1);
  CHECK(mentions(r, "ro/out.png"));
  CHECK(mentions(r, "not writable"));
  CHECK_FALSE(mentions(r, "missing.scene"));
}

TEST_CASE("output checks: --stats in a missing folder exits 1 before rendering and -o is neither written nor replaced") {
  ScratchDir dir("check-stats");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path image = dir.write("out.png", "old image");
  CommandResult r = run_radiant("render " + quoted(scene) + " -o " + quoted(image) + " --stats " +
                                quoted(dir.file("no/stats.json")) + " --width 8 --height 8 --spp 1 --quiet");
  CHECK(r.exit_code == 1);
  CHECK(mentions(r, "no/stats.json"));
  CHECK(read_bytes(image) == "old image");
}

TEST_CASE("output checks: converge refuses a report folder it cannot create before the scene is read") {
  ScratchDir dir("check-converge");
  fs::path file = dir.write("report.txt", "a file");
  for (fs::path out : {file, file / "sub"}) {
    CAPTURE(out);
    CommandResult r = run_radiant("converge " + quoted(dir.file("missing.scene")) + " --out " + quoted(out));
    CHECK(r.exit_code == 1);
    CHECK(mentions(r, out.string()));
    CHECK_FALSE(mentions(r, "missing.scene"));
  }
  CHECK(read_bytes(file) == "a file");
}

TEST_CASE("output checks: compare --diff in a format radiant cannot write or in a missing folder fails before reading") {
  ScratchDir dir("check-diff");
  fs::path a = dir.file("missing-a.exr"), b = dir.file("missing-b.exr");
  for (std::string diff : {"diff.xyz", "no/diff.png"}) {
    CAPTURE(diff);
    CommandResult r = run_radiant("compare " + quoted(a) + " " + quoted(b) + " --diff " + quoted(dir.file(diff)));
    CHECK(r.exit_code == 2);  // compare's errors are all 2: 1 means the images differ
    CHECK(mentions(r, diff));
    CHECK_FALSE(mentions(r, "missing-a.exr"));
  }
}

TEST_CASE("output checks: a batch script's outputs are all checked before its first line renders") {
  ScratchDir dir("check-batch");
  dir.write("plane.scene", lit_plane_scene);
  fs::path script = dir.write("views.txt",
                              "scene plane.scene\n"
                              "render -o a.png --width 8 --height 8 --spp 1 --quiet\n"
                              "render -o b.xyz --width 8 --height 8 --spp 1 --quiet\n"
                              "render -o no/c.png --width 8 --height 8 --spp 1 --quiet\n");
  CommandResult r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(mentions(r, "views.txt:3:"));
  CHECK(mentions(r, "b.xyz"));
  CHECK_FALSE(fs::exists(dir.file("a.png")));
  dir.write("views.txt",
            "scene plane.scene\n"
            "render -o a.png --width 8 --height 8 --spp 1 --quiet\n"
            "render -o no/c.png --width 8 --height 8 --spp 1 --quiet\n");
  r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(mentions(r, "views.txt:3:"));
  CHECK(mentions(r, "no/c.png"));
  CHECK_FALSE(fs::exists(dir.file("a.png")));
}

TEST_CASE("same file: --stats same.png -o same.png is refused, and so is an output over the scene or --env") {
  ScratchDir dir("same-render");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::path sky = dir.file("sky.exr");
  write_rgb(sky, 4, 2, std::vector<float>(24, 0.5f));
  std::string sky_bytes = read_bytes(sky);
  std::string base = "render " + quoted(scene) + " --width 8 --height 8 --spp 1 --quiet ";
  CommandResult same = run_radiant(base + "-o " + quoted(dir.file("same.png")) + " --stats " + quoted(dir.file("same.png")));
  CHECK(same.exit_code == 2);
  CHECK(mentions(same, "--stats"));
  CHECK_FALSE(fs::exists(dir.file("same.png")));
  // The scene through another spelling of its path.
  CommandResult over_scene = run_radiant(base + "-o " + quoted(dir.file("out.png")) + " --stats " +
                                         quoted(dir.path / "." / "plane.scene"));
  CHECK(over_scene.exit_code == 2);
  CHECK(mentions(over_scene, "the scene"));
  CHECK(read_bytes(scene) == lit_plane_scene);
  CommandResult over_env = run_radiant(base + "-o " + quoted(sky) + " --env " + quoted(sky));
  CHECK(over_env.exit_code == 2);
  CHECK(read_bytes(sky) == sky_bytes);
  // By identity: a symlink to the map and a hard link to it are the map.
  fs::create_symlink(sky, dir.file("link.exr"));
  fs::create_hard_link(sky, dir.file("hard.exr"));
  for (std::string other : {"link.exr", "hard.exr"}) {
    CAPTURE(other);
    CommandResult r = run_radiant(base + "-o " + quoted(dir.file(other)) + " --env " + quoted(sky));
    CHECK(r.exit_code == 2);
    CHECK(read_bytes(sky) == sky_bytes);
  }
  CHECK_FALSE(fs::exists(dir.file("out.png")));
}

TEST_CASE("same file: compare --diff onto an input is refused and the input is untouched") {
  ScratchDir dir("same-compare");
  fs::path a = dir.file("a.exr"), b = dir.file("b.exr");
  write_rgb(a, 8, 4, ramp_rgb(8, 4));
  write_rgb(b, 8, 4, scaled(ramp_rgb(8, 4), 1.05f));
  std::string a_bytes = read_bytes(a);
  CommandResult r = run_radiant("compare " + quoted(a) + " " + quoted(b) + " --diff " + quoted(a));
  CHECK(r.exit_code == 2);
  CHECK(mentions(r, "--diff"));
  CHECK(read_bytes(a) == a_bytes);
}

TEST_CASE("same file: converge refuses a --reference that is one of its report files") {
  ScratchDir dir("same-converge");
  fs::path scene = dir.write("plane.scene", lit_plane_scene);
  fs::create_directory(dir.file("report"));
  fs::path reference = dir.file("report/converge.png");
  write_rgb(reference, 8, 8, std::vector<float>(192, 0.5f));
  std::string bytes = read_bytes(reference);
  CommandResult r = run_radiant("converge " + quoted(scene) + " --out " + quoted(dir.file("report")) + " --reference " +
                                quoted(reference) + " --mode path --spp-ladder 1 --quiet");
  CHECK(r.exit_code == 2);
  CHECK(mentions(r, "--reference"));
  CHECK(read_bytes(reference) == bytes);
}

TEST_CASE("same file: batch refuses two lines writing one file and an output over the script, naming the line") {
  ScratchDir dir("same-batch");
  dir.write("plane.scene", lit_plane_scene);
  fs::path script = dir.write("views.txt",
                              "scene plane.scene\n"
                              "render -o a.png --width 8 --height 8 --spp 1 --quiet\n"
                              "render -o ./a.png --width 8 --height 8 --spp 1 --quiet\n");
  CommandResult twice = run_radiant("batch " + quoted(script));
  CHECK(twice.exit_code == 1);
  CHECK(mentions(twice, "views.txt:3:"));
  CHECK(mentions(twice, "line 2"));
  CHECK_FALSE(fs::exists(dir.file("a.png")));
  std::string text = "scene plane.scene\nrender -o a.png --width 8 --height 8 --spp 1 --quiet --stats views.txt\n";
  dir.write("views.txt", text);
  CommandResult over_script = run_radiant("batch " + quoted(script));
  CHECK(over_script.exit_code == 1);
  CHECK(mentions(over_script, "views.txt:2:"));
  CHECK(mentions(over_script, "the script"));
  CHECK(read_bytes(script) == text);
}

TEST_CASE("same file: an output over a file the scene reads (texture, MTL, glTF buffer) is refused before rendering") {
  ScratchDir dir("same-scene-files");
  write_texel_bytes(dir.file("tex.png"), 2, 2, 3, std::vector<unsigned char>(12, 200));
  dir.write("box.mtl", "newmtl wall\nKd 1 1 1\nmap_Kd tex.png\n");
  fs::path obj = dir.write("quad.obj", "mtllib box.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl wall\nf 1/1 2/2 3/3 4/4\n");
  std::string texture = read_bytes(dir.file("tex.png")), mtl = read_bytes(dir.file("box.mtl"));
  std::string base = "render " + quoted(obj) + " --width 8 --height 8 --spp 1 --env-color 1,1,1 --quiet ";
  CommandResult over_texture = run_radiant(base + "-o " + quoted(dir.file("tex.png")));
  CHECK(over_texture.exit_code == 2);
  CHECK(mentions(over_texture, "a file the scene reads"));
  CHECK(read_bytes(dir.file("tex.png")) == texture);
  CommandResult over_mtl = run_radiant(base + "-o " + quoted(dir.file("out.png")) + " --stats " + quoted(dir.file("box.mtl")));
  CHECK(over_mtl.exit_code == 2);
  CHECK(read_bytes(dir.file("box.mtl")) == mtl);
  CHECK_FALSE(fs::exists(dir.file("out.png")));
  // The same in a batch line: the script stops before its first render.
  fs::path script = dir.write("views.txt", "scene quad.obj\nrender -o first.png --width 8 --height 8 --spp 1 --quiet\n"
                                           "render -o tex.png --width 8 --height 8 --spp 1 --quiet\n");
  CommandResult batch = run_radiant("batch " + quoted(script));
  CHECK(batch.exit_code == 1);
  CHECK(mentions(batch, "views.txt:3:"));
  CHECK_FALSE(fs::exists(dir.file("first.png")));
  CHECK(read_bytes(dir.file("tex.png")) == texture);
}

TEST_CASE("outputs: -o - writes the image to standard output in --format, --stats - the JSON") {
  ScratchDir dir("stdout-outputs");
  fs::path scene = dir.write("s.scene", lit_plane_scene);
  // No metadata: the command lines differ (-o), the bytes must not.
  std::string render = "render " + quoted(scene) + " --width 8 --height 8 --spp 1 --quiet --no-metadata";
  CommandResult file = run_radiant(render + " -o " + quoted(dir.file("o.png")));
  REQUIRE(file.exit_code == 0);
  CommandResult piped = run_radiant(render + " -o -");
  REQUIRE(piped.exit_code == 0);
  CHECK(piped.out == read_bytes(dir.file("o.png")));  // PNG unless --format says otherwise
  CommandResult exr = run_radiant(render + " -o - --format exr");
  REQUIRE(exr.exit_code == 0);
  CHECK(exr.out.substr(0, 4) == std::string("\x76\x2f\x31\x01", 4));  // OpenEXR's magic number
  CommandResult stats = run_radiant(render + " -o " + quoted(dir.file("p.png")) + " --stats -");
  REQUIRE(stats.exit_code == 0);
  CHECK(stats.out.find("\"rays_per_second\"") != std::string::npos);
  CHECK(read_bytes(dir.file("p.png")) == read_bytes(dir.file("o.png")));
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(fs::temp_directory_path()))
    if (entry.path().filename().string().find("radiant-standard-output") != std::string::npos) left.push_back(entry.path());
  CHECK(left.empty());  // the temporaries behind standard output are gone
}

TEST_CASE("outputs: standard output for two outputs, --format for a file and a bad --format are usage errors") {
  ScratchDir dir("stdout-refusals");
  fs::path scene = dir.write("s.scene", lit_plane_scene);
  std::string render = "render " + quoted(scene) + " --width 8 --height 8 --spp 1";
  CommandResult both = run_radiant(render + " -o - --stats -");
  CHECK(both.exit_code == 2);
  CHECK(both.err.find("--stats '-' is the same file as -o '-'") != std::string::npos);
  CHECK(both.out.empty());
  CommandResult format = run_radiant(render + " -o " + quoted(dir.file("o.png")) + " --format exr");
  CHECK(format.exit_code == 2);
  CHECK(format.err.find("--format is for -o -") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("o.png")));
  CommandResult unknown = run_radiant(render + " -o - --format xyz");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.out.empty());
}

// A session writes only where render and batch would: never over the scene it loaded, a file the
// scene reads (texture, MTL, glTF buffer), or one of its own outputs, whichever command writes
// (session -o, set stats, save). A refused setting is not kept.
#include <doctest/doctest.h>

#include <filesystem>

#include "support/child_process.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

ChildSetup piped() {
  ChildSetup setup;
  setup.piped_stdin = true;
  return setup;
}

// A textured quad: quad.obj reads box.mtl, which reads tex.png.
fs::path textured_quad(const ScratchDir& dir) {
  write_texel_bytes(dir.file("tex.png"), 2, 2, 3, std::vector<unsigned char>(12, 200));
  dir.write("box.mtl", "newmtl wall\nKd 1 1 1\nmap_Kd tex.png\n");
  return dir.write("quad.obj", "mtllib box.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl wall\nf 1/1 2/2 3/3 4/4\n");
}

CommandResult run_session(const std::vector<std::string>& args, const std::string& commands) {
  RadiantProcess session(args, piped());
  session.write_stdin(commands);
  session.close_stdin();
  return session.wait(120);
}

}  // namespace

TEST_CASE("session outputs: set stats, save and -o over the scene, its MTL, its texture or -o itself are refused") {
  ScratchDir dir("session-outputs");
  fs::path obj = textured_quad(dir);
  std::string scene = read_bytes(obj), mtl = read_bytes(dir.file("box.mtl")), texture = read_bytes(dir.file("tex.png"));
  std::vector<std::string> args = {"session", obj.string(), "-o", dir.file("view.png").string(), "--width", "8",
                                   "--height", "8", "--spp", "1", "--env-color", "1,1,1"};
  CommandResult r = run_session(args, "wait\nset stats " + obj.string() + "\nset stats " + dir.file("box.mtl").string() +
                                          "\nsave " + dir.file("tex.png").string() + "\nset stats " +
                                          dir.file("view.png").string() + "\nset spp 2\nwait\n");
  CHECK(r.err.find("line 2: --stats '" + obj.string() + "' is the same file as the scene") != std::string::npos);
  CHECK(r.err.find("line 3: --stats '" + dir.file("box.mtl").string() + "' is the same file as a file the scene reads") !=
        std::string::npos);
  CHECK(r.err.find("line 4: save '" + dir.file("tex.png").string() + "' is the same file as a file the scene reads") !=
        std::string::npos);
  CHECK(r.err.find("line 5: --stats '" + dir.file("view.png").string() + "' is the same file as -o") != std::string::npos);
  CHECK(r.err.find("line 6") == std::string::npos);  // the refused settings were not kept
  CHECK(r.exit_code == 2);
  CHECK(read_bytes(obj) == scene);
  CHECK(read_bytes(dir.file("box.mtl")) == mtl);
  CHECK(read_bytes(dir.file("tex.png")) == texture);

  std::vector<std::string> over_texture = {"session", obj.string(), "-o", dir.file("tex.png").string(), "--width", "8",
                                           "--height", "8", "--spp", "1"};
  CommandResult o = run_session(over_texture, "wait\n");
  CHECK(o.err.find("-o '" + dir.file("tex.png").string() + "' is the same file as a file the scene reads") != std::string::npos);
  CHECK(o.exit_code == 2);
  CHECK(read_bytes(dir.file("tex.png")) == texture);
  CommandResult over_scene = run_session({"session", obj.string(), "-o", obj.string() + ".png", "--stats", obj.string()}, "");
  CHECK(over_scene.exit_code == 2);
  CHECK(read_bytes(obj) == scene);
}

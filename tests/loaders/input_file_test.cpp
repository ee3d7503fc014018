// Every file a loader reads is checked before it is opened: a FIFO, a device or a folder named
// by a scene is refused with one line instead of blocking forever or failing obscurely. The
// FIFO cases run the CLI with a timeout, so that a regression fails instead of hanging.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>

#include "load_scene.h"
#include "support/load_errors.h"
#include "support/hostile_files.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

void make_fifo(const fs::path& path) { REQUIRE(mkfifo(path.c_str(), 0600) == 0); }

// Renders `scene` in `dir` with a short timeout; returns stderr with the folder removed.
CommandResult render_with_timeout(const ScratchDir& dir, const std::string& scene) {
  CommandResult r = run_radiant("render '" + dir.file(scene).string() + "' -o '" + dir.file("out.png").string() +
                                "' --width 8 --height 8 --spp 1 --env-color 1,1,1 -q", "", 20);
  r.err = dir.without_path(r.err);
  return r;
}

}  // namespace

TEST_CASE("input files: a glTF image that is missing, a folder or a FIFO says so") {
  ScratchDir dir("input-gltf-image");
  dir.write("missing.gltf", gltf_textured_triangle("nothing.png"));
  CHECK(load_error(dir, dir.file("missing.gltf")) == "missing.gltf: images[0].uri 'nothing.png': no such file");
  fs::create_directory(dir.file("folder.png"));
  dir.write("folder.gltf", gltf_textured_triangle("folder.png"));
  CHECK(load_error(dir, dir.file("folder.gltf")) == "folder.gltf: images[0].uri 'folder.png': is a directory");
  make_fifo(dir.file("pipe.png"));
  dir.write("pipe.gltf", gltf_textured_triangle("pipe.png"));
  CommandResult r = render_with_timeout(dir, "pipe.gltf");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: pipe.gltf: images[0].uri 'pipe.png': is not a regular file\n");
}

TEST_CASE("input files: a glTF buffer that is a folder or a FIFO says so") {
  ScratchDir dir("input-gltf-buffer");
  std::string text = gltf_with_extras(1);
  size_t data = text.find("data:");
  std::string with_file = text.substr(0, data) + "buffer.bin" + text.substr(text.find('"', data));
  fs::create_directory(dir.file("buffer.bin"));
  dir.write("folder.gltf", with_file);
  CHECK(load_error(dir, dir.file("folder.gltf")) == "folder.gltf: buffers[0].uri 'buffer.bin': is a directory");
}

TEST_CASE("input files: an OBJ mtllib or MTL map that is a FIFO is refused, not waited on") {
  ScratchDir dir("input-obj-fifo");
  make_fifo(dir.file("pipe.mtl"));
  dir.write("mtllib.obj", obj_using_mtl("pipe.mtl"));
  CommandResult r = render_with_timeout(dir, "mtllib.obj");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: mtllib.obj: mtllib 'pipe.mtl': is not a regular file\n");

  make_fifo(dir.file("pipe.png"));
  std::string mtl;
  dir.write("map.obj", obj_textured_triangle("map.mtl", "pipe.png", mtl));
  dir.write("map.mtl", mtl);
  r = render_with_timeout(dir, "map.obj");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: map.obj: material 't' map_Kd 'pipe.png': is not a regular file\n");
}

TEST_CASE("input files: an OBJ mtllib or MTL map that is a folder says so (a missing one is a warning)") {
  ScratchDir dir("input-obj-missing");
  dir.write("mtllib.obj", obj_using_mtl("none.mtl"));
  CHECK(load_error(dir, dir.file("mtllib.obj")) == "no error");
  fs::create_directory(dir.file("folder.png"));
  std::string mtl;
  dir.write("map.obj", obj_textured_triangle("map.mtl", "folder.png", mtl));
  dir.write("map.mtl", mtl);
  CHECK(load_error(dir, dir.file("map.obj")) == "map.obj: material 't' map_Kd 'folder.png': is a directory");
}

TEST_CASE("input files: a .scene @mesh that is a FIFO is refused, not waited on") {
  ScratchDir dir("input-mesh-fifo");
  make_fifo(dir.file("pipe.obj"));
  dir.write("mesh.scene", "@mesh\nfile pipe.obj\n");
  CommandResult r = render_with_timeout(dir, "mesh.scene");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant: mesh.scene:2:6: 'pipe.obj': is not a regular file\n");
}

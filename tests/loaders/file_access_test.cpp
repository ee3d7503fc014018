// resolve_inside and the glTF/OBJ loaders' use of it: no escapes from the scene's folder.
#include <doctest/doctest.h>

#include <filesystem>

#include "file_access.h"
#include "loaders/gltf_builder.h"
#include "load_scene.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

static std::string refusal(const fs::path& base, const std::string& uri) {
  try {
    resolve_inside(base, uri, false, "s.gltf: images[0].uri");
  } catch (const LoadError& error) {
    return error.what();
  }
  return "allowed";
}

TEST_CASE("resolve_inside: files inside the folder resolve, escapes are refused") {
  ScratchDir dir("file-access");
  fs::create_directories(dir.file("scene/textures"));
  dir.write("scene/textures/a.png", "x");
  dir.write("outside.png", "x");
  fs::path base = dir.file("scene");
  CHECK(resolve_inside(base, "textures/a.png", false, "w") == fs::canonical(base / "textures/a.png"));
  CHECK(resolve_inside(base, "textures/../textures/a.png", false, "w") == fs::canonical(base / "textures/a.png"));
  CHECK(refusal(base, "/etc/passwd") ==
        "s.gltf: images[0].uri: '/etc/passwd' is an absolute path (use --allow-external-files to allow it)");
  CHECK(refusal(base, "../outside.png") ==
        "s.gltf: images[0].uri: '../outside.png' leaves the scene's folder (use --allow-external-files to allow it)");
  CHECK(refusal(base, "textures/../../outside.png").find("leaves the scene's folder") != std::string::npos);
  fs::create_symlink(dir.file("outside.png"), base / "link.png");
  CHECK(refusal(base, "link.png") == "s.gltf: images[0].uri: 'link.png' leads outside the scene's folder through a "
                                     "symlink (use --allow-external-files to allow it)");
  CHECK(resolve_inside(base, "link.png", true, "w") == base / "link.png");
  CHECK(resolve_inside(base, "../outside.png", true, "w") == dir.file("outside.png"));
  CHECK(resolve_inside(base, "/etc/passwd", true, "w") == fs::path("/etc/passwd"));
}

TEST_CASE("gltf paths: external buffers load from the folder and escapes need the flag") {
  ScratchDir dir("gltf-paths");
  fs::create_directories(dir.file("scene"));
  GltfBuilder b = quad_builder();
  std::string body = std::string(quad_mesh) + ",\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]";
  dir.write("scene/quad.bin", b.bin);
  dir.write("quad.bin", b.bin);
  CHECK(load_scene(dir.write("scene/inside.gltf", b.gltf(body, "quad.bin")).string()).meshes.size() == 1);
  std::string escaping = dir.write("scene/escape.gltf", b.gltf(body, "../quad.bin")).string();
  CHECK_THROWS_WITH_AS(load_scene(escaping),
                       (escaping + ": buffers[0].uri: '../quad.bin' leaves the scene's folder (use "
                                   "--allow-external-files to allow it)").c_str(),
                       LoadError);
  LoadOptions allow;
  allow.allow_external_files = true;
  CHECK(load_scene(escaping, allow).meshes.size() == 1);
  std::string absolute = dir.write("scene/absolute.gltf", b.gltf(body, dir.file("quad.bin").string())).string();
  CHECK_THROWS_WITH_AS(load_scene(absolute),
                       (absolute + ": buffers[0].uri: '" + dir.file("quad.bin").string() +
                        "' is an absolute path (use --allow-external-files to allow it)").c_str(),
                       LoadError);
  CHECK(load_scene(absolute, allow).meshes.size() == 1);
  fs::create_symlink(dir.file("quad.bin"), dir.file("scene/link.bin"));
  std::string linked = dir.write("scene/linked.gltf", b.gltf(body, "link.bin")).string();
  CHECK_THROWS_AS(load_scene(linked), LoadError);
  CHECK(load_scene(linked, allow).meshes.size() == 1);
}

TEST_CASE("obj paths: mtllib and textures outside the folder are refused") {
  ScratchDir dir("obj-paths");
  fs::create_directories(dir.file("scene"));
  dir.write("outside.mtl", "newmtl red\nKd 1 0 0\n");
  std::string obj = dir.write("scene/a.obj", "mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n").string();
  CHECK_THROWS_WITH_AS(load_scene(obj),
                       (obj + ": mtllib: '../outside.mtl' leaves the scene's folder (use --allow-external-files to "
                              "allow it)").c_str(),
                       LoadError);
  LoadOptions allow;
  allow.allow_external_files = true;
  CHECK(load_scene(obj, allow).materials.at(0).kd.x == 1);
}

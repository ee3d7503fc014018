// OBJ material names with spaces, and tinyobjloader's messages placed as file:line.
#include <doctest/doctest.h>

#include <map>
#include <sstream>

#include "load_scene.h"
#include "obj/obj_material_names.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

namespace {

const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

// The scene's warnings with the scratch folder's path removed.
std::vector<std::string> warnings_of(const ScratchDir& dir, const SceneDesc& scene) {
  std::vector<std::string> warnings;
  for (const std::string& w : scene.warnings) warnings.push_back(dir.without_path(w));
  return warnings;
}

}  // namespace

TEST_CASE("obj material names: the encoding tinyobjloader sees has no blanks and decodes to the name") {
  for (std::string name : {"Hard Shiny Plastic White", "a\tb", "100% red", "%20 literal", "plain"}) {
    std::string encoded = encode_material_name(name);
    CHECK(encoded.find_first_of(" \t") == std::string::npos);
    CHECK(decode_material_name(encoded) == name);
  }
}

TEST_CASE("obj material names: the filter rewrites only keyword lines and counts lines as tinyobjloader does") {
  std::istringstream in("v 0 0 0\r\n  usemtl  Hard Shiny  Plastic \r\nusemtlx y\rusemtl\nusemtl one");
  MaterialNameFilter filter(in, "usemtl");
  std::istream named(&filter);
  std::stringstream out;
  out << named.rdbuf();
  CHECK(out.str() == "v 0 0 0\nusemtl Hard%20Shiny%20%20Plastic\nusemtlx y\nusemtl\nusemtl one\n");
  REQUIRE(filter.named_lines().size() == 3);
  CHECK(filter.named_lines()[0].line == 2);
  CHECK(filter.named_lines()[0].name == "Hard Shiny  Plastic");
  CHECK(filter.named_lines()[1].line == 4);
  CHECK(filter.named_lines()[1].name == "");
  CHECK(filter.named_lines()[2].line == 5);
}

TEST_CASE("obj: usemtl and newmtl names with spaces are the whole rest of the line, so they match") {
  ScratchDir dir("obj-spaced-names");
  dir.write("m.mtl", "newmtl Hard Shiny Plastic White  \nKd 0.9 0.9 0.9\nnewmtl Hard Shiny Plastic Red\nKd 0.9 0 0\n");
  std::string obj = "mtllib m.mtl\n" + triangle + "usemtl Hard Shiny Plastic Red\nf 1 2 3\n" +
                    "usemtl   Hard Shiny Plastic White\nf 1 3 2\n";
  SceneDesc scene = load_scene(dir.write("a.obj", obj).string());
  CHECK(warnings_of(dir, scene).empty());
  REQUIRE(scene.meshes.size() == 2);
  std::map<std::string, color3> kd;
  for (const MeshDesc& mesh : scene.meshes) kd[mesh.name] = scene.materials.at(size_t(mesh.material)).kd;
  REQUIRE(kd.count("Hard Shiny Plastic Red") == 1);
  REQUIRE(kd.count("Hard Shiny Plastic White") == 1);
  CHECK(kd["Hard Shiny Plastic Red"].y == 0);
  CHECK(kd["Hard Shiny Plastic White"].y == doctest::Approx(0.9));
}

TEST_CASE("obj: a usemtl naming no material of the MTL is a warning at its line, once per name") {
  ScratchDir dir("obj-unknown-material");
  dir.write("m.mtl", "newmtl known\nKd 1 1 1\n");
  std::string obj = "mtllib m.mtl\n" + triangle + "usemtl Default Grey\nf 1 2 3\nusemtl known\nf 1 3 2\n" +
                    "usemtl Default Grey\nf 2 1 3\n";
  SceneDesc scene = load_scene(dir.write("a.obj", obj).string());
  CHECK(warnings_of(dir, scene) ==
        std::vector<std::string>{"a.obj:5: usemtl 'Default Grey': no material of that name in the MTL files; its "
                                 "faces get the default material"});
}

TEST_CASE("obj: without any mtllib, usemtl is the default material and no warning") {
  ScratchDir dir("obj-no-mtllib");
  SceneDesc scene = load_scene(dir.write("a.obj", triangle + "usemtl Default\nf 1 2 3\nusemtl other\nf 1 3 2\n").string());
  CHECK(scene.warnings.empty());
  REQUIRE(scene.meshes.size() == 1);
  CHECK(scene.materials.at(size_t(scene.meshes[0].material)).kd.x == doctest::Approx(0.8f));
}

TEST_CASE("obj: a missing MTL says so once, not again for every usemtl") {
  ScratchDir dir("obj-missing-mtl");
  SceneDesc scene = load_scene(dir.write("a.obj", "mtllib gone.mtl\n" + triangle + "usemtl x\nf 1 2 3\n").string());
  CHECK(warnings_of(dir, scene) == std::vector<std::string>{"a.obj: mtllib 'gone.mtl': no such file; its materials "
                                                            "are replaced by the default material"});
}

TEST_CASE("obj: tinyobjloader's messages name the OBJ or MTL line") {
  ScratchDir dir("obj-placed-messages");
  CHECK(load_error(dir, dir.write("zero.obj", triangle + "f 1 2 3\nf 0 1 2\n")) ==
        "zero.obj:5: f: an index is 0 or not a number (OBJ indices start at 1)");
  SceneDesc group = load_scene(dir.write("g.obj", triangle + "g \nf 1 2 3\n").string());
  CHECK(warnings_of(dir, group) == std::vector<std::string>{"g.obj:4: g without a name"});
  SceneDesc short_faces = load_scene(dir.write("s.obj", triangle + "f 1 2 3\nf 1 2\nf 2 3\n").string());
  CHECK(warnings_of(dir, short_faces) ==
        std::vector<std::string>{"s.obj:5: 2 faces with fewer than 3 corners are skipped (this one first)"});
  dir.write("m.mtl", "newmtl glass pane\nKd 1 1 1\nTr 0.5\nd 0.5\n");
  SceneDesc both = load_scene(dir.write("d.obj", "mtllib m.mtl\n" + triangle + "usemtl glass pane\nf 1 2 3\n").string());
  CHECK(warnings_of(dir, both) == std::vector<std::string>{"m.mtl:4: material 'glass pane' sets both d and Tr; d is used"});
}

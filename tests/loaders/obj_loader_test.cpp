// OBJ/MTL to SceneDesc: one mesh per material, Phong mapping, v flipped to the glTF convention.
#include <doctest/doctest.h>


#include "load_scene.h"
#include "obj/obj_loader.h"
#include "support/load_errors.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;

static const char* two_material_obj =
    "mtllib m.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "vn 0 0 1\n"
    "g left\nusemtl glass\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"
    "g right\nusemtl mirror\nf 1/1/1 2/2/1 3/3/1\n"
    "usemtl glass\nf 1/1/1 3/3/1 4/4/1\n";

static const char* materials_mtl =
    "newmtl glass\nKd 0.1 0.2 0.3\nKs 0.5 0.5 0.5\nNs 64\nNi 1.45\nd 0.25\nillum 7\n"
    "newmtl mirror\nKd 0 0 0\nKs 0.9 0.8 0.7\nillum 3\nKe 2 2 2\nmap_Kd tex.png\nmap_bump -bm 0.5 tex.png\nnorm tex.png\n"
    "map_d tex.png\n";

static void write_texture(const std::filesystem::path& path) { write_texel_bytes(path, 2, 2, 1, {10, 20, 30, 40}); }

TEST_CASE("obj: polygons are triangulated into one mesh per material with the MTL mapping") {
  ScratchDir dir("obj-materials");
  dir.write("m.mtl", materials_mtl);
  write_texture(dir.file("tex.png"));
  SceneDesc scene = load_scene(dir.write("a.obj", two_material_obj).string());
  REQUIRE(scene.meshes.size() == 2);
  REQUIRE(scene.materials.size() == 2);
  const MeshDesc& glass_mesh = scene.meshes[0];
  CHECK(glass_mesh.name == "glass");
  CHECK(glass_mesh.triangle_count() == 3);  // the quad's two triangles and the last face
  CHECK(glass_mesh.positions.size() == 4);  // corners shared across faces
  CHECK(glass_mesh.texcoords0[2].y == 0);   // vt 1 1 -> v' = 1 - 1
  CHECK(glass_mesh.texcoords0[0].y == 1);
  CHECK(glass_mesh.normals[0].z == 1);
  const MaterialDesc& glass = scene.materials[glass_mesh.material];
  CHECK(glass.model == MaterialModel::phong);
  CHECK(glass.kd.z == doctest::Approx(0.3));
  CHECK(glass.shininess == 64);
  CHECK(glass.ior == doctest::Approx(1.45));
  CHECK(glass.kt.x == doctest::Approx(0.75));  // 1 - d
  CHECK(glass.kr.x == doctest::Approx(0.5));   // illum 7 reflects too
  CHECK(glass.alpha == 1);
  const MaterialDesc& mirror = scene.materials[scene.meshes[1].material];
  CHECK(mirror.kr.y == doctest::Approx(0.8));
  CHECK(is_black(mirror.kt));
  CHECK(mirror.emission.x == 2);
  CHECK(mirror.base_color_texture.valid());
  CHECK(mirror.normal_texture.texture == mirror.base_color_texture.texture);  // one texture per file
  CHECK(mirror.bump_texture.texture == mirror.base_color_texture.texture);    // a height map, not a normal map
  CHECK(mirror.bump_scale == 0.5f);
  CHECK(mirror.alpha_texture.valid());
  CHECK(mirror.alpha_mode == AlphaMode::mask);
  REQUIRE(scene.images.size() == 1);
  CHECK(scene.images[0].channels == 1);
  CHECK(scene.images[0].texels8 == std::vector<uint8_t>{10, 20, 30, 40});
  CHECK(scene.meshes[1].tangents.size() == scene.meshes[1].positions.size());
  CHECK(scene.warnings.empty());
}

TEST_CASE("obj: without vn, faces are flat unless a smoothing group asks for shared normals") {
  ScratchDir dir("obj-smoothing");
  // Two faces folded along a shared edge (vertices 2 and 3), no normals.
  const std::string fold = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\n";
  SceneDesc flat = load_scene(dir.write("flat.obj", fold + "f 1 2 3\nf 2 4 3\n").string());
  CHECK(flat.meshes.at(0).normals.empty());
  SceneDesc off = load_scene(dir.write("off.obj", fold + "s off\nf 1 2 3\nf 2 4 3\n").string());
  CHECK(off.meshes.at(0).normals.empty());
  SceneDesc smooth = load_scene(dir.write("smooth.obj", fold + "s 1\nf 1 2 3\nf 2 4 3\n").string());
  const MeshDesc& mesh = smooth.meshes.at(0);
  REQUIRE(mesh.normals.size() == 4);
  CHECK(mesh.normals[0].z == doctest::Approx(1));  // only in the flat face
  CHECK(mesh.normals[1].z < 0.99f);                // shared by both faces: tilted between them
  CHECK(mesh.normals[1].x < 0);
}

TEST_CASE("obj: a file of bare faces is flat and grey, its missing light is render's warning, not the loader's") {
  ScratchDir dir("obj-dark");
  std::string path = dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string();
  SceneDesc scene = load_scene(path);
  CHECK(scene.meshes.at(0).normals.empty());  // no vn, no smoothing group: flat
  CHECK(scene.materials.at(0).kd.x == doctest::Approx(0.8));
  CHECK(scene.warnings.empty());
}

TEST_CASE("obj: out-of-range face indices are errors") {
  ScratchDir dir("obj-range");
  std::string path = dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1\n  f 1 2 3 9\n").string();
  CHECK_THROWS_WITH_AS(load_scene(path), (path + ":6:11: vertex index 9 out of range (3 vertices)").c_str(), LoadError);
  std::string normals = dir.write("b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n").string();
  CHECK_THROWS_WITH_AS(load_scene(normals), (normals + ":5:13: normal index 2 out of range (1 normals)").c_str(),
                       LoadError);
}

TEST_CASE("obj: append_obj places the meshes and can override their material") {
  ScratchDir dir("obj-append");
  std::string path = dir.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string();
  SceneDesc scene;
  scene.materials.push_back({});
  append_obj(scene, path, translation({0, 0, 5}), {}, 0);
  REQUIRE(scene.instances.size() == 1);
  CHECK(scene.instances[0].transform.m[2][3] == 5);
  CHECK(scene.meshes[0].material == 0);
  CHECK(scene.materials.size() == 1);
}

// The message of loading `obj` (beside `mtl` as m.mtl), with the scratch folder removed.
static std::string obj_error(const std::string& obj, const std::string& mtl = "") {
  ScratchDir dir("obj-numbers");
  if (!mtl.empty()) dir.write("m.mtl", mtl);
  return load_error(dir, dir.write("a.obj", obj));
}

TEST_CASE("obj: nan, inf and numbers a float cannot hold are refused as file:line:col, not read as 0") {
  const std::string face = "f 1 2 3\n";
  CHECK(obj_error("v 0 0 0\nv 1 0 0\nv nan 1 0\n" + face) == "a.obj:3:3: v: 'nan' is not a number");
  CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 inf\n" + face) == "a.obj:4:8: vn: 'inf' is not a number");
  CHECK(obj_error("v 0 0 0\nv 1 0 0\n  v 0 1e39 0\n" + face) == "a.obj:3:7: v: '1e39' does not fit in a float");
  CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0,5\n" + face) == "a.obj:4:8: vt: '0,5' is not a number");
  CHECK(obj_error("v 0 0 0\nv 1 0 0\nv 0 1\n" + face) == "a.obj:3:1: v: expected 3 numbers, found 2");
  CHECK(obj_error("v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nvt .5 -1.e-3\n" + face) == "no error");
}

TEST_CASE("obj: MTL numbers are checked, and negative colors and emission are refused naming the MTL line") {
  const std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\n";
  CHECK(obj_error(obj, "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 -1 1\n") ==
        "m.mtl:3:6: Ke: '-1' is negative (a color or emission must not be)");
  CHECK(obj_error(obj, "newmtl lamp\nKd -0.5 0.5 0.5\n") ==
        "m.mtl:2:4: Kd: '-0.5' is negative (a color or emission must not be)");
  CHECK(obj_error(obj, "newmtl lamp\nNs nan\n") == "m.mtl:2:4: Ns: 'nan' is not a number");
  CHECK(obj_error(obj, "newmtl lamp\n\tKe 1e39 0 0\n") == "m.mtl:2:5: Ke: '1e39' does not fit in a float");
  CHECK(obj_error(obj, "newmtl lamp\nKe 4 4 4\nNi 1.5\nd 1\nillum 2\n") == "no error");
}

TEST_CASE("obj: a face index past 32 bits is refused naming it, not wrapped to another vertex") {
  std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  std::string range = " is out of range (indices are at most 2147483647 in magnitude)";
  CHECK(obj_error(vertices + "f 4294967299 1 2\n") == "a.obj:4:3: f: index '4294967299'" + range);
  CHECK(obj_error(vertices + "f 1 2 -2147483649\n") == "a.obj:4:7: f: index '-2147483649'" + range);
  CHECK(obj_error(vertices + "vt 0 0\nf 1 2/99999999999999999999999/1 3\n") ==
        "a.obj:5:7: f: index '99999999999999999999999'" + range);
  CHECK(obj_error(vertices + "l 1 18446744073709551617\n") == "a.obj:4:5: l: index '18446744073709551617'" + range);
  // The largest index an int holds is an ordinary out-of-range index.
  CHECK(obj_error(vertices + "f 1 2 2147483647\n") == "a.obj:4:7: vertex index 2147483647 out of range (3 vertices)");
  CHECK(obj_error(vertices + "f -3 -2 -1\n") == "no error");
}

TEST_CASE("obj: a line longer than 1 MiB in an OBJ or its MTL is refused before it is read whole") {
  std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string long_comment = "# " + std::string(1 << 20, 'x') + "\n";
  CHECK(obj_error(triangle + long_comment) == "a.obj:5: line is longer than 1048576 characters");
  CHECK(obj_error("v 0 0 " + std::string(1 << 20, '0') + "1\n" + triangle) ==
        "a.obj:1: line is longer than 1048576 characters");
  std::string with_library = "mtllib m.mtl\nusemtl red\n" + triangle;
  CHECK(obj_error(with_library, "newmtl red\nKd 0.5 0.5 0." + std::string(1 << 20, '5') + "\n") ==
        "m.mtl:2: line is longer than 1048576 characters");
  // A line of exactly the limit is read.
  CHECK(obj_error(triangle + "#" + std::string((1 << 20) - 1, 'x') + "\n") == "no error");
}

TEST_CASE("obj: a texture or material name of 100 kB is quoted in a message of at most a few hundred bytes") {
  std::string obj = "mtllib m.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  std::string long_name = std::string(100000, 'n') + ".png";
  std::string message = obj_error(obj, "newmtl red\nmap_Kd /" + long_name + "\n");
  CHECK(message.find("map_Kd") != std::string::npos);  // refused: an absolute path
  CHECK(message.find("... (100005 bytes)") != std::string::npos);
  CHECK(message.size() < 700);
}

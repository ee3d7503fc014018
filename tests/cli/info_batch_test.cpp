// `radiant info` and `radiant batch` as scripts use them.
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("info: the showcase reports its shapes, lights by kind, effects with reasons and the auto mode") {
  CommandResult r = run_radiant("info " + quoted(source_path("assets/showcase.scene")) + " --json");
  REQUIRE(r.exit_code == 0);
  nlohmann::json info = nlohmann::json::parse(r.out);
  CHECK(info["lights"]["point"] == 1);
  CHECK(info["lights"]["spot"] == 1);
  nlohmann::json shadows = {{"effect", "transparent-shadows"}, {"reason", "2 transmissive material(s) let light through"}};
  CHECK(std::find(info["effects"].begin(), info["effects"].end(), shadows) != info["effects"].end());
  CHECK(info["auto_mode"]["mode"] == "whitted");
}

TEST_CASE("info: warns about a scene without light and about a light enclosed in geometry") {
  ScratchDir dir("info-warnings");
  fs::path dark = dir.write("dark.scene", "@sphere\nradius 1\ncenter 0 0 -3\n");
  CommandResult r = run_radiant("info " + quoted(dark));
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("warning: no lights") != std::string::npos);
  fs::path enclosed = dir.write("enclosed.scene",
                                "@light point\ncolor 255 255 255\nposition 0 0 -3\n@sphere\nradius 1\ncenter 0 0 -3\n");
  r = run_radiant("info " + quoted(enclosed));
  CHECK(r.out.find("is inside closed geometry") != std::string::npos);
  CHECK(r.out.find("warning: no lights") == std::string::npos);
}

TEST_CASE("info: a bad file exits 1 with the loader's located message") {
  ScratchDir dir("info-bad");
  fs::path bad = dir.write("bad.scene", "@sphere\nradius x\ncenter 0 0 0\n");
  CommandResult r = run_radiant("info " + quoted(bad));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("bad.scene:2:8:") != std::string::npos);
}

TEST_CASE("batch: one load renders every view, views differ where the camera moved") {
  ScratchDir dir("batch");
  fs::copy_file(source_path("assets/first-render.scene"), dir.file("s.scene"));
  fs::path script = dir.write("views.txt",
                              "# two views of one scene\n"
                              "scene s.scene\n"
                              "render -o a.png --width 32 --height 32 --spp 1 --quiet\n"
                              "render -o b.png --width 32 --height 32 --spp 1 --quiet --look-from 300,0,1000 --look-at 0,0,-200\n");
  CommandResult r = run_radiant("batch " + quoted(script));
  REQUIRE(r.exit_code == 0);
  REQUIRE(fs::exists(dir.file("a.png")));
  REQUIRE(fs::exists(dir.file("b.png")));
  CHECK(read_bytes(dir.file("a.png")) != read_bytes(dir.file("b.png")));
}

TEST_CASE("batch: a bad line is reported as script:line before anything renders") {
  ScratchDir dir("batch-bad");
  fs::copy_file(source_path("assets/first-render.scene"), dir.file("s.scene"));
  fs::path script = dir.write("views.txt", "scene s.scene\nrender -o a.png --spp 1\nrender -o b.png --spp zero\n");
  CommandResult r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(r.err.find("views.txt:3:") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.file("a.png")));
}

TEST_CASE("batch: every line is resolved before the first render: a later bad crop, size, camera or scene writes nothing") {
  ScratchDir dir("batch-check-all");
  fs::copy_file(source_path("assets/first-render.scene"), dir.file("s.scene"));
  const std::string good = "scene s.scene\nrender -o a.png --width 32 --height 32 --spp 1 --quiet\n";
  struct Case {
    std::string line;
    std::string message;  // what follows "views.txt:3: "
  };
  for (const Case& c : {Case{"render -o b.png --width 32 --height 32 --spp 1 --crop 0,0,40,8",
                             "--crop must lie inside the 32x32 image with x0 < x1 and y0 < y1"},
                        Case{"render -o b.png --spp 1 --camera nosuch", ""},
                        Case{"render -o b.png --spp 1 --fov 180", "--fov must be in (0, 180) degrees"},
                        Case{"render -o b.png --spp 1 --env \"" + dir.file("sky.exr").string() + "\"",
                             dir.file("sky.exr").string() + ": cannot read environment map"},
                        Case{"scene missing.scene", ""}}) {
    CAPTURE(c.line);
    fs::path script = dir.write("views.txt", good + c.line + "\n");
    CommandResult r = run_radiant("batch " + quoted(script));
    CHECK(r.exit_code == 1);
    CHECK(r.err.rfind("radiant batch: " + script.string() + ":3: " + c.message, 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir.file("a.png")));
    CHECK_FALSE(fs::exists(dir.file("b.png")));
  }
}

TEST_CASE("batch: an image size out of range on a later line writes nothing") {
  ScratchDir dir("batch-size");
  // A camera four times wider than tall: --height 20000 asks for an 80000-pixel width.
  dir.write("wide.scene", "@camera\nposition 0 0 5\ndirection 0 0 -1\nup 0 1 0\nview-distance 1\nview-size 4 1\n"
                          "@sphere\ncenter 0 0 0\nradius 1\n@light point\nposition 0 3 3\n");
  fs::path script = dir.write("views.txt", "scene wide.scene\nrender -o a.png --height 8 --spp 1 --quiet\n"
                                           "render -o b.png --height 20000 --spp 1\n");
  CommandResult r = run_radiant("batch " + quoted(script));
  CHECK(r.exit_code == 1);
  CHECK(r.err == "radiant batch: " + script.string() + ":3: image size 80000x20000 is out of range (1 to 65536)\n");
  CHECK_FALSE(fs::exists(dir.file("a.png")));
}

TEST_CASE("json: documents stay valid whatever the names hold: quotes, control characters, invalid UTF-8") {
  ScratchDir dir("json-names");
  std::string name = std::string("we\"ird\\ \x01\t") + "\xff\xfe" + ".scene";
  fs::path scene = dir.write(name, "scene a \"quoted\" name\n@camera\nposition 0 0 5\ndirection 0 0 -1\nup 0 1 0\n"
                                   "@light point\ncolor 255 255 255\nposition 0 0 5\n@sphere\ncenter 0 0 0\nradius 1\n");
  CommandResult info = run_radiant("info --json " + quoted(scene));
  REQUIRE(info.exit_code == 0);
  nlohmann::json document = nlohmann::json::parse(info.out);  // throws unless valid
  std::string reported = document["scene"];
  CHECK(reported.find("we\"ird\\ \x01\t") != std::string::npos);
  CHECK(reported.find("\xef\xbf\xbd") != std::string::npos);  // U+FFFD for the bytes that are not UTF-8
  CHECK(document["name"] == "a \"quoted\" name");
  fs::path stats = dir.file("stats.json");
  CommandResult render = run_radiant("render " + quoted(scene) + " -o " + quoted(dir.file("o.png")) +
                                     " --width 8 --height 8 --spp 1 --quiet --stats " + quoted(stats));
  REQUIRE(render.exit_code == 0);
  CHECK(nlohmann::json::parse(read_bytes(stats))["scene"].get<std::string>().find("we\"ird") != std::string::npos);
}

TEST_CASE("info: each camera and light is listed by index, name and kind, as --camera takes them") {
  CommandResult r = run_radiant("info " + quoted(source_path("assets/showcase.scene")));
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("    camera 0 'main': perspective\n") != std::string::npos);
  CHECK(r.out.find("    light 3: spot\n") != std::string::npos);
  CommandResult j = run_radiant("info " + quoted(source_path("assets/showcase.scene")) + " --json");
  REQUIRE(j.exit_code == 0);
  CHECK(j.out.find("\"camera_list\"") != std::string::npos);
  CHECK(j.out.find("\"kind\": \"ambient\"") != std::string::npos);
}

TEST_CASE("info: animations with their lengths and material variants are listed, as --animation and --variant take them") {
  CommandResult r = run_radiant("info " + quoted(source_path("assets/models/turntable.gltf")));
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("  animations: 1 (--animation NAME|INDEX)\n    animation 0 'spin': 2 s\n") != std::string::npos);
  CHECK(r.out.find("  variants:  2 (--variant NAME)\n    variant 0 'orange'\n    variant 1 'blue'\n") != std::string::npos);
  CommandResult j = run_radiant("info " + quoted(source_path("assets/models/turntable.gltf")) + " --json");
  REQUIRE(j.exit_code == 0);
  nlohmann::json info = nlohmann::json::parse(j.out);
  CHECK(info["animations"][0]["name"] == "spin");
  CHECK(info["animations"][0]["seconds"] == 2.0);
  CHECK(info["material_variants"] == nlohmann::json::array({"orange", "blue"}));
}

TEST_CASE("info: counts agree with their nouns, zero kinds are left out and sizes have one decimal") {
  CommandResult r = run_radiant("info " + quoted(source_path("assets/showcase.scene")));
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("5 spheres, 2 planes, 1 cylinder, 1 tube; ") != std::string::npos);
  CHECK(r.out.find("1 cylinders") == std::string::npos);
  CommandResult cornell = run_radiant("info " + quoted(source_path("assets/cornell.gltf")));
  REQUIRE(cornell.exit_code == 0);
  CHECK(cornell.out.find("  geometry:  32 triangles in 8 meshes, 8 instances (32 placed); 1.") != std::string::npos);
  CHECK(cornell.out.find(" KiB\n") != std::string::npos);
  CHECK(cornell.out.find("0 spheres") == std::string::npos);
  CHECK(cornell.out.find("  textures:  none\n  lights:    none\n") != std::string::npos);
}

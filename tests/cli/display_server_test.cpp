// --display-server: the image reaches a tev viewer pass by pass, the last pass equal to the file
// written; a viewer that is not there costs one warning and nothing else.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "support/tev_listener.h"
#include "support/test_scenes.h"
#include "support/test_support.h"

using namespace radiant::test;

namespace {

size_t count_type(const std::vector<TevMessageRead>& messages, uint8_t type) {
  return size_t(std::count_if(messages.begin(), messages.end(), [&](const TevMessageRead& m) { return m.type == type; }));
}

size_t count_lines_with(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("render --display-server sends every pass, the last one equal to the image written") {
  ScratchDir dir("display");
  TevListener viewer;
  std::string out = dir.file("out.exr").string();
  CommandResult r = run_radiant("render " + quoted(dir.write("p.scene", lit_plane_scene)) + " -o " + radiant::test::quoted(out) +
                                " --width 16 --height 8 --spp 4 --display-server " + viewer.address());
  REQUIRE(r.exit_code == 0);
  std::vector<TevMessageRead> messages = viewer.messages();
  REQUIRE(!messages.empty());
  const TevMessageRead& create = messages.front();
  CHECK(create.type == 4);
  CHECK(create.name == out);
  CHECK(create.grab_focus);
  CHECK(create.width == 16);
  CHECK(create.height == 8);
  CHECK(create.channels == std::vector<std::string>{"R", "G", "B"});
  CHECK(count_type(messages, 4) == 1);
  CHECK(count_type(messages, 3) == 3 * 3);  // passes of 1, 2 and 4 samples, three channels each
  TestImage written = read_image(out);
  const TevMessageRead* last_red = nullptr;
  for (const TevMessageRead& m : messages)
    if (m.type == 3 && m.channel == "R") last_red = &m;
  REQUIRE(last_red != nullptr);
  REQUIRE(last_red->width == 16);
  REQUIRE(last_red->height == 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) CHECK(last_red->values[size_t(y) * 16 + x] == written.at(x, y, 0));
  CHECK(written.at(8, 4, 0) > 0.0f);  // the plane is lit: the comparison is not of black images
}

TEST_CASE("render --display-server with no viewer listening warns once and writes the image") {
  ScratchDir dir("display-refused");
  std::string address;
  {
    TevListener gone;  // a port that was free a moment ago: nothing listens there now
    address = gone.address();
    gone.messages();
  }
  std::string out = dir.file("out.png").string();
  CommandResult r = run_radiant("render " + quoted(dir.write("p.scene", lit_plane_scene)) + " -o " + radiant::test::quoted(out) +
                                " --width 16 --height 8 --spp 4 --display-server " + address);
  CHECK(r.exit_code == 0);
  CHECK(std::filesystem::exists(out));
  CHECK(count_lines_with(r.err, "display server " + address) == 1);
}

TEST_CASE("--display-server refuses an address that is not HOST:PORT as a usage error") {
  ScratchDir dir("display-usage");
  std::string scene = quoted(dir.write("p.scene", lit_plane_scene));
  for (const char* bad : {"localhost", "127.0.0.1:", "127.0.0.1:0", "127.0.0.1:70000", "127.0.0.1:http"}) {
    CAPTURE(bad);
    CommandResult r = run_radiant("render " + scene + " -o " + quoted(dir.file("o.png")) + " --display-server " + bad);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--display-server") != std::string::npos);
    CHECK(!std::filesystem::exists(dir.file("o.png")));
  }
}

TEST_CASE("batch and session --display-server show each view under its output's name") {
  ScratchDir dir("display-views");
  std::string scene = dir.write("p.scene", lit_plane_scene).string();
  {
    TevListener viewer;
    std::string script = "scene " + scene + "\nrender -o " + dir.file("a.png").string() + " --width 8 --height 8 --spp 2\n" +
                         "render -o " + dir.file("b.png").string() + " --width 4 --height 4 --spp 1\n";
    CommandResult r = run_radiant("batch - -q --display-server " + viewer.address(), script);
    REQUIRE(r.exit_code == 0);
    std::vector<TevMessageRead> messages = viewer.messages();
    std::vector<std::string> created;
    for (const TevMessageRead& m : messages)
      if (m.type == 4) created.push_back(m.name);
    CHECK(created == std::vector<std::string>{dir.file("a.png").string(), dir.file("b.png").string()});
  }
  {
    TevListener viewer;
    std::string out = dir.file("v.png").string();
    CommandResult r = run_radiant("session -o " + radiant::test::quoted(out) + " --display-server " + viewer.address() +
                                      " --width=8 --height=8 --spp=2",
                                  "render " + scene + "\n");
    REQUIRE(r.exit_code == 0);
    std::vector<TevMessageRead> messages = viewer.messages();
    REQUIRE(count_type(messages, 4) == 1);
    CHECK(messages.front().name == out);
    CHECK(count_type(messages, 3) == 2 * 3);  // passes of 1 and 2 samples
  }
}

// `cmake --install`: the installed program finds its OpenImageIO module from any prefix, and the
// man page and completions are installed beside it.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>

#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("install: an installed radiant renders PNG and EXR (its module found relative to it) from any prefix") {
  ScratchDir dir("install");
  fs::path prefix = dir.file("prefix");
  std::string install = "cmake --install '" + std::string(RADIANT_BINARY_DIR) + "' --prefix '" + prefix.string() + "' >/dev/null";
  REQUIRE(std::system(install.c_str()) == 0);
  fs::path radiant = prefix / "bin" / "radiant";
  REQUIRE(fs::exists(radiant));
  fs::path scene = prefix / "share" / "radiant" / "assets" / "first-render.scene";
  REQUIRE(fs::exists(scene));
  // Moved elsewhere, the installation still works: nothing points back into the build.
  fs::path moved = dir.file("moved");
  fs::rename(prefix, moved);
  for (const char* output : {"o.png", "o.exr"}) {
    std::string render = "'" + (moved / "bin" / "radiant").string() + "' render '" +
                         (moved / "share" / "radiant" / "assets" / "first-render.scene").string() + "' -o '" +
                         dir.file(output).string() + "' --width 8 --height 8 --spp 1 --quiet";
    CHECK_MESSAGE(std::system(render.c_str()) == 0, output);
    CHECK(fs::exists(dir.file(output)));
  }
  if (!built_with_address_sanitizer) {  // the sanitizer builds make no manual
    CHECK(fs::exists(moved / "share" / "man" / "man1" / "radiant.1"));
    CHECK(fs::exists(moved / "share" / "bash-completion" / "completions" / "radiant"));
    CHECK(fs::exists(moved / "share" / "zsh" / "vendor-completions" / "_radiant"));
  }
}

TEST_CASE("install: the man page's synopsis has every command, bash completes merge and the words of enum flags") {
  if (built_with_address_sanitizer) return;  // the sanitizer builds make no manual
  fs::path manual = fs::path(RADIANT_BINARY_DIR) / "manual";
  std::string page = read_bytes(manual / "radiant.1");
  for (const char* command : {"render", "info", "compare", "converge", "batch", "session", "merge", "denoise"})
    CHECK_MESSAGE(page.find(std::string(".B radiant ") + command + "\n") != std::string::npos, command);
  // Ask the generated completion what it offers, as bash would.
  auto complete = [&](const std::string& line) {
    ScratchDir dir("completion");
    fs::path script = dir.write("ask.sh", "source '" + (manual / "radiant.bash").string() + "'\n"
                                          "COMP_WORDS=(" + line + ")\nCOMP_CWORD=$((${#COMP_WORDS[@]} - 1))\n"
                                          "_radiant\necho \"${COMPREPLY[*]}\"\n");
    std::string run = "bash '" + script.string() + "' > '" + dir.file("out").string() + "'";
    REQUIRE(std::system(run.c_str()) == 0);
    return read_bytes(dir.file("out"));
  };
  CHECK(complete("radiant me").find("merge") != std::string::npos);
  CHECK(complete("radiant render --mode p") == "path\n");
  CHECK(complete("radiant render --view ne") == "neutral\n");
  CHECK(complete("radiant render --env st").find("studio") != std::string::npos);
}

// A session's progress: on a terminal, a status line above the prompt redrawn in place with the
// pass and the spp reached, leaving what the user types alone; off a terminal, nothing unless
// --progress lines asks for a line per pass.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "support/child_process.h"
#include "support/test_support.h"

using namespace radiant::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> session_args(ScratchDir& dir, const std::string& spp, std::vector<std::string> more = {}) {
  fs::copy_file(source_path("assets/cornell.gltf"), dir.file("cornell.gltf"), fs::copy_options::overwrite_existing);
  std::vector<std::string> args = {"session", dir.file("cornell.gltf").string(), "-o", dir.file("view.png").string(),
                                   "--width", "48", "--height", "48", "--spp", spp, "--threads", "1"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The spp each "pass N, S of T spp" status names, in the order printed.
std::vector<int> passes_reached(const std::string& text, int total) {
  std::vector<int> reached;
  for (size_t at = text.find(": pass "); at != std::string::npos; at = text.find(": pass ", at + 1)) {
    int pass = 0, samples = 0, of = 0;
    if (std::sscanf(text.c_str() + at, ": pass %d, %d of %d spp", &pass, &samples, &of) == 3 && of == total)
      reached.push_back(samples);
  }
  return reached;
}

const std::string save = "\0337", up = "\033[A", erase = "\r\033[K", restore = "\0338";

}  // namespace

TEST_CASE("session progress: at a terminal the status line above the prompt shows each pass, the typing stays") {
  ScratchDir dir("session-progress-terminal");
  ChildSetup setup;
  setup.terminal_stderr = true;
  setup.terminal_stdin = true;
  RadiantProcess session(session_args(dir, "64"), setup);
  REQUIRE(session.wait_for_stderr("radiant> ", 60));
  session.write_stdin("inf");  // typed, not yet entered, while the render refines
  REQUIRE(session.wait_for_stdout("wrote ", 1, 120));
  session.write_stdin("o\n");
  REQUIRE(session.wait_for_stdout("last render: ", 1, 60));
  session.write_stdin("quit\n");
  CommandResult r = session.wait(60);
  CHECK(r.exit_code == 0);
  // Before the first prompt, the status line it keeps above itself: "starting", or the first
  // pass when the render got there before the prompt was drawn.
  size_t prompt = r.err.find("radiant> ");
  REQUIRE(prompt != std::string::npos);
  size_t status = r.err.rfind("rendering " + dir.file("view.png").string() + ": ", prompt);
  REQUIRE(status != std::string::npos);
  CHECK(r.err.find("\r\n", status) == prompt - 2);
  // Every pass, 1 to 64 spp, in order (a pass drawn before the prompt is drawn again above it);
  // once the prompt is up, redrawn in place: save the cursor, up to the status line, back.
  std::vector<int> reached = passes_reached(r.err, 64);
  reached.erase(std::unique(reached.begin(), reached.end()), reached.end());
  CHECK(reached == std::vector<int>{1, 2, 4, 8, 16, 32, 64});
  for (size_t at = r.err.find(": pass ", prompt); at != std::string::npos; at = r.err.find(": pass ", at + 1)) {
    size_t line = r.err.rfind("rendering ", at);
    REQUIRE(line != std::string::npos);
    CHECK(r.err.compare(line - 9, 9, save + up + erase) == 0);
    CHECK(r.err.find(restore, at) < r.err.find('\n', at));
  }
  // From the typing to the Enter the prompt's line is never erased: "inf" stays on screen.
  size_t typed = r.err.find("inf"), entered = r.err.find("o\r\n", typed);
  REQUIRE(typed != std::string::npos);
  REQUIRE(entered != std::string::npos);
  std::string meanwhile = r.err.substr(typed, entered - typed);
  for (size_t at = meanwhile.find(erase); at != std::string::npos; at = meanwhile.find(erase, at + 1))
    CHECK(meanwhile.compare(at - 5, 5, save + up) == 0);  // only the status line's
}

TEST_CASE("session progress: off a terminal nothing by default, a line per pass with --progress lines") {
  ScratchDir dir("session-progress-lines");
  ChildSetup piped;
  piped.piped_stdin = true;
  RadiantProcess quiet(session_args(dir, "8"), piped);
  quiet.close_stdin();
  CommandResult plain = quiet.wait(120);
  CHECK(plain.exit_code == 0);
  CHECK(plain.out.find("wrote ") != std::string::npos);
  CHECK(plain.err.empty());

  RadiantProcess lines(session_args(dir, "8", {"--progress", "lines"}), piped);
  lines.close_stdin();
  CommandResult r = lines.wait(120);
  CHECK(r.exit_code == 0);
  CHECK(passes_reached(r.err, 8) == std::vector<int>{1, 2, 4, 8});
  CHECK(r.err.find("radiant session: rendering ") == 0);
  CHECK(r.err.find('\r') == std::string::npos);  // whole lines, nothing redrawn
}

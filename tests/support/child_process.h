// radiant as a child process the test controls while it runs: a file size limit (a full disk),
// an unprivileged user (so permissions apply when the tests run as root), a terminal as stderr
// (so radiant prints its progress), and signals.
#pragma once

#include <sys/resource.h>
#include <sys/types.h>

#include <string>
#include <vector>

#include "support/test_support.h"

namespace radiant::test {

struct ChildSetup {
  // RLIMIT_FSIZE in bytes, with SIGXFSZ ignored: a write past it fails with EFBIG, as on a full disk.
  rlim_t file_size_limit = RLIM_INFINITY;
  bool keep_file_size_signal = false;  // leave SIGXFSZ's default (death) to radiant's own handling
  bool unprivileged = false;    // when the tests run as root, the child runs as nobody (uid 65534)
  bool terminal_stderr = false;  // stderr is a pseudo-terminal, as in an interactive shell
  bool piped_stdin = false;      // stdin is a pipe the test writes to (write_stdin), else empty
  // stdin is the pseudo-terminal too (needs terminal_stderr): write_stdin types on it, and the
  // terminal echoes what is typed; close_stdin types Ctrl-D.
  bool terminal_stdin = false;
};

class RadiantProcess {
 public:
  // Starts `radiant ARGS` (no shell: each element is one argument), stdin empty.
  explicit RadiantProcess(const std::vector<std::string>& args, const ChildSetup& setup = {});
  ~RadiantProcess();  // kills and reaps a child still running
  RadiantProcess(const RadiantProcess&) = delete;
  RadiantProcess& operator=(const RadiantProcess&) = delete;

  pid_t pid() const { return pid_; }
  // With a terminal stderr: reads it until `text` has appeared; false after `timeout_seconds`.
  bool wait_for_stderr(const std::string& text, double timeout_seconds);
  void send(int signal) const;
  // With piped_stdin or terminal_stdin: writes `text` to the child's standard input; closing it is the end of input.
  void write_stdin(const std::string& text);
  void close_stdin();
  // Reads standard output until `text` has appeared `count` times; false after `timeout_seconds`.
  bool wait_for_stdout(const std::string& text, int count, double timeout_seconds);
  // Waits for the exit; after `timeout_seconds` kills the child and gives exit code -1, as for
  // any death by a signal.
  CommandResult wait(double timeout_seconds);

 private:
  void read_terminal(int timeout_ms);
  ScratchDir io_{"child"};
  pid_t pid_ = -1;
  int terminal_ = -1;  // the pseudo-terminal's master side
  int stdin_ = -1;     // the write end of the child's stdin pipe, or the terminal's master side
  bool stdin_is_terminal_ = false;
  std::string terminal_text_;
};

// Runs `radiant ARGS` to its end under `setup`.
CommandResult run_radiant_with(const std::vector<std::string>& args, const ChildSetup& setup,
                               double timeout_seconds = 120);

}  // namespace radiant::test

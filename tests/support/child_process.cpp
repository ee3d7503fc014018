#include "support/child_process.h"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace radiant::test {

namespace {

using Clock = std::chrono::steady_clock;

// Runs in the forked child: only async-signal-safe calls until exec.
[[noreturn]] void exec_child(const std::vector<char*>& argv, const ChildSetup& setup, int stdin_fd, int stdout_fd,
                             int stderr_fd) {
  dup2(stdin_fd >= 0 ? stdin_fd : open("/dev/null", O_RDONLY), STDIN_FILENO);
  dup2(stdout_fd, STDOUT_FILENO);
  dup2(stderr_fd, STDERR_FILENO);
  if (!setup.keep_file_size_signal) signal(SIGXFSZ, SIG_IGN);  // inherited through exec: EFBIG instead of death
  rlimit limit{setup.file_size_limit, setup.file_size_limit};
  if (setup.file_size_limit != RLIM_INFINITY && setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(125);
  if (setup.unprivileged && geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(65534) != 0 || setuid(65534) != 0))
    _exit(125);
  execv(argv[0], argv.data());
  _exit(127);
}

}  // namespace

RadiantProcess::RadiantProcess(const std::vector<std::string>& args, const ChildSetup& setup) {
  std::vector<std::string> words = {RADIANT_EXE};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  int stdout_fd = open(io_.file("stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  int stderr_fd = -1;
  if (setup.terminal_stderr) {
    int terminal_child = -1;
    if (openpty(&terminal_, &terminal_child, nullptr, nullptr, nullptr) != 0) throw std::runtime_error("openpty failed");
    fcntl(terminal_, F_SETFD, FD_CLOEXEC);
    fcntl(terminal_child, F_SETFD, FD_CLOEXEC);
    stderr_fd = terminal_child;
  } else {
    stderr_fd = open(io_.file("stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  }
  if (stdout_fd < 0 || stderr_fd < 0) throw std::runtime_error("cannot open the child's output files");
  int stdin_pipe[2] = {-1, -1};
  if (setup.piped_stdin && pipe2(stdin_pipe, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  pid_ = fork();
  bool typed_stdin = setup.terminal_stdin && setup.terminal_stderr;
  if (pid_ == 0) exec_child(argv, setup, typed_stdin ? stderr_fd : stdin_pipe[0], stdout_fd, stderr_fd);
  close(stdout_fd);
  close(stderr_fd);
  if (setup.piped_stdin) close(stdin_pipe[0]);
  stdin_ = stdin_pipe[1];
  if (typed_stdin) {
    stdin_ = fcntl(terminal_, F_DUPFD_CLOEXEC, 0);
    stdin_is_terminal_ = true;
  }
  if (pid_ < 0) throw std::runtime_error("fork failed");
}

RadiantProcess::~RadiantProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  if (terminal_ >= 0) close(terminal_);
  close_stdin();
}

void RadiantProcess::write_stdin(const std::string& text) {
  if (stdin_ < 0) throw std::logic_error("write_stdin needs piped_stdin or terminal_stdin");
  signal(SIGPIPE, SIG_IGN);  // a child that has exited fails the write instead of killing the tests
  for (size_t done = 0; done < text.size();) {
    ssize_t wrote = write(stdin_, text.data() + done, text.size() - done);
    if (wrote <= 0) throw std::runtime_error("cannot write to the child's stdin");
    done += size_t(wrote);
  }
}

void RadiantProcess::close_stdin() {
  if (stdin_ >= 0 && stdin_is_terminal_ && pid_ > 0) (void)!write(stdin_, "\x04", 1);  // the end of input
  if (stdin_ >= 0) close(stdin_);
  stdin_ = -1;
}

bool RadiantProcess::wait_for_stdout(const std::string& text, int count, double timeout_seconds) {
  auto end = Clock::now() + std::chrono::duration<double>(timeout_seconds);
  for (;;) {
    std::string out = read_bytes(io_.file("stdout.txt"));
    int found = 0;
    for (size_t at = out.find(text); at != std::string::npos; at = out.find(text, at + 1)) ++found;
    if (found >= count) return true;
    if (Clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void RadiantProcess::read_terminal(int timeout_ms) {
  pollfd ready{terminal_, POLLIN, 0};
  if (poll(&ready, 1, timeout_ms) <= 0) return;
  char buffer[4096];
  ssize_t got = read(terminal_, buffer, sizeof buffer);
  if (got > 0) terminal_text_.append(buffer, size_t(got));
  else std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));  // the child closed it
}

bool RadiantProcess::wait_for_stderr(const std::string& text, double timeout_seconds) {
  if (terminal_ < 0) throw std::logic_error("wait_for_stderr needs terminal_stderr");
  auto end = Clock::now() + std::chrono::duration<double>(timeout_seconds);
  while (terminal_text_.find(text) == std::string::npos) {
    if (Clock::now() > end) return false;
    read_terminal(50);
  }
  return true;
}

void RadiantProcess::send(int signal) const { kill(pid_, signal); }

CommandResult RadiantProcess::wait(double timeout_seconds) {
  CommandResult result;
  auto end = Clock::now() + std::chrono::duration<double>(timeout_seconds);
  int status = 0;
  while (waitpid(pid_, &status, WNOHANG) == 0) {
    if (Clock::now() > end) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status, 0);
      break;
    }
    if (terminal_ >= 0) read_terminal(20);
    else std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  pid_ = -1;
  close_stdin();
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_bytes(io_.file("stdout.txt"));
  if (terminal_ >= 0) {
    read_terminal(0);
    result.err = terminal_text_;
  } else {
    result.err = read_bytes(io_.file("stderr.txt"));
  }
  return result;
}

CommandResult run_radiant_with(const std::vector<std::string>& args, const ChildSetup& setup, double timeout_seconds) {
  return RadiantProcess(args, setup).wait(timeout_seconds);
}

}  // namespace radiant::test

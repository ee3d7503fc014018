// SIGINT, SIGTERM and every other catchable signal that would end the process (SIGHUP, SIGQUIT,
// SIGUSR1, SIGALRM, ...; not the faults). While work whose outputs can be saved is under way (a
// render and the writing of its outputs), the first signal only asks it to stop: the render ends
// at its next pixel once every pixel has its first sample (render/pass_schedule.h), what was
// rendered is written marked partial and committed, and the command exits 128 + the signal
// (130, 143, 129, ...). At any other time, at a second signal, and at
// SIGPIPE (its reader is gone: nothing more can be delivered), the handler removes every
// temporary (src/output/temporary_registry.h) and exits at once with that code (SIGPIPE: 141).
// A signal ignored when radiant starts (nohup) stays ignored.
#pragma once

#include <atomic>
#include <string>

namespace radiant::cli {

// Installs the handlers; SIGXFSZ is ignored, so that a file size limit (ulimit -f) is a write
// error, reported like a full disk, rather than a death that leaves a temporary behind.
void install_signal_handlers();

// The first of those signals received, or 0. RenderOptions::stop_request points here.
const std::atomic<int>& interrupt_signal();

// While one lives, a first signal is deferred to the work, which checks interrupt_signal().
class DeferredInterrupts {
 public:
  DeferredInterrupts();
  ~DeferredInterrupts();
  DeferredInterrupts(const DeferredInterrupts&) = delete;
  DeferredInterrupts& operator=(const DeferredInterrupts&) = delete;
};

// Thrown once interrupted work has committed its outputs; main() returns exit_code(). Not a
// std::exception, so that the commands' error handlers let it through to main().
struct Interrupted {
  int signal;
  int exit_code() const { return 128 + signal; }
};

// Throws Interrupted when a signal has arrived.
void throw_if_interrupted();

// "SIGINT", "SIGTERM", "SIGHUP", ...
std::string signal_name(int signal);

}  // namespace radiant::cli

#include "interrupts.h"

#include <signal.h>
#include <unistd.h>

#include <cstring>
#include <string>

#include "output/temporary_registry.h"

namespace radiant::cli {

namespace {

std::atomic<int> received{0};
std::atomic<int> deferring{0};  // live DeferredInterrupts

static_assert(std::atomic<int>::is_always_lock_free, "read and written by the signal handler");

// Every signal whose default action ends the process and that a program may catch, but for the
// faults (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT: the sanitizers' and debuggers'), SIGXFSZ
// (ignored) and SIGKILL/SIGSTOP (uncatchable).
constexpr int terminating_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGUSR1, SIGUSR2,
                                       SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGPOLL, SIGSTKFLT, SIGPWR};

// Async-signal-safe: atomics, unlink (in the registry) and _exit only.
void on_signal(int signal) {
  int none = 0;
  bool first = received.compare_exchange_strong(none, signal);
  // SIGPIPE: the reader is gone, so nothing written from now on can arrive: end at once.
  if (first && signal != SIGPIPE && deferring.load() > 0) return;
  remove_registered_temporaries();
  _exit(128 + signal);
}

}  // namespace

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  for (int signal : terminating_signals) sigaddset(&action.sa_mask, signal);  // one handler at a time
  action.sa_flags = SA_RESTART;  // the work notices the flag; system calls need not fail
  for (int signal : terminating_signals) {
    // A signal ignored or handled before radiant started (nohup's SIGHUP, a profiler's
    // SIGPROF) stays so.
    struct sigaction before {};
    if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_DFL) sigaction(signal, &action, nullptr);
  }
  signal(SIGXFSZ, SIG_IGN);
}

const std::atomic<int>& interrupt_signal() { return received; }

DeferredInterrupts::DeferredInterrupts() { deferring.fetch_add(1); }

DeferredInterrupts::~DeferredInterrupts() { deferring.fetch_sub(1); }

void throw_if_interrupted() {
  if (int signal = received.load()) throw Interrupted{signal};
}

std::string signal_name(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "signal " + std::to_string(signal);
}

}  // namespace radiant::cli

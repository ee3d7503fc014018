#include "interrupts.h"

#include <signal.h>
#include <unistd.h>

#include "output/temporary_registry.h"

namespace radiant::cli {

namespace {

std::atomic<int> received{0};
std::atomic<int> deferring{0};  // live DeferredInterrupts

static_assert(std::atomic<int>::is_always_lock_free, "read and written by the signal handler");

// Async-signal-safe: atomics, unlink (in the registry) and _exit only.
void on_signal(int signal) {
  int none = 0;
  bool first = received.compare_exchange_strong(none, signal);
  if (first && deferring.load() > 0) return;
  remove_registered_temporaries();
  _exit(128 + signal);
}

}  // namespace

void install_signal_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  sigaddset(&action.sa_mask, SIGINT);  // one handler at a time
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESTART;  // the work notices the flag; system calls need not fail
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  signal(SIGXFSZ, SIG_IGN);
}

const std::atomic<int>& interrupt_signal() { return received; }

DeferredInterrupts::DeferredInterrupts() { deferring.fetch_add(1); }

DeferredInterrupts::~DeferredInterrupts() { deferring.fetch_sub(1); }

void throw_if_interrupted() {
  if (int signal = received.load()) throw Interrupted{signal};
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
  }
  return "a signal";
}

}  // namespace radiant::cli

#include "app/interrupt_signals.hpp"

#include <time.h>

#include <atomic>
#include <csignal>

namespace si {
namespace {

// A signal handler can only reach static storage, so these flags are the exception to "no
// global state"; they live in this file only. 0 = none, else the signal number; and when the
// first one came (CLOCK_MONOTONIC, ns).
std::atomic<int> g_signal{0};
std::atomic<long long> g_first_ns{0};

// One interrupt often arrives twice: Ctrl-C reaches a sweep's cases directly (one process group)
// and again through the sweep, which forwards it; a batch scheduler signals every process of
// the job and the sweep forwards too. A repeat within this window is the same request.
constexpr long long kRepeatWindowNs = 1'000'000'000;

long long monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);  // async-signal-safe (POSIX.1-2008)
  return static_cast<long long>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

extern "C" void on_interrupt(int signal) {
  const long long now = monotonic_ns();
  if (g_signal == 0) {
    g_signal = signal;
    g_first_ns = now;
    return;
  }
  if (now - g_first_ns < kRepeatWindowNs) return;
  std::signal(signal, SIG_DFL);  // a second request ends the process at once (default action);
  raise(signal);                 // both async-signal-safe (POSIX)
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  g_first_ns = 0;
  previous_int_ = std::signal(SIGINT, on_interrupt);
  previous_term_ = std::signal(SIGTERM, on_interrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
}

bool interrupted() {
  return g_signal != 0;
}

const char* interrupt_name() {
  switch (g_signal.load()) {
    case SIGINT:
      return "Ctrl-C";
    case SIGTERM:
      return "SIGTERM";
    default:
      return "";
  }
}

}  // namespace si

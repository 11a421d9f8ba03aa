#include "app/interrupt_signals.hpp"

#include <atomic>
#include <csignal>

namespace si {
namespace {

// A signal handler can only reach static storage, so this one flag is the exception to "no
// global state"; it lives in this file only. 0 = none, else the signal number.
std::atomic<int> g_signal{0};

extern "C" void on_interrupt(int signal) {
  g_signal = signal;
  std::signal(signal, SIG_DFL);  // async-signal-safe (POSIX): a second one ends the process
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_signal = 0;
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

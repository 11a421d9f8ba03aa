// Ctrl-C (SIGINT) and SIGTERM ask a run to stop after the current point and write what
// converged. SIGTERM matters as much as Ctrl-C: batch schedulers (Slurm, PBS) and `timeout` send
// it before SIGKILL, and a run that dies at once loses every point since its last checkpoint.
// A second signal of either kind, a second or more after the first, ends the process at once
// (the default action), for a user who does not want to wait for the current point; one within
// the second is the same request delivered twice (interrupt_signals.cpp says when that happens).
#pragma once

namespace si {

// Installs the handlers for its lifetime and restores the previous ones afterwards; clears the
// record of an earlier interrupt.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  void (*previous_int_)(int) = nullptr;
  void (*previous_term_)(int) = nullptr;
};

// True once SIGINT or SIGTERM arrived under a guard.
bool interrupted();

// "Ctrl-C" or "SIGTERM": what stopped the run, for its message; "" if none.
const char* interrupt_name();

}  // namespace si

#include "app/progress_line.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace si {

ProgressLine::ProgressLine(std::ostream& err, double depth_max)
    : err_(err), depth_max_(depth_max), tty_(isatty(STDERR_FILENO) != 0) {}

void ProgressLine::show(const PathPoint& p) {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double d = p.state.depth;
  pace_.add(d, elapsed);
  char eta[32] = "";
  if (const std::optional<double> left = pace_.remaining(depth_max_))
    std::snprintf(eta, sizeof eta, ", ETA %.0f s", *left);
  char line[256];
  std::snprintf(line, sizeof line,
                "depth %.4f / %.4g mm, force %.6g N, %d nodes in contact, step %.3g, %d "
                "iterations, %.1f s%s",
                d, depth_max_, p.state.force, p.state.contact_nodes, p.step, p.iterations, elapsed,
                eta);
  if (tty_)
    err_ << '\r' << line << "\033[K" << std::flush;
  else
    err_ << line << '\n';
}

void ProgressLine::failed(const cont::StepFailure& f) {
  char line[160];
  std::snprintf(line, sizeof line, "depth %.4f mm: a step of %.3g failed, ", f.p, f.step);
  std::string text = line;
  if (f.retry > 0) {
    std::snprintf(line, sizeof line, "retrying with %.3g: ", f.retry);
    text += line;
  }
  text += f.reason;
  err_ << (tty_ ? "\r\033[K" : "") << text << '\n' << std::flush;
}

void ProgressLine::done() {
  if (tty_) err_ << '\n';
}

}  // namespace si

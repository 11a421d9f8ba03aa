#include "io/thread_count.hpp"

#include <algorithm>
#include <thread>

#include "core/error.hpp"

namespace si {

void check_parallel_count(int count, const std::string& option, int least,
                          const std::string& unit) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int limit = kThreadsPerCore * hardware;
  if (count >= least && count <= limit) return;
  throw_input("expected " + std::to_string(least) + (least == 0 ? " (OpenMP's default)" : "") +
                  " to " + std::to_string(limit) + " " + unit + " (" +
                  std::to_string(kThreadsPerCore) + " per hardware thread; this machine has " +
                  std::to_string(hardware) + ")",
              Where{"command line", option, std::to_string(count), 0});
}

void check_thread_count(int threads) {
  check_parallel_count(threads, "--threads", 0, "threads");
}

}  // namespace si

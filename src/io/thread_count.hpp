// `--threads N` of the run and static commands (OpenMP threads of the element assembly) and
// `sweep -j N` (cases run at once). A count far above the machine's is never faster and can be
// fatal: `--threads 100000` crashed inside libgomp, 30000 took 114 s and 3 GB for a 0.4 s run.
// Counts up to kThreadsPerCore times the hardware threads are accepted (oversubscription a user
// may try on purpose), more are refused.
#pragma once

#include <string>

namespace si {

constexpr int kThreadsPerCore = 4;

// Throws an input error naming --threads unless 0 <= threads <= kThreadsPerCore * the hardware
// threads (at least kThreadsPerCore); 0 means OpenMP's default.
void check_thread_count(int threads);

// As check_thread_count for any such option: `least` <= count <= the same limit; `unit` names
// what is counted in the message ("threads", "cases at once").
void check_parallel_count(int count, const std::string& option, int least, const std::string& unit);

}  // namespace si

// OpenBLAS's worker threads spin and yield while waiting; on the small dense blocks of our
// sparse factorizations (CHOLMOD supernodes, UMFPACK fronts) and on a busy 2-core machine that
// cost more than it gained (perf: a third of a linear indentation path in sched_yield). The CLI
// therefore runs OpenBLAS single-threaded unless OPENBLAS_NUM_THREADS says otherwise. With the
// reference BLAS (no OpenBLAS) this does nothing.
#pragma once

namespace si {

// Returns true if OpenBLAS was found and limited.
bool limit_blas_threads();

}  // namespace si

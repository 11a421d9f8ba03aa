#include "core/blas_threads.hpp"

#include <dlfcn.h>

#include <cstdlib>

namespace si {

// Looked up at run time: the BLAS is a system alternative (reference BLAS or OpenBLAS), chosen
// after linking. A weak symbol would not do: the linker resolves an undefined weak reference in
// an executable to null when no library it links against defines it.
bool limit_blas_threads() {
  if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return false;
  using SetThreads = void (*)(int);
  const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  if (set == nullptr) return false;
  set(1);
  return true;
}

}  // namespace si

#include <coaxfit/base/blas_threads.h>

#include <dlfcn.h>

namespace coaxfit
{
  bool
  set_blas_threads(const int n_threads)
  {
    using Setter = void (*)(int);
    void *symbol = dlsym(RTLD_DEFAULT, "openblas_set_num_threads");
    if (symbol == nullptr)
      return false;
    reinterpret_cast<Setter>(symbol)(n_threads);
    return true;
  }
} // namespace coaxfit

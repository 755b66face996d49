#include <hati/base/blas_kernels.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace hati
{
void select_blas_kernels(char **argv)
{
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
    return;
  // OpenBLAS's own query, if the BLAS loaded is OpenBLAS
  using CoreName = char *(*)();
  const auto core_name =
      reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  if (core_name == nullptr || core_name() == nullptr)
    return;
  const std::string core = core_name();
  if (core != "Prescott" && core != "Core2" && core != "Penryn" && core != "Dunnington" &&
      core != "Nehalem" && core != "Sandybridge")
    return;
  __builtin_cpu_init();
  const char *target = nullptr;
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512vl"))
    target = "SkylakeX";
  else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    target = "Haswell";
  if (target == nullptr)
    return;
  setenv("OPENBLAS_CORETYPE", target, 1);
  // OpenBLAS's dynamic-architecture entry points: forget the kernel table
  // and choose it again, now from OPENBLAS_CORETYPE (what OpenBLAS does when
  // it is loaded); no BLAS call has run yet. Where they are missing or the
  // core did not change, start again with the variable set (0.5 s more)
  using Entry = void (*)();
  const auto quit = reinterpret_cast<Entry>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_quit"));
  const auto init = reinterpret_cast<Entry>(dlsym(RTLD_DEFAULT, "gotoblas_dynamic_init"));
  if (quit != nullptr && init != nullptr)
  {
    quit();
    init();
    if (core_name() != nullptr && std::string(core_name()) == target)
      return;
  }
  execv("/proc/self/exe", argv);
  // exec failed: go on with the kernels OpenBLAS chose
  unsetenv("OPENBLAS_CORETYPE");
}
} // namespace hati

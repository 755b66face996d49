/**
 * @file
 * libFuzzer harness of the accelerogram reader (Accelerogram::read): the
 * input is written to a scratch file read twice, as a PEER NGA `.AT2` file
 * and as a two-column `time value` file, and every record read is
 * evaluated (interpolation at and between the samples, peak). Errors thrown
 * as exceptions are the expected outcome of bad input; crashes, sanitizer
 * reports, hangs and other exceptions are findings. Run by bench/fuzz.sh.
 */
#include <hati/loading/accelerogram.h>

#include "fuzz_common.h"

#include <cmath>
#include <exception>
#include <filesystem>

namespace
{
std::string at2_file, text_file;

void exercise(const hati::Accelerogram &g)
{
  const auto &t = g.times();
  volatile double sink = g.peak().first;
  for (std::size_t i = 0; i < t.size() && i < 64; ++i)
  {
    sink = sink + g(t[i]);
    if (i + 1 < t.size())
      sink = sink + g(0.5 * (t[i] + t[i + 1]));
  }
  sink = sink + g(t.front() - 1.) + g(t.back() + 1.);
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int *, char ***)
{
  at2_file = hati::fuzz::scratch_file(".AT2");
  text_file = hati::fuzz::scratch_file(".txt");
  std::filesystem::remove(text_file);
  std::filesystem::create_symlink(at2_file, text_file);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  hati::fuzz::write_file(at2_file, data, size);
  static const char *const units[3] = {"g", "m/s^2", "cm/s^2"};
  for (const std::string &file : {at2_file, text_file})
    try
    {
      exercise(hati::Accelerogram::read(file, units[size % 3], 1.));
    }
    catch (const std::exception &)
    {
      // a one-line error: the expected outcome of bad input
    }
  return 0;
}

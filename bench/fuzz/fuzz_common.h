/**
 * @file
 * Shared helpers of the libFuzzer harnesses of bench/fuzz/ (built with
 * HATI_FUZZ=ON, run by bench/fuzz.sh): a per-process scratch file for the
 * readers that take a file name, and silencing of the terminal output.
 */
#ifndef hati_bench_fuzz_common_h
#define hati_bench_fuzz_common_h

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <streambuf>
#include <string>

namespace hati
{
namespace fuzz
{
/** A stream buffer that drops everything (model builds print notes). */
class NullBuffer : public std::streambuf
{
protected:
  int overflow(int c) override { return c; }
  std::streamsize xsputn(const char *, std::streamsize n) override { return n; }
};

/** Send std::cout to nowhere for the rest of the process (stderr stays). */
inline void silence_stdout()
{
  static NullBuffer null;
  std::cout.rdbuf(&null);
}

/**
 * A scratch file name in the temporary directory, unique to this process,
 * ending with @p suffix (the readers choose the format by the extension).
 */
inline std::string scratch_file(const std::string &suffix)
{
  const char *tmp = std::getenv("TMPDIR");
  return std::string(tmp && *tmp ? tmp : "/tmp") + "/hati-fuzz-" +
         std::to_string(::getpid()) + suffix;
}

/** Write @p size bytes at @p data to @p path (truncating it). */
inline void write_file(const std::string &path, const uint8_t *data, const size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
}
} // namespace fuzz
} // namespace hati

#endif

// Unit test of the output primitives of issue #7 (include/hati/output):
// - append_number() and the num_put facet of use_shortest_numbers() write
//   doubles that read back (strtod) to the same bits, for 200000 random bit
//   patterns (every exponent, subnormals) and edge values, in no more
//   characters than printf's %.17g;
// - CsvFile keeps the rows in memory until flush(), then writes them whole;
//   a write error (/dev/full: ENOSPC) throws one line naming the file and
//   "No space left on device";
// - write_file_atomically() replaces a file and leaves no temporary file,
//   with and without fsync, and into a missing directory it throws naming
//   the file; sync_file() of a missing file throws naming it.
// Returns non-zero on failure.
#include <deal.II/base/exceptions.h>

#include "test_tools.h"

#include <hati/output/csv_file.h>
#include <hati/output/run_directory.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <unistd.h>

using namespace hati_test;

namespace
{
std::string read(const std::string &name)
{
  std::ifstream in(name);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool same_bits(const double a, const double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}
} // namespace

int main()
{
  // --- shortest round-trip numbers ---
  std::mt19937_64 random(7);
  unsigned long mismatches = 0, longer = 0, tested = 0;
  std::ostringstream facet;
  hati::use_shortest_numbers(facet);
  auto test = [&](const double x)
  {
    if (!std::isfinite(x))
      return;
    ++tested;
    const std::string text = hati::shortest_number(x);
    if (!same_bits(std::strtod(text.c_str(), nullptr), x))
      ++mismatches;
    char printf_text[40];
    std::snprintf(printf_text, sizeof(printf_text), "%.17g", x);
    if (text.size() > std::strlen(printf_text))
      ++longer;
    facet.str("");
    facet << x;
    if (facet.str() != text)
      ++mismatches;
  };
  for (int i = 0; i < 200000; ++i)
  {
    const std::uint64_t bits = random();
    double x;
    std::memcpy(&x, &bits, sizeof(x));
    test(x);
  }
  for (const double x : {0.,
                         -0.,
                         1e-6,
                         0.1,
                         1. / 3.,
                         6.000000000000001e-05,
                         1e300,
                         -1e-300,
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::max(),
                         std::numeric_limits<double>::epsilon()})
    test(x);
  expect(mismatches == 0,
         "shortest numbers read back to the same bits (stream facet too): " +
             std::to_string(tested) + " values, " + std::to_string(mismatches) +
             " mismatches");
  expect(longer == 0, "shortest numbers are never longer than %.17g");
  expect(hati::shortest_number(0.1) == "0.1" && hati::shortest_number(1e-6) == "1e-06" &&
             hati::shortest_number(2.) == "2",
         "0.1, 1e-6 and 2 are written 0.1, 1e-06 and 2");

  // --- CsvFile: whole rows at flush ---
  const std::string dir = std::filesystem::temp_directory_path().string() +
                          "/hati_unit_csv_" + std::to_string(::getpid());
  std::filesystem::create_directories(dir);
  {
    hati::CsvFile csv;
    csv.open(dir + "/rows.csv");
    csv << "time,x\n" << 0.5 << ',' << 7u << '\n';
    expect(read(dir + "/rows.csv").empty(), "rows stay in the buffer until flush()");
    csv.flush();
    expect(read(dir + "/rows.csv") == "time,x\n0.5,7\n",
           "flush() writes the rows: '" + read(dir + "/rows.csv") + "'");
    csv.close();
  }
  {
    std::string message;
    try
    {
      hati::CsvFile full;
      full.open("/dev/full");
      full << 1. << '\n';
      full.flush();
    }
    catch (const std::exception &e)
    {
      message = message_of(e);
    }
    expect(message.find("/dev/full") != std::string::npos &&
               message.find("No space left on device") != std::string::npos,
           "a full device: the error names the file and the system error: " + message);
  }

  // --- atomic replacement ---
  hati::write_file_atomically(dir + "/summary.json", "{}\n");
  hati::write_file_atomically(dir + "/summary.json", "{\"a\": 1}\n");
  expect(read(dir + "/summary.json") == "{\"a\": 1}\n" &&
             !std::filesystem::exists(dir + "/.summary.json.tmp"),
         "write_file_atomically replaces the file and leaves no temporary file");
  {
    std::string message;
    try
    {
      hati::write_file_atomically(dir + "/missing/summary.json", "{}\n");
    }
    catch (const std::exception &e)
    {
      message = message_of(e);
    }
    expect(message.find(dir + "/missing/summary.json") != std::string::npos &&
               message.find("No such file or directory") != std::string::npos,
           "into a missing directory: " + message);
  }
  // without fsync (a file replaced often), then made durable by sync_file()
  hati::write_file_atomically(dir + "/solution.pvd", "<a/>\n", false);
  hati::write_file_atomically(dir + "/solution.pvd", "<b/>\n", false);
  hati::sync_file(dir + "/solution.pvd");
  expect(read(dir + "/solution.pvd") == "<b/>\n" &&
             !std::filesystem::exists(dir + "/.solution.pvd.tmp"),
         "write_file_atomically without fsync replaces the file too");
  {
    std::string message;
    try
    {
      hati::sync_file(dir + "/missing.pvd");
    }
    catch (const std::exception &e)
    {
      message = message_of(e);
    }
    expect(message.find(dir + "/missing.pvd") != std::string::npos &&
               message.find("No such file or directory") != std::string::npos,
           "sync_file of a missing file: " + message);
  }
  std::filesystem::remove_all(dir);
  return finish();
}

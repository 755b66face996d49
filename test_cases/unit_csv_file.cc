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
//   the file; sync_file() of a missing file throws naming it;
// - issue #19: no output file is written through a symbolic link (CsvFile,
//   write_file_atomically() onto a link or with a link as its temporary,
//   OutputStream, sync_file()): each is refused with "<path> is a symbolic
//   link: refused" and the link's target keeps its bytes; a stale
//   temporary file is replaced;
// - append_whole_rows() writes 3 MiB of rows exactly (through its child
//   process), and a write cut by the file size limit (RLIMIT_FSIZE, a
//   partial write then EFBIG) leaves the file on its last whole row, the
//   error "File too large" thrown by CsvFile, which then writes no more;
// - OutputFolder::overwrite() rewrites a file in place, shorter or longer.
// Returns non-zero on failure.
#include <deal.II/base/exceptions.h>

#include "test_tools.h"

#include <hati/output/csv_file.h>
#include <hati/output/run_directory.h>

#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace hati_unit_csv_file
{

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

/** The one-line message of what @p f throws ("" if nothing). */
template <class F> std::string thrown(F f)
{
  try
  {
    f();
  }
  catch (const std::exception &e)
  {
    return message_of(e);
  }
  return "";
}

bool same_bits(const double a, const double b)
{
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}
} // namespace

HATI_UNIT_TEST(csv_file)
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

  // --- issue #19: never through a symbolic link ---
  const std::string victim = dir + "/victim.txt";
  const std::string victim_text = "outside the output folder\n";
  {
    std::ofstream(victim) << victim_text;
  }
  const auto refused = [&](const std::string &message, const std::string &link)
  {
    return message.find(link + " is a symbolic link: refused") != std::string::npos &&
           read(victim) == victim_text;
  };
  std::filesystem::create_symlink(victim, dir + "/linked.csv");
  std::string message = thrown([&] { hati::CsvFile().open(dir + "/linked.csv"); });
  expect(refused(message, dir + "/linked.csv"),
         "CsvFile refuses a link, its target unchanged: " + message);
  message = thrown([&] { hati::write_file_atomically(dir + "/linked.csv", "x\n"); });
  expect(refused(message, dir + "/linked.csv"),
         "write_file_atomically refuses a link as the file: " + message);
  std::filesystem::create_symlink(victim, dir + "/.linked.json.tmp");
  message = thrown([&] { hati::write_file_atomically(dir + "/linked.json", "x\n"); });
  expect(refused(message, dir + "/.linked.json.tmp") &&
             !std::filesystem::exists(dir + "/linked.json"),
         "write_file_atomically refuses a link as the temporary: " + message);
  message = thrown(
      [&]
      {
        hati::OutputStream out(hati::OutputFolder(dir).create("linked.csv"));
        out << "x\n";
        out.close();
      });
  expect(refused(message, dir + "/linked.csv"),
         "OutputStream refuses a link: " + message);
  message = thrown([&] { hati::sync_file(dir + "/linked.csv"); });
  expect(refused(message, dir + "/linked.csv"), "sync_file refuses a link: " + message);
  {
    std::ofstream(dir + "/.stale.json.tmp") << "left by a killed run";
    hati::write_file_atomically(dir + "/stale.json", "{}\n");
    expect(read(dir + "/stale.json") == "{}\n" &&
               !std::filesystem::exists(dir + "/.stale.json.tmp"),
           "a stale temporary file is replaced");
  }
  {
    hati::OutputStream out(hati::OutputFolder(dir).create("stream.txt"));
    for (int i = 0; i < 100000; ++i)
      out << i << '\n';
    out.close();
    std::ostringstream expected;
    for (int i = 0; i < 100000; ++i)
      expected << i << '\n';
    expect(read(dir + "/stream.txt") == expected.str(),
           "OutputStream writes what is streamed (beyond its 64 KiB buffer)");
  }

  // --- whole rows: 3 MiB through the child; a cut write cut back ---
  {
    std::string rows;
    for (int i = 0; rows.size() < (3u << 20); ++i)
      rows += "row " + std::to_string(i) + ",1.5,-2\n";
    const hati::OutputFile file = hati::create_output_file(dir + "/rows3.csv");
    const int error = hati::append_whole_rows(file.fd, rows.data(), rows.size());
    expect(error == 0 && read(dir + "/rows3.csv") == rows,
           "append_whole_rows writes " + std::to_string(rows.size()) +
               " bytes of rows exactly");
  }
  {
    // rows of 10 bytes, a file size limit of 4096 + 5: the write of 8000
    // bytes stops at the limit (4101 bytes), the next one fails with EFBIG
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit previous;
    getrlimit(RLIMIT_FSIZE, &previous);
    rlimit limit = previous;
    limit.rlim_cur = 4096 + 5;
    setrlimit(RLIMIT_FSIZE, &limit);
    hati::CsvFile csv;
    csv.open(dir + "/cut.csv");
    csv << "time,x,y\n"; // 9 bytes, then rows of 10
    for (int i = 0; i < 799; ++i)
      csv << "0.5,1.5," << i % 10 << '\n';
    message = thrown([&] { csv.flush(); });
    const bool stopped = !csv.is_open() && thrown(
                                               [&]
                                               {
                                                 csv << "1,2,3\n";
                                                 csv.close();
                                               })
                                               .empty();
    setrlimit(RLIMIT_FSIZE, &previous);
    const std::string left = read(dir + "/cut.csv");
    expect(message.find(dir + "/cut.csv") != std::string::npos &&
               message.find("File too large") != std::string::npos,
           "a write cut by the file size limit: one line naming the file and the "
           "error: " +
               message);
    expect(left.size() == 9 + 409 * 10 && left.back() == '\n' && stopped,
           "... the file is cut back to its last whole row (" +
               std::to_string(left.size()) +
               " bytes, 4099 expected) and no more is "
               "written");
  }

  // --- in-place overwrite (the failed summary.json on a full disk) ---
  {
    const hati::OutputFolder folder(dir);
    hati::write_file_atomically(dir + "/summary.json",
                                "{\n  \"status\": \"running\"\n}\n");
    const bool longer = folder.overwrite(
        "summary.json", "{\"status\": \"failed\", \"message\": \"x\"}\n");
    const std::string first = read(dir + "/summary.json");
    const bool shorter = folder.overwrite("summary.json", "{}\n");
    expect(longer && first == "{\"status\": \"failed\", \"message\": \"x\"}\n" &&
               shorter && read(dir + "/summary.json") == "{}\n" &&
               !folder.overwrite("missing.json", "{}\n") &&
               !folder.overwrite("linked.csv", "{}\n") && read(victim) == victim_text,
           "OutputFolder::overwrite rewrites in place, longer and shorter, never "
           "creates a file nor follows a link");
  }
  std::filesystem::remove_all(dir);
  return finish();
}
} // namespace hati_unit_csv_file

// Unit test of state.bin (issue #59, finding 3; include/hati/output/state_file.h):
// - a state written by state_file_content() reads back bitwise
//   (read_state_file(): time, model, parameters, files, every vector);
// - every single byte of the file changed (one bit of each byte flipped,
//   bit i mod 8 of byte i: header and data) is refused with the file
//   named: FNV-1a changes for any one changed byte, so the checksum line
//   or the format catches each (no variant may load);
// - the time line altered with a fresh checksum (a file written by hand)
//   still parses strictly: '+0.5', ' 0.5', '0.5s', '1e999' refused;
// - another Young's modulus in the model's parameters is refused naming
//   the entry and both values, another mesh file digest naming the file;
// - a state of format 1 (before the checksum) is refused saying so;
// - a FIFO, /dev/zero and a directory are refused before they are opened,
//   within a second each (a FIFO would block for ever, /dev/zero never
//   end).
// Returns non-zero on failure.
#include <deal.II/base/exceptions.h>

#include "test_tools.h"

#include <hati/base/fnv_hash.h>
#include <hati/output/state_file.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace hati_unit_state_file
{
using namespace hati;
using namespace hati_test;

namespace
{
const std::string where = "Analysis/Initial state file";

void write(const std::string &path, const std::string &bytes)
{
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(bytes.data(), bytes.size());
}

/** The message read_state_file() throws for @p path, empty if it loads. */
std::string
refusal(const std::string &path, const unsigned int n, const RunState &expected)
{
  try
  {
    read_state_file(path, n, expected, where);
  }
  catch (const std::exception &e)
  {
    return message_of(e);
  }
  return "";
}

/** @p content with its checksum line made anew (a file edited by hand). */
std::string rechecksummed(const std::string &content)
{
  const auto first = content.find('\n'), second = content.find('\n', first + 1);
  const std::string rest = content.substr(second + 1);
  return content.substr(0, first + 1) + "checksum " + hex_digits(fnv1a64(rest)) + "\n" +
         rest;
}

RunState example()
{
  RunState s;
  s.time = 0.123456789012345678;
  s.model = "3D solid: 2 x 1 x 1 cells\nof degree 1";
  s.model_parameters = {"Model/Type = 3D solid", "Model/Solid/Young's modulus = 2.1e11"};
  s.model_files = {"Model/Frame/Mesh file = a.msh: fnv1a64 0123456789abcdef, 12 bytes"};
  for (Vector<double> *v : {&s.displacement, &s.velocity, &s.contact_force})
  {
    v->reinit(6);
    for (unsigned int i = 0; i < 6; ++i)
      (*v)[i] = 1e-3 * (i + 1) * (v == &s.velocity ? -1. : 1.);
  }
  s.interface_multiplier.reinit(2);
  s.interface_multiplier[1] = 42.;
  s.interface_signature = "00112233445566ff";
  s.implicit_interface.reinit(4);
  s.implicit_interface[3] = -7.;
  return s;
}
} // namespace

HATI_UNIT_TEST(state_file)
{
  char folder_template[] = "/tmp/hati_unit_state_XXXXXX";
  const std::string folder = ::mkdtemp(folder_template);
  const std::string path = folder + "/state.bin";
  const RunState s = example();
  const std::string content = state_file_content(s);
  write(path, content);

  // 1. round trip
  const RunState r = read_state_file(path, 6, s, where);
  bool same = r.time == s.time && r.model == state_model_line(s.model) &&
              r.model_parameters == s.model_parameters &&
              r.model_files == s.model_files &&
              r.interface_signature == s.interface_signature;
  for (unsigned int i = 0; i < 6; ++i)
    same = same && r.displacement[i] == s.displacement[i] &&
           r.velocity[i] == s.velocity[i] && r.contact_force[i] == s.contact_force[i];
  same = same && r.interface_multiplier[1] == 42. && r.implicit_interface[3] == -7.;
  expect(same, "round trip: every value read back bitwise");

  // 2. every bit of every byte flipped: refused, the file named
  unsigned int loaded = 0, unnamed = 0;
  for (std::size_t i = 0; i < content.size(); ++i)
  {
    std::string damaged = content;
    damaged[i] = static_cast<char>(damaged[i] ^ (1u << (i % 8)));
    write(path, damaged);
    const std::string m = refusal(path, 6, s);
    loaded += m.empty() ? 1 : 0;
    unnamed += !m.empty() && m.find(where + " = " + path) != 0 ? 1 : 0;
  }
  std::cout << "  " << content.size() << " variants, each with one byte changed"
            << std::endl;
  expect(loaded == 0,
         "every changed byte refused (" + std::to_string(loaded) + " variants loaded)");
  expect(unnamed == 0, "every refusal names the parameter and the file");
  // the time's digit flipped (the audit's case: 1 ms later) names the checksum
  {
    std::string later = content;
    later.replace(later.find("time 0.1234"), 11, "time 0.1244");
    write(path, later);
    const std::string m = refusal(path, 6, s);
    expect(m.find("checksum does not match") != std::string::npos,
           "a digit of the time changed: 'checksum does not match' (" + m + ")");
  }

  // 3. a time line edited by hand (checksum made anew) parses strictly
  for (const std::string bad : {"+0.5", " 0.5", "0.5s", "1e999", "-0", "nan", ""})
  {
    std::string edited = content;
    const auto at = edited.find("time ") + 5;
    edited.replace(at, edited.find('\n', at) - at, bad);
    write(path, rechecksummed(edited));
    const std::string m = refusal(path, 6, s);
    expect(m.find("is not a finite time >= 0") != std::string::npos,
           "time '" + bad + "' refused (" + m + ")");
  }

  // 4. another model: Young's modulus, a mesh file
  write(path, content);
  {
    RunState other = s;
    other.model_parameters[1] = "Model/Solid/Young's modulus = 2e11";
    const std::string m = refusal(path, 6, other);
    expect(m.find("another model: Model/Solid/Young's modulus: '2.1e11' in the state, "
                  "'2e11' in this run") != std::string::npos,
           "another E refused naming the modulus (" + m + ")");
    other = s;
    other.model_files[0] =
        "Model/Frame/Mesh file = a.msh: fnv1a64 00000000000000ff, 12 bytes";
    const std::string f = refusal(path, 6, other);
    expect(f.find("other mesh files: Model/Frame/Mesh file = a.msh:") !=
               std::string::npos,
           "another mesh file refused naming it (" + f + ")");
  }

  // 5. format 1
  write(path, "hati state 1\ntime 0\nn_dofs 6\nmodel x\ndata\n");
  expect(refusal(path, 6, s).find("older hati (format 1") != std::string::npos,
         "format 1 refused saying so");

  // 6. what is not a regular file, before it is opened
  const std::string fifo = folder + "/fifo";
  ::mkfifo(fifo.c_str(), 0600);
  for (const std::string &p : {fifo, std::string("/dev/zero"), folder})
  {
    const auto start = std::chrono::steady_clock::now();
    const std::string m = refusal(p, 6, s);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expect(m.find("is not a regular file") != std::string::npos && seconds < 1.,
           p + " refused in " + std::to_string(seconds) + " s (" + m + ")");
  }
  std::remove(fifo.c_str());
  std::remove(path.c_str());
  ::rmdir(folder.c_str());
  return finish();
}
} // namespace hati_unit_state_file

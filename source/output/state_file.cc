#include <deal.II/base/exceptions.h>

#include <hati/base/names.h>
#include <hati/output/state_file.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace hati
{
namespace
{
constexpr const char *format_line = "hati state 1";

/** The next header line of @p in, which must start with @p key and a space. */
std::string
header_value(std::istringstream &in, const std::string &key, const std::string &where)
{
  std::string line;
  AssertThrow(std::getline(in, line) && line.rfind(key + " ", 0) == 0,
              ExcMessage(where + ": the header has no '" + key +
                         "' line where expected (not a state.bin written by hati, or "
                         "damaged)"));
  return line.substr(key.size() + 1);
}

/**
 * An optional header line `<key> <count>[ <rest>]`: false (nothing read)
 * if @p line does not start with @p key and a space; otherwise @p count,
 * @p rest (after one space; empty if the count ends the line) and whether
 * a count was read at all (@p valid).
 */
bool optional_count_line(const std::string &line,
                         const std::string &key,
                         unsigned long &count,
                         std::string &rest,
                         bool &valid)
{
  if (line.rfind(key + " ", 0) != 0)
    return false;
  const std::string text = line.substr(key.size() + 1);
  char *end = nullptr;
  count = std::strtoul(text.c_str(), &end, 10);
  valid = end != text.c_str() && (*end == '\0' || *end == ' ');
  rest = *end == ' ' ? std::string(end + 1) : std::string();
  return true;
}
} // namespace

std::string state_model_line(const std::string &description)
{
  std::string line = description;
  for (char &c : line)
    if (c == '\n' || c == '\r')
      c = ' ';
  return line;
}

std::string state_file_content(const RunState &state)
{
  std::ostringstream s;
  s.precision(17);
  s << format_line << "\ntime " << state.time << "\nn_dofs " << state.displacement.size()
    << "\nmodel " << state_model_line(state.model) << '\n';
  if (state.interface_multiplier.size() > 0)
    s << "interface " << state.interface_multiplier.size() << ' '
      << state.interface_signature << '\n';
  if (state.implicit_interface.size() > 0)
    s << "implicit_interface " << state.implicit_interface.size() << '\n';
  s << "data\n";
  std::string content = s.str();
  const std::size_t n = state.displacement.size(), header = content.size();
  Assert(state.velocity.size() == n && state.contact_force.size() == n,
         ExcMessage("state_file_content: vectors of different sizes"));
  const std::size_t k = state.interface_multiplier.size(),
                    l = state.implicit_interface.size();
  content.resize(header + (3 * n + k + l) * sizeof(double));
  std::size_t at = header;
  for (const Vector<double> *v :
       {&state.displacement, &state.velocity, &state.contact_force})
  {
    std::memcpy(&content[at], v->data(), n * sizeof(double));
    at += n * sizeof(double);
  }
  if (k > 0)
    std::memcpy(&content[at], state.interface_multiplier.data(), k * sizeof(double));
  at += k * sizeof(double);
  if (l > 0)
    std::memcpy(&content[at], state.implicit_interface.data(), l * sizeof(double));
  return content;
}

RunState read_state_file(const std::string &path,
                         const unsigned int n_dofs,
                         const std::string &model,
                         const std::string &parameter)
{
  const std::string where = parameter + " = " + printable(path);
  std::ifstream file(path, std::ios::binary);
  AssertThrow(
      file, ExcMessage(where + ": cannot open the state file: " + std::strerror(errno)));
  const std::string content((std::istreambuf_iterator<char>(file)),
                            std::istreambuf_iterator<char>());
  std::istringstream in(content);
  std::string line;
  AssertThrow(std::getline(in, line) && line == format_line,
              ExcMessage(where + ": not a state file of hati (its first line is not '" +
                         format_line + "'; Output/State interval writes state.bin)"));
  RunState state;
  const std::string time = header_value(in, "time", where);
  const std::string dofs = header_value(in, "n_dofs", where);
  state.model = header_value(in, "model", where);
  std::getline(in, line);
  unsigned long n_interface = 0, n_implicit = 0;
  std::string rest;
  bool valid = false;
  if (optional_count_line(line, "interface", n_interface, rest, valid))
  {
    state.interface_signature = rest;
    AssertThrow(valid && n_interface < n_dofs && rest.size() == 16,
                ExcMessage(where + ": the interface line '" + printable(line) +
                           "' does not give a number of interface rows"));
    std::getline(in, line);
  }
  if (optional_count_line(line, "implicit_interface", n_implicit, rest, valid))
  {
    AssertThrow(valid && rest.empty() && n_implicit <= 2ul * n_dofs && n_interface > 0,
                ExcMessage(where + ": the implicit_interface line '" + printable(line) +
                           "' does not give a number of values"));
    std::getline(in, line);
  }
  AssertThrow(in && line == "data",
              ExcMessage(where + ": the header does not end with a 'data' line"));
  char *end = nullptr;
  state.time = std::strtod(time.c_str(), &end);
  AssertThrow(end != time.c_str() && *end == '\0' && std::isfinite(state.time) &&
                  state.time >= 0.,
              ExcMessage(where + ": the time '" + printable(time) +
                         "' is not a finite time >= 0 (s)"));
  AssertThrow(dofs == std::to_string(n_dofs),
              ExcMessage(where + ": the state has " + printable(dofs) +
                         " DoFs, the model of this run " + std::to_string(n_dofs) +
                         ": it was written for another model or mesh"));
  AssertThrow(state.model == state_model_line(model),
              ExcMessage(where + ": the state was written for the model '" +
                         printable(state.model) + "', this run's is '" +
                         state_model_line(model) + "'"));
  // (a header without data leaves the stream at its end: tellg() is -1)
  const std::size_t data = in.tellg() < 0 ? content.size()
                                          : static_cast<std::size_t>(in.tellg()),
                    bytes = (3 * std::size_t(n_dofs) + n_interface + n_implicit) *
                            sizeof(double);
  AssertThrow(content.size() == data + bytes,
              ExcMessage(where + ": " + std::to_string(content.size() - data) +
                         " bytes of data where " + std::to_string(bytes) +
                         " were expected (a truncated or damaged file)"));
  std::size_t at = data;
  for (Vector<double> *v : {&state.displacement, &state.velocity, &state.contact_force})
  {
    v->reinit(n_dofs);
    std::memcpy(v->data(), &content[at], n_dofs * sizeof(double));
    at += n_dofs * sizeof(double);
  }
  state.interface_multiplier.reinit(n_interface);
  if (n_interface > 0)
    std::memcpy(
        state.interface_multiplier.data(), &content[at], n_interface * sizeof(double));
  at += n_interface * sizeof(double);
  state.implicit_interface.reinit(n_implicit);
  if (n_implicit > 0)
    std::memcpy(
        state.implicit_interface.data(), &content[at], n_implicit * sizeof(double));
  for (const Vector<double> *v : {&state.displacement,
                                  &state.velocity,
                                  &state.contact_force,
                                  &state.interface_multiplier,
                                  &state.implicit_interface})
    for (const double x : *v)
      AssertThrow(std::isfinite(x),
                  ExcMessage(where + ": the state holds a value that is not finite"));
  return state;
}
} // namespace hati

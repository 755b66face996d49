#include <deal.II/base/exceptions.h>

#include <hati/base/fnv_hash.h>
#include <hati/base/input_file.h>
#include <hati/base/names.h>
#include <hati/output/state_file.h>

#include <map>

#include <cctype>
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
constexpr const char *format_line = "hati state 2";
constexpr const char *checksum_key = "checksum ";

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

/** A header line `<key> <n>` and the n lines after it. */
std::vector<std::string>
header_lines(std::istringstream &in, const std::string &key, const std::string &where)
{
  const std::string count = header_value(in, key, where);
  char *end = nullptr;
  const unsigned long n = std::strtoul(count.c_str(), &end, 10);
  AssertThrow(
      end != count.c_str() && *end == '\0' && n < 100000,
      ExcMessage(where + ": the header's '" + key + "' line does not give a count"));
  std::vector<std::string> lines(n);
  for (auto &line : lines)
    AssertThrow(std::getline(in, line),
                ExcMessage(where + ": the header ends within its '" + key + "' lines"));
  return lines;
}

/** `Entry = value` lines as a map from the entry to the value. */
std::map<std::string, std::string> entries(const std::vector<std::string> &lines,
                                           const std::string &separator)
{
  std::map<std::string, std::string> m;
  for (const auto &line : lines)
  {
    const auto at = line.find(separator);
    m[line.substr(0, at)] =
        at == std::string::npos ? std::string() : line.substr(at + separator.size());
  }
  return m;
}

/**
 * What differs between the lines @p state and @p run (`entry<separator>value`),
 * at most three entries, as `entry: <value> in the state, <value> in this run`.
 */
std::string differences(const std::vector<std::string> &state,
                        const std::vector<std::string> &run,
                        const std::string &separator)
{
  const auto a = entries(state, separator), b = entries(run, separator);
  std::map<std::string, std::pair<std::string, std::string>> d;
  for (const auto &[k, v] : a)
    if (b.count(k) == 0 || b.at(k) != v)
      d[k] = {"'" + v + "'", b.count(k) ? "'" + b.at(k) + "'" : std::string("none")};
  for (const auto &[k, v] : b)
    if (a.count(k) == 0)
      d[k] = {"none", "'" + v + "'"};
  std::string text;
  unsigned int n = 0;
  for (const auto &[k, v] : d)
  {
    if (n == 3)
    {
      text += "; and " + std::to_string(d.size() - 3) + " more";
      break;
    }
    text += (n++ == 0 ? "" : "; ") + k + ": " + v.first + " in the state, " + v.second +
            " in this run";
  }
  return printable(text);
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
  s << "time " << state.time << "\nn_dofs " << state.displacement.size() << "\nmodel "
    << state_model_line(state.model) << "\nparameters " << state.model_parameters.size()
    << '\n';
  for (const auto &line : state.model_parameters)
    s << state_model_line(line) << '\n';
  s << "files " << state.model_files.size() << '\n';
  for (const auto &line : state.model_files)
    s << state_model_line(line) << '\n';
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
  // the checksum of everything after its line: any byte changed is seen
  return std::string(format_line) + "\n" + checksum_key + hex_digits(fnv1a64(content)) +
         "\n" + content;
}

RunState read_state_file(const std::string &path,
                         const unsigned int n_dofs,
                         const RunState &expected,
                         const std::string &parameter)
{
  const std::string where = parameter + " = " + printable(path);
  // a FIFO, a device or a directory refused before it is opened
  require_regular_file(path, where, "state");
  std::ifstream file(path, std::ios::binary);
  AssertThrow(
      file, ExcMessage(where + ": cannot open the state file: " + std::strerror(errno)));
  const std::string content((std::istreambuf_iterator<char>(file)),
                            std::istreambuf_iterator<char>());
  AssertThrow(
      !file.bad(),
      ExcMessage(where + ": cannot read the state file: " + std::strerror(errno)));
  std::istringstream in(content);
  std::string line;
  const bool has_format = static_cast<bool>(std::getline(in, line));
  AssertThrow(!has_format || line != "hati state 1",
              ExcMessage(where + ": a state file of an older hati (format 1, without a "
                                 "checksum); run that step again to write it anew"));
  AssertThrow(has_format && line == format_line,
              ExcMessage(where + ": not a state file of hati (its first line is not '" +
                         format_line + "'; Output/State interval writes state.bin)"));
  AssertThrow(std::getline(in, line) && line.rfind(checksum_key, 0) == 0,
              ExcMessage(where + ": the header has no checksum line (damaged)"));
  const std::size_t checked =
      in.tellg() < 0 ? content.size() : static_cast<std::size_t>(in.tellg());
  AssertThrow(line.substr(std::strlen(checksum_key)) ==
                  hex_digits(fnv1a64(content.data() + checked, content.size() - checked)),
              ExcMessage(where +
                         ": the checksum does not match its content: the file "
                         "is damaged or was changed (" +
                         std::to_string(content.size()) + " bytes)"));
  RunState state;
  const std::string time = header_value(in, "time", where);
  const std::string dofs = header_value(in, "n_dofs", where);
  state.model = header_value(in, "model", where);
  state.model_parameters = header_lines(in, "parameters", where);
  state.model_files = header_lines(in, "files", where);
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
  // the time as written (17 digits): nothing before or after the number
  char *end = nullptr;
  state.time = std::strtod(time.c_str(), &end);
  AssertThrow(!time.empty() && (std::isdigit(static_cast<unsigned char>(time[0])) != 0) &&
                  end != time.c_str() && *end == '\0' && std::isfinite(state.time) &&
                  state.time >= 0.,
              ExcMessage(where + ": the time '" + printable(time) +
                         "' is not a finite time >= 0 (s)"));
  AssertThrow(dofs == std::to_string(n_dofs),
              ExcMessage(where + ": the state has " + printable(dofs) +
                         " DoFs, the model of this run " + std::to_string(n_dofs) +
                         ": it was written for another model or mesh"));
  std::vector<std::string> parameters, files;
  for (const auto &l : expected.model_parameters)
    parameters.push_back(state_model_line(l));
  for (const auto &l : expected.model_files)
    files.push_back(state_model_line(l));
  AssertThrow(state.model_parameters == parameters,
              ExcMessage(where + ": the state was written for another model: " +
                         differences(state.model_parameters, parameters, " = ")));
  AssertThrow(state.model_files == files,
              ExcMessage(where + ": the state was written with other mesh files: " +
                         differences(state.model_files, files, ": ")));
  AssertThrow(state.model == state_model_line(expected.model),
              ExcMessage(where + ": the state was written for the model '" +
                         printable(state.model) + "', this run's is '" +
                         state_model_line(expected.model) + "'"));
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

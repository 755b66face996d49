#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hati/base/fnv_hash.h>
#include <hati/base/input_file.h>
#include <hati/output/run_directory.h>
#include <hati/run/simulation.h>
#include <hati/run/suite_checks.h>

#include <cstdint>
#include <cstdio>
#include <fstream>

namespace hati
{
namespace
{
/** The parts of the path `Subsection/.../Entry`. */
std::vector<std::string> path_parts(const std::string &path)
{
  std::vector<std::string> parts;
  std::string::size_type start = 0, slash;
  while ((slash = path.find('/', start)) != std::string::npos)
  {
    parts.push_back(Utilities::trim(path.substr(start, slash - start)));
    start = slash + 1;
  }
  parts.push_back(Utilities::trim(path.substr(start)));
  return parts;
}

/** The value of the entry @p path of @p prm; false if it is not declared. */
bool get_value(const ParameterHandler &prm, const std::string &path, std::string &value)
{
  auto parts = path_parts(path);
  const std::string entry = parts.back();
  parts.pop_back();
  try
  {
    value = prm.get(parts, entry);
    return true;
  }
  catch (...)
  {
    return false;
  }
}

/** Apply `path=value` to @p prm and undo it; a one-line message after @p where if it
 * fails. */
void try_override(ParameterHandler &prm,
                  const std::string &path,
                  const std::string &value,
                  const std::string &where)
{
  std::string original;
  const bool declared = get_value(prm, path, original);
  try
  {
    apply_override(prm, path + "=" + value);
  }
  catch (const std::exception &e)
  {
    std::string message = one_line_message(e);
    const auto see = message.find(" (see hati --print-parameters)");
    if (message.rfind("--set ", 0) == 0)
      message = message.substr(6, see == std::string::npos ? std::string::npos : see - 6);
    AssertThrow(false, ExcMessage(where + ": " + message));
  }
  if (declared)
    apply_override(prm, path + "=" + original);
}

/** Whether the entry @p path names an input file. */
bool names_input_file(const std::string &path)
{
  return path == "Loading/Accelerogram X" || path == "Loading/Accelerogram Y" ||
         path == "Loading/Accelerogram Z" || path == "Model/Frame/Mesh file";
}
} // namespace

void check_suite_overrides(ParameterHandler &prm, const SuiteParameters &suite)
{
  for (const auto &record : suite.records)
    for (unsigned int d = 0; d < 3; ++d)
    {
      const std::string entry = std::string("Loading/Accelerogram ") + "XYZ"[d];
      const std::string where = "Suite/Records: record '" + record.name + "'";
      try_override(prm, entry, record.files[d], where);
      // a generated record's files are written once the suite is checked
      if (!record.files[d].empty() && !record.generated)
        require_regular_file(record.files[d], where, "accelerogram");
    }
  for (const auto &v : suite.variations)
    for (const auto &value : v.values)
    {
      const std::string where = "Suite/Variations: '" + v.path + "=" + value + "'";
      try_override(prm, v.path, value, "Suite/Variations");
      if (names_input_file(v.path) && !Utilities::trim(value).empty())
        require_regular_file(Utilities::trim(value), where, "input");
    }
}

std::string input_digests(const ParameterHandler &prm)
{
  std::string text;
  for (const std::string path : {"Loading/Accelerogram X",
                                 "Loading/Accelerogram Y",
                                 "Loading/Accelerogram Z",
                                 "Model/Frame/Mesh file"})
  {
    std::string file;
    if (!get_value(prm, path, file) || Utilities::trim(file).empty())
      continue;
    file = Utilities::trim(file);
    text += path + " = " + file + ": " + file_digest(file) + "\n";
  }
  return text;
}
} // namespace hati

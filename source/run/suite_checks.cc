#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

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
    // FNV-1a, 64 bits: enough to see that a file changed
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    std::uint64_t size = 0;
    std::ifstream in(file, std::ios::binary);
    char block[1 << 16];
    while (in && (in.read(block, sizeof(block)), in.gcount() > 0))
    {
      for (std::streamsize i = 0; i < in.gcount(); ++i)
      {
        hash ^= static_cast<unsigned char>(block[i]);
        hash *= 0x100000001b3ULL;
      }
      size += in.gcount();
    }
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(hash));
    text += path + " = " + file + ": " +
            (in.bad() || !std::ifstream(file) ? std::string("missing")
                                              : "fnv1a64 " + std::string(hex) + ", " +
                                                    std::to_string(size) + " bytes") +
            "\n";
  }
  return text;
}
} // namespace hati

#include <hati/output/member_result.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <fstream>
#include <sstream>

namespace hati
{
namespace
{
using Json = nlohmann::ordered_json;

/** Append `<name>.<key>` for each object of @p group that has a number @p key. */
void add_per_name(const Json &group,
                  const std::string &key,
                  const std::string &column,
                  std::vector<std::pair<std::string, double>> &values)
{
  if (!group.is_object())
    return;
  for (const auto &[name, entry] : group.items())
    if (entry.is_object() && entry.contains(key) && entry[key].is_number())
      values.emplace_back(name + "." + column, entry[key].get<double>());
}
} // namespace

std::string read_member_summary(const std::string &folder, MemberResult &result)
{
  std::ifstream in(folder + "/summary.json");
  if (!in)
    return "";
  const Json summary = Json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.is_object() || !summary.contains("status") ||
      !summary["status"].is_string())
    return "";
  const std::string status = summary["status"].get<std::string>();
  if (status == "derailed" && summary.contains("derailment") &&
      summary["derailment"].is_object())
  {
    // which wheel and when (D2), the suite's record of the member
    const Json &d = summary["derailment"];
    std::ostringstream s;
    s << d.value("wheel", std::string()) << " at t = " << d.value("time", 0.) << " s";
    result.error = s.str();
  }
  if (status != "completed")
    return status;
  auto &values = result.values;
  values.clear();
  if (summary.contains("wheels"))
  {
    add_per_name(summary["wheels"], "peak_mean_force", "peak_mean_force", values);
    add_per_name(summary["wheels"], "slip_distance", "slip_distance", values);
    add_per_name(summary["wheels"], "uplift_time", "uplift_time", values);
    add_per_name(summary["wheels"], "max_lateral_offset", "max_lateral_offset", values);
    for (const auto &[name, entry] : summary["wheels"].items())
      if (entry.is_object() && entry.contains("runway_load"))
        for (const char *key :
             {"vertical_max", "vertical_min", "lateral_max", "longitudinal_max"})
          if (entry["runway_load"].contains(key) && entry["runway_load"][key].is_number())
            values.emplace_back(name + ".runway_load." + key,
                                entry["runway_load"][key].get<double>());
  }
  // the runway springs' forces (Runway = springs)
  if (summary.contains("runway_reaction") && summary["runway_reaction"].is_object())
    for (const auto &[wheel, directions] : summary["runway_reaction"].items())
      for (const char *direction : {"vertical", "lateral", "longitudinal"})
        if (directions.is_object() && directions.contains(direction))
          for (const char *extreme : {"max", "min"})
            if (directions[direction].contains(extreme) &&
                directions[direction][extreme].is_number())
              values.emplace_back(wheel + ".runway_reaction." + direction + "_" + extreme,
                                  directions[direction][extreme].get<double>());
  // every one-sided contact's uplift (the wheels' among them)
  if (summary.contains("contacts"))
    add_per_name(summary["contacts"], "max_uplift", "max_uplift", values);
  if (summary.contains("section_force_envelope"))
    for (const auto &[force, entry] : summary["section_force_envelope"].items())
      if (entry.is_object() && entry.contains("max_abs") && entry["max_abs"].is_number())
        values.emplace_back("section_force." + force, entry["max_abs"].get<double>());
  if (summary.contains("max_absolute_acceleration"))
    add_per_name(summary["max_absolute_acceleration"],
                 "value",
                 "max_absolute_acceleration",
                 values);
  if (summary.contains("beam_stresses") && summary["beam_stresses"].is_object())
    for (const auto &[name, entry] : summary["beam_stresses"].items())
      for (const char *key : {"max_normal_stress", "max_von_mises"})
        if (entry.is_object() && entry.contains(key) && entry[key].is_object() &&
            entry[key].contains("value") && entry[key]["value"].is_number())
          values.emplace_back(name + "." + key, entry[key]["value"].get<double>());
  if (summary.contains("solids") && summary["solids"].is_object())
    for (const auto &[name, entry] : summary["solids"].items())
      if (entry.is_object() && entry.contains("max_von_mises") &&
          entry["max_von_mises"].is_object() &&
          entry["max_von_mises"].contains("value") &&
          entry["max_von_mises"]["value"].is_number())
        values.emplace_back(name + ".max_von_mises",
                            entry["max_von_mises"]["value"].get<double>());
  if (summary.contains("rope_tension"))
    add_per_name(summary["rope_tension"], "max", "max_tension", values);
  if (summary.contains("wall_time") && summary["wall_time"].is_number())
    result.wall_time = summary["wall_time"].get<double>();
  return status;
}

bool member_outputs_whole(const std::string &folder)
{
  std::ifstream in(folder + "/summary.json");
  if (!in)
    return false;
  const Json summary = Json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.is_object() ||
      summary.value("status", "") != "completed")
    return false;
  for (const char *key : {"model", "n_dofs", "end_time", "n_steps", "wall_time"})
    if (!summary.contains(key))
      return false;
  if (!summary["end_time"].is_number() || !summary["wall_time"].is_number())
    return false;
  std::ifstream manifest(folder + "/.hati-manifest");
  bool history = false;
  for (std::string name; std::getline(manifest, name);)
  {
    if (name.empty() || name[0] == '.' || name.find('/') != std::string::npos)
      continue; // the temporaries .<name>.tmp (replaced, so gone)
    struct stat status;
    if (::lstat((folder + "/" + name).c_str(), &status) != 0 || !S_ISREG(status.st_mode))
      return false;
    history = history || name == "history.csv";
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0 &&
        status.st_size > 0)
    {
      std::ifstream csv(folder + "/" + name, std::ios::binary);
      char last = 0;
      if (!csv.seekg(-1, std::ios::end) || !csv.get(last) || last != '\n')
        return false;
    }
  }
  return history;
}
} // namespace hati

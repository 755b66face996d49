#include <hati/base/version.h>
#include <hati/output/run_directory.h>
#include <hati/output/summary.h>

#include <nlohmann/json.hpp>

#include <cmath>

namespace hati
{
namespace
{
nlohmann::ordered_json json_value(const SummaryValue &value)
{
  switch (value.kind())
  {
  case SummaryValue::Kind::number:
    return std::isfinite(value.number()) ? nlohmann::ordered_json(value.number())
                                         : nlohmann::ordered_json(nullptr);
  case SummaryValue::Kind::integer:
    return value.integer();
  case SummaryValue::Kind::string:
    return value.text();
  case SummaryValue::Kind::boolean:
    return value.integer() != 0;
  case SummaryValue::Kind::list:
  {
    auto list = nlohmann::ordered_json::array();
    for (const auto &item : value.items())
      list.push_back(json_value(item));
    return list;
  }
  case SummaryValue::Kind::object:
  {
    auto object = nlohmann::ordered_json::object();
    for (const auto &[key, member] : value.members())
      object[key] = json_value(member);
    return object;
  }
  case SummaryValue::Kind::null:
    break;
  }
  return nullptr;
}

std::string dump(const nlohmann::ordered_json &json)
{
  // one line; invalid UTF-8 (e.g. in a file name) replaced instead of throwing
  return json.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

/** `{"key": value, ...}` with one top-level entry per line. */
std::string document(const SummaryEntries &entries)
{
  std::string out = "{\n";
  for (unsigned int i = 0; i < entries.size(); ++i)
    out += "  " + dump(entries[i].first) + ": " + to_json(entries[i].second) +
           (i + 1 < entries.size() ? ",\n" : "\n");
  return out + "}\n";
}
} // namespace

std::string to_json(const SummaryValue &value) { return dump(json_value(value)); }

namespace
{
/** The `warnings` entry: a list of strings, empty if none. */
SummaryValue warning_list(const std::vector<std::string> &warnings)
{
  SummaryValue list = SummaryValue::list();
  for (const auto &w : warnings)
    list.push_back(w);
  return list;
}
} // namespace

void write_summary(const std::string &filename,
                   const SummaryEntries &entries,
                   const std::vector<std::string> &warnings,
                   const std::string &status)
{
  auto all = entries;
  all.emplace_back("git_commit", hati_git_commit());
  all.emplace_back("warnings", warning_list(warnings));
  if (stop_requested() || !status.empty())
  {
    all.emplace_back("status", status.empty() ? "interrupted" : status);
    for (const auto &[key, value] : entries)
      if (key == "end_time")
        all.emplace_back("time_reached", value);
  }
  else
    all.emplace_back("status", "completed");
  write_file_atomically(filename, document(all));
}

std::string failed_summary(const std::string &message,
                           const std::vector<std::string> &warnings)
{
  return document({{"git_commit", hati_git_commit()},
                   {"warnings", warning_list(warnings)},
                   {"status", "failed"},
                   {"message", message}});
}
} // namespace hati

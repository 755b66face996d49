#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hati/model/frame_items.h>

#include <cmath>
#include <cstdlib>

namespace hati
{
using namespace dealii;

std::vector<FrameItem> parse_frame_items(const std::string &text,
                                         const std::string &entry)
{
  std::vector<FrameItem> items;
  for (const std::string &raw : Utilities::split_string_list(text, ';'))
  {
    const std::string item = Utilities::trim(raw);
    if (item.empty())
      continue;
    const auto colon = item.find(':');
    AssertThrow(colon != std::string::npos && colon > 0,
                ExcMessage("Model/Frame/" + entry + ": item '" + item +
                           "' is not of the form 'name: values'"));
    FrameItem it;
    it.name = Utilities::trim(item.substr(0, colon));
    for (const std::string &v : Utilities::split_string_list(item.substr(colon + 1), ','))
      it.values.push_back(Utilities::trim(v));
    if (it.values.size() == 1 && it.values[0].empty())
      it.values.clear();
    items.push_back(it);
  }
  return items;
}

double frame_item_number(const std::string &value,
                         const std::string &entry,
                         const FrameItem &item)
{
  char *end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  AssertThrow(!value.empty() && end != nullptr && *end == '\0' && std::isfinite(x),
              ExcMessage("Model/Frame/" + entry + ": item '" + item.name + "': '" +
                         value + "' is not a number"));
  return x;
}

void expect_frame_item_values(const FrameItem &item,
                              const std::string &entry,
                              const std::vector<unsigned int> &counts,
                              const std::string &expected)
{
  for (const unsigned int c : counts)
    if (item.values.size() == c)
      return;
  AssertThrow(false,
              ExcMessage("Model/Frame/" + entry + ": item '" + item.name + "' has " +
                         std::to_string(item.values.size()) + " values, expected " +
                         expected));
}
} // namespace hati

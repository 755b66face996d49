#ifndef hati_model_frame_items_h
#define hati_model_frame_items_h

#include <string>
#include <vector>

namespace hati
{
/** One item "name: v1, v2, ..." of a `Model/Frame` list entry. */
struct FrameItem
{
  std::string name;
  std::vector<std::string> values;
};

/**
 * Split `name: v, v; name: v, v` into items; @p entry names the parameter
 * (after `Model/Frame/`) in errors.
 */
std::vector<FrameItem> parse_frame_items(const std::string &text,
                                         const std::string &entry);

/**
 * @p value as a finite number; a one-line error naming `Model/Frame/<entry>`
 * and @p item otherwise.
 */
double frame_item_number(const std::string &value,
                         const std::string &entry,
                         const FrameItem &item);

/**
 * Throw a one-line error unless @p item has one of the value @p counts
 * ("... has N values, expected <expected>").
 */
void expect_frame_item_values(const FrameItem &item,
                              const std::string &entry,
                              const std::vector<unsigned int> &counts,
                              const std::string &expected);
} // namespace hati

#endif

#ifndef hati_base_summary_value_h
#define hati_base_summary_value_h

#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * One value of `summary.json`, built by the models and analyses without a
 * JSON library: null, a number (written as null if not finite), an
 * integer, a string (any characters: output/ escapes them), a list, or an
 * object whose keys keep the order they were added in. output/summary.h
 * turns it into JSON; nothing below output/ formats JSON text.
 */
class SummaryValue
{
public:
  enum class Kind
  {
    null,
    number,
    integer,
    string,
    list,
    object,
    boolean
  };

  /** null */
  SummaryValue() = default;
  SummaryValue(const double x) : kind_(Kind::number), number_(x) {}
  SummaryValue(const int x) : kind_(Kind::integer), integer_(x) {}
  SummaryValue(const unsigned int x) : kind_(Kind::integer), integer_(x) {}
  SummaryValue(const long x) : kind_(Kind::integer), integer_(x) {}
  SummaryValue(const unsigned long x) : kind_(Kind::integer), integer_(x) {}
  SummaryValue(const long long x) : kind_(Kind::integer), integer_(x) {}
  SummaryValue(const unsigned long long x)
      : kind_(Kind::integer), integer_(static_cast<long long>(x))
  {
  }
  SummaryValue(std::string x) : kind_(Kind::string), text_(std::move(x)) {}
  SummaryValue(const char *x) : kind_(Kind::string), text_(x) {}

  /** true or false (a named constructor: a bool argument elsewhere stays an integer). */
  static SummaryValue boolean(const bool x)
  {
    SummaryValue v;
    v.kind_ = Kind::boolean;
    v.integer_ = x ? 1 : 0;
    return v;
  }
  /** An empty object, to fill with set(). */
  static SummaryValue object()
  {
    SummaryValue v;
    v.kind_ = Kind::object;
    return v;
  }

  /** An empty list, to fill with push_back(). */
  static SummaryValue list()
  {
    SummaryValue v;
    v.kind_ = Kind::list;
    return v;
  }

  /** Add the member @p key of an object (after the ones set before). */
  SummaryValue &set(const std::string &key, SummaryValue value)
  {
    kind_ = Kind::object;
    members_.emplace_back(key, std::move(value));
    return *this;
  }

  /** Append @p value to a list. */
  SummaryValue &push_back(SummaryValue value)
  {
    kind_ = Kind::list;
    items_.push_back(std::move(value));
    return *this;
  }

  Kind kind() const { return kind_; }
  double number() const { return number_; }
  long long integer() const { return integer_; }
  const std::string &text() const { return text_; }
  const std::vector<SummaryValue> &items() const { return items_; }
  const std::vector<std::pair<std::string, SummaryValue>> &members() const
  {
    return members_;
  }

private:
  Kind kind_ = Kind::null;
  double number_ = 0.;
  long long integer_ = 0;
  std::string text_;
  std::vector<SummaryValue> items_;
  std::vector<std::pair<std::string, SummaryValue>> members_;
};

/** Top-level entries of `summary.json`, in their order in the file. */
using SummaryEntries = std::vector<std::pair<std::string, SummaryValue>>;
} // namespace hati

#endif

#ifndef hati_base_registry_h
#define hati_base_registry_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
/**
 * Named implementations of one family (models, analyses, time integration
 * methods), in the spirit of ASPECT's plugin registration: each entry has
 * its name (the value of the selecting parameter), one line of
 * documentation, the declaration of its own parameters and its factory.
 * Adding an implementation is a new file and one registration line in the
 * family's list (e.g. source/model/model_registry.cc); an unknown name is
 * refused with the list of registered names.
 *
 * @tparam Factory the callable that makes (or runs) an implementation.
 */
template <class Factory> class Registry
{
public:
  struct Entry
  {
    /** Value of the selecting parameter, e.g. `bridge crane`. */
    std::string name;
    /** What it is, for the documentation of the selecting parameter. */
    std::string documentation;
    /** Declares the implementation's own parameters (may be empty). */
    std::function<void(dealii::ParameterHandler &)> declare;
    Factory create;
  };

  /**
   * @p parameter: the selecting parameter (`Model/Type`), for messages;
   * @p entries: the implementations, in the order of the documentation.
   */
  explicit Registry(std::string parameter, std::vector<Entry> entries = {})
      : parameter(std::move(parameter))
  {
    for (Entry &e : entries)
      add(std::move(e));
  }

  /** Register @p entry; a second entry of the same name is a programming error. */
  void add(Entry entry)
  {
    for (const Entry &e : list)
      AssertThrow(
          e.name != entry.name,
          dealii::ExcMessage(parameter + ": '" + entry.name + "' is registered twice"));
    list.push_back(std::move(entry));
  }

  /** The entry called @p name; throws naming the registered names if none is. */
  const Entry &get(const std::string &name) const
  {
    for (const Entry &e : list)
      if (e.name == name)
        return e;
    AssertThrow(false,
                dealii::ExcMessage(parameter + ": unknown '" + name +
                                   "'; registered: " + join(", ", ", ")));
    return list.front();
  }

  const std::vector<Entry> &entries() const { return list; }

  /** `a|b|c`, the values of a Patterns::Selection, in registration order. */
  std::string selection() const { return join("|", "|"); }

  /**
   * The registered names, or with @p documented their documentation texts,
   * in registration order, joined by @p separator, the last two by
   * @p last_separator.
   */
  std::string join(const std::string &separator,
                   const std::string &last_separator,
                   const bool documented = false) const
  {
    std::string r;
    for (unsigned int i = 0; i < list.size(); ++i)
    {
      if (i > 0)
        r += (i + 1 == list.size() ? last_separator : separator);
      r += documented ? list[i].documentation : list[i].name;
    }
    return r;
  }

  /** Call every entry's parameter declaration. */
  void declare_parameters(dealii::ParameterHandler &prm) const
  {
    for (const Entry &e : list)
      if (e.declare)
        e.declare(prm);
  }

private:
  std::string parameter;
  std::vector<Entry> list;
};
} // namespace hati

#endif

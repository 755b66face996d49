#ifndef hati_base_names_h
#define hati_base_names_h

#include <deal.II/base/exceptions.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace hati
{
/**
 * @name The names users give (issue #19, finding 4)
 *
 * Contacts, nodes, members, sections, materials and monitors are named with
 * letters, digits, `_`, `-` and `.` only, so that a name goes unquoted into a
 * CSV field, a JSON string and `parameters.prm` and reads back the same (no
 * separator, comment sign, quote, space or control character). Gmsh nodes
 * without a physical name are named `@<tag>` (digits after the `@`); a node
 * name must not read as a number, so that the second value of a node-to-node
 * contact (`Model/Frame/Contacts`) is never taken for a normal component.
 * @{
 */

/** Whether @p c may appear in a name: a letter, a digit, `_`, `-` or `.` (ASCII). */
inline bool is_name_character(const char c)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
         c == '_' || c == '-' || c == '.';
}

/**
 * @p text fit for a one-line message: a newline as `\n`, a tab as `\t`, other
 * control characters and bytes outside ASCII as `\xHH`.
 */
inline std::string printable(const std::string &text)
{
  std::string r;
  for (const char c : text)
  {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n')
      r += "\\n";
    else if (c == '\t')
      r += "\\t";
    else if (byte < 0x20 || byte >= 0x7f)
    {
      char hex[8];
      std::snprintf(hex, sizeof(hex), "\\x%02X", byte);
      r += hex;
    }
    else
      r += c;
  }
  return r;
}

/** Whether std::strtod reads all of @p name as a number (`1`, `-2.5e3`, `inf`, `0x1f`).
 */
inline bool reads_as_number(const std::string &name)
{
  char *end = nullptr;
  std::strtod(name.c_str(), &end);
  return !name.empty() && end != nullptr && *end == '\0';
}

/** What a name of check_name() is. */
enum class NameKind
{
  /** contacts, members, sections, materials */
  plain,
  /** nodes: `@<tag>` allowed, a number refused */
  node
};

/**
 * Throw a one-line message `<entry>: the <what> name '<name>' ...` if @p name
 * is empty, has a character other than those of is_name_character() or, for
 * @p kind = NameKind::node, reads as a number (reads_as_number()); a node
 * name `@<digits>` (the unnamed nodes of a Gmsh file) is accepted. @p entry
 * names the parameter (e.g. `Model/Frame/Contacts`), @p what the kind of
 * item (e.g. `contact`).
 */
inline void check_name(const std::string &name,
                       const std::string &entry,
                       const std::string &what,
                       const NameKind kind = NameKind::plain)
{
  const std::string head = entry + ": the " + what + " name '" + printable(name) + "' ";
  const std::string rule =
      "; a name may have only letters, digits, '_', '-' and '.' (it goes unquoted "
      "into the CSV files, summary.json and parameters.prm)";
  AssertThrow(!name.empty(),
              dealii::ExcMessage(entry + ": a " + what + " name is empty"));
  const bool gmsh_tag = kind == NameKind::node && name.size() > 1 && name[0] == '@' &&
                        name.find_first_not_of("0123456789", 1) == std::string::npos;
  if (gmsh_tag)
    return;
  for (const char c : name)
    AssertThrow(is_name_character(c),
                dealii::ExcMessage(head + "has the character '" +
                                   printable(std::string(1, c)) + "'" + rule));
  AssertThrow(kind != NameKind::node || !reads_as_number(name),
              dealii::ExcMessage(head +
                                 "reads as a number; a node name must not (in "
                                 "Model/Frame/Contacts the value after the node would be "
                                 "taken for the normal's nx, not for a node)"));
}
/** @} */
} // namespace hati

#endif

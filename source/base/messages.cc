#include <deal.II/base/exceptions.h>

#include <hati/base/messages.h>

#include <cctype>
#include <new>
#include <sstream>

namespace hati
{
using namespace dealii;

std::string one_line_message(const std::exception &e)
{
  std::string text;
  if (const auto *d = dynamic_cast<const ExceptionBase *>(&e))
  {
    std::ostringstream s;
    d->print_info(s);
    text = s.str();
  }
  else if (dynamic_cast<const std::bad_alloc *>(&e) != nullptr)
    text = "out of memory (std::bad_alloc): the run needs more memory than this "
           "machine (or its memory limit) gives; reduce the model's size";
  else
    text = e.what();
  std::string r;
  bool space = false;
  for (const char c : text)
  {
    if (std::isspace(static_cast<unsigned char>(c)))
      space = !r.empty();
    else
    {
      if (space)
        r += ' ';
      r += c;
      space = false;
    }
  }
  const std::string prefix = "Additional information: ";
  if (r.compare(0, prefix.size(), prefix) == 0)
    r = r.substr(prefix.size());
  return r;
}
} // namespace hati

#include <deal.II/base/exceptions.h>

#include <hati/output/csv_file.h>
#include <hati/output/run_directory.h>

#include <cerrno>
#include <fcntl.h>
#include <locale>
#include <unistd.h>

namespace hati
{
using namespace dealii;

namespace
{
/** A `num_put` facet writing floating-point numbers with append_number(). */
class ShortestNumPut : public std::num_put<char>
{
protected:
  iter_type do_put(iter_type out, std::ios_base &, char, double x) const override
  {
    return write(out, x);
  }
  iter_type do_put(iter_type out, std::ios_base &, char, long double x) const override
  {
    return write(out, static_cast<double>(x));
  }

private:
  static iter_type write(iter_type out, const double x)
  {
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof(buffer), x);
    for (const char *c = buffer; c != r.ptr; ++c)
      *out++ = *c;
    return out;
  }
};
} // namespace

std::string shortest_number(const double x)
{
  std::string s;
  append_number(s, x);
  return s;
}

void use_shortest_numbers(std::ostream &out)
{
  out.imbue(std::locale(out.getloc(), new ShortestNumPut));
}

CsvFile::~CsvFile()
{
  if (fd >= 0)
    ::close(fd); // errors are reported by an explicit flush()/close()
}

void CsvFile::open(const std::string &name)
{
  filename = name;
  fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  AssertThrow(fd >= 0,
              ExcMessage("cannot open the output file " + name +
                         " for writing: " + system_error_text(errno)));
  buffer.reserve(1 << 16);
}

void CsvFile::flush()
{
  if (fd < 0 || buffer.empty())
    return;
  const char *p = buffer.data();
  std::size_t left = buffer.size();
  while (left > 0)
  {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR)
      continue;
    AssertThrow(n > 0,
                ExcMessage("cannot write the output file " + filename + ": " +
                           system_error_text(n < 0 ? errno : ENOSPC)));
    p += n;
    left -= n;
  }
  buffer.clear();
}

void CsvFile::close()
{
  if (fd < 0)
    return;
  flush();
  const int result = ::close(fd);
  fd = -1;
  AssertThrow(result == 0,
              ExcMessage("cannot close the output file " + filename + ": " +
                         system_error_text(errno)));
}
} // namespace hati

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

std::string csv_field(const std::string &text)
{
  if (text.find_first_of(",\"\n\r") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (const char c : text)
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

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

CsvFile::~CsvFile() = default; // errors are reported by an explicit flush()/close()

void CsvFile::open(const std::string &filename) { open(create_output_file(filename)); }

void CsvFile::open(OutputFile f)
{
  file = std::move(f);
  buffer.clear();
  buffer.reserve(1 << 16);
}

void CsvFile::flush()
{
  if (file.fd < 0 || buffer.empty())
    return;
  const int error = append_whole_rows(file.fd, buffer.data(), buffer.size());
  buffer.clear();
  if (error != 0)
  {
    // the file ends on its last whole row; nothing more is written to it
    const std::string path = file.path;
    file = OutputFile();
    AssertThrow(false,
                ExcMessage("cannot write the output file " + path + ": " +
                           system_error_text(error)));
  }
}

void CsvFile::close()
{
  if (file.fd < 0)
    return;
  flush();
  const std::string path = file.path;
  const int result = ::close(file.release());
  AssertThrow(result == 0,
              ExcMessage("cannot close the output file " + path + ": " +
                         system_error_text(errno)));
}
} // namespace hati

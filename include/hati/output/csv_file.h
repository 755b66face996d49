#ifndef hati_output_csv_file_h
#define hati_output_csv_file_h

#include <hati/output/output_file.h>

#include <charconv>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

namespace hati
{
/**
 * Append @p x to @p out as the shortest text that reads back to the same
 * double (`std::to_chars`, e.g. `0.1`, `1e-06`, `6.000000000000001e-05`):
 * full precision, no trailing digits.
 */
inline void append_number(std::string &out, const double x)
{
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), x);
  out.append(buffer, r.ptr);
}

/** The shortest round-trip text of @p x (append_number()). */
std::string shortest_number(const double x);

/** @p text as a CSV field: quoted (quotes doubled) if it has a comma, quote or newline.
 */
std::string csv_field(const std::string &text);

/**
 * Make @p out write doubles and floats as append_number() does (a `num_put`
 * facet), for code that writes rows to a `std::ostream`.
 */
void use_shortest_numbers(std::ostream &out);

/**
 * A CSV file written in whole rows: the rows are formatted into a buffer
 * (`std::to_chars`, shortest round-trip) and written to the file only by
 * flush(), as one append of complete lines (append_whole_rows(): by a child
 * process outside the run's process group that finishes it even when the
 * run or its group is killed, and cut back to the last whole row if it
 * fails), so the file ends on a complete line at every instant, even after
 * a SIGKILL of the run or its process group or on a full disk. flush() and
 * close() check every write and throw a one-line message naming the file
 * and the system error (e.g. `No space left on device`); after a failed
 * write nothing more is written.
 */
class CsvFile
{
public:
  CsvFile() = default;
  ~CsvFile();
  CsvFile(const CsvFile &) = delete;
  CsvFile &operator=(const CsvFile &) = delete;

  /**
   * Create (or truncate) @p filename, not through a symbolic link
   * (create_output_file()); throws naming it if that fails.
   */
  void open(const std::string &filename);
  /** Write into @p file (e.g. from RunDirectory::open()). */
  void open(OutputFile file);
  bool is_open() const { return file.fd >= 0; }
  const std::string &name() const { return file.path; }

  CsvFile &operator<<(const double x)
  {
    append_number(buffer, x);
    return *this;
  }
  CsvFile &operator<<(const char c)
  {
    buffer += c;
    return *this;
  }
  CsvFile &operator<<(const std::string_view s)
  {
    buffer.append(s);
    return *this;
  }
  CsvFile &operator<<(const char *s)
  {
    buffer.append(s);
    return *this;
  }
  CsvFile &operator<<(const std::string &s)
  {
    buffer.append(s);
    return *this;
  }
  template <class Integer, class = std::enable_if_t<std::is_integral_v<Integer>>>
  CsvFile &operator<<(const Integer i)
  {
    char text[24];
    const auto r = std::to_chars(text, text + sizeof(text), i);
    buffer.append(text, r.ptr);
    return *this;
  }

  /** Bytes formatted but not yet written. */
  std::size_t buffered() const { return buffer.size(); }
  /** Write the buffered rows (call between rows only). */
  void flush();
  /** flush() and close, checking both. */
  void close();

private:
  OutputFile file;
  std::string buffer;
};
} // namespace hati

#endif

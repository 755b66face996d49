#include <deal.II/base/exceptions.h>

#include <hati/base/input_file.h>
#include <hati/loading/accelerogram.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <utility>

namespace hati
{
using dealii::ExcMessage;

namespace
{
/** Shortest and longest AT2 sample interval DT (s). */
constexpr double min_dt = 1e-6, max_dt = 1.;
/** Largest number of samples of a record (-): 8e8 bytes per vector. */
constexpr long max_samples = 100000000;

/** "<entry>: " or nothing. */
std::string prefix(const std::string &entry) { return entry.empty() ? "" : entry + ": "; }

bool is_at2(const std::string &file)
{
  std::string ext = file.size() >= 4 ? file.substr(file.size() - 4) : "";
  std::transform(ext.begin(),
                 ext.end(),
                 ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".at2";
}

/** All numbers of a line; false if a token is not a number. */
bool numbers(const std::string &line, std::vector<double> &v)
{
  std::istringstream s(line);
  std::string token;
  v.clear();
  while (s >> token)
  {
    char *end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || !std::isfinite(x))
      return false;
    v.push_back(x);
  }
  return true;
}
} // namespace

namespace
{
/** Where an error is: "<entry>: accelerogram file '<file>', line <n>: ". */
class Position
{
public:
  Position(const std::string &file, const std::string &entry) : file(file), entry(entry)
  {
  }

  std::string at(const unsigned int line) const
  {
    return prefix(entry) + "accelerogram file '" + file + "', line " +
           std::to_string(line) + ": ";
  }

  std::string whole() const { return prefix(entry) + "accelerogram file '" + file + "'"; }

private:
  const std::string file, entry;
};

/**
 * NPTS and DT (s) of the fourth line @p line of an AT2 header, both in
 * their bounds (0 < NPTS <= max_samples, min_dt <= DT <= max_dt).
 */
std::pair<long, double> at2_header(const std::string &line, const Position &where)
{
  std::string upper = line;
  std::transform(upper.begin(),
                 upper.end(),
                 upper.begin(),
                 [](unsigned char c) { return std::toupper(c); });
  long npts = -1;
  double dt = -1.;
  const auto p_n = upper.find("NPTS="), p_d = upper.find("DT=");
  if (p_n != std::string::npos && p_d != std::string::npos)
  {
    npts = std::strtol(upper.c_str() + p_n + 5, nullptr, 10);
    dt = std::strtod(upper.c_str() + p_d + 3, nullptr);
  }
  else if (upper.find("NPTS") != std::string::npos)
  {
    std::istringstream s(upper);
    s >> npts >> dt;
    if (!s)
      npts = -1;
  }
  AssertThrow(npts > 0 && dt > 0. && std::isfinite(dt),
              ExcMessage(where.at(4) +
                         "expected 'NPTS= n, DT= dt SEC' or 'n dt NPTS, DT' with n > 0 "
                         "and finite dt > 0, got '" +
                         line + "'"));
  if (!(npts <= max_samples && dt >= min_dt && dt <= max_dt))
  {
    std::ostringstream s;
    s << where.at(4) << "NPTS = " << npts << ", DT = " << dt << " s: expected at most "
      << double(max_samples) << " samples and " << min_dt << " s <= DT <= " << max_dt
      << " s";
    AssertThrow(false, ExcMessage(s.str()));
  }
  return {npts, dt};
}
} // namespace

Accelerogram Accelerogram::read(const std::string &filename,
                                const std::string &units,
                                const double scale,
                                const std::string &entry)
{
  // stat first: opening a FIFO would block, a device would never end
  require_regular_file(filename, entry, "accelerogram");
  const Position where(filename, entry);
  std::ifstream in(filename);
  AssertThrow(
      in,
      ExcMessage(prefix(entry) + "cannot open the accelerogram file '" + filename + "'"));
  Accelerogram g;
  std::string line;
  unsigned int number = 0;
  std::vector<double> v;
  if (is_at2(filename))
  {
    // four header lines; the fourth holds NPTS and DT
    for (unsigned int i = 0; i < 4; ++i)
    {
      AssertThrow(std::getline(in, line),
                  ExcMessage(where.at(number + 1) +
                             "the file ends inside the 4-line AT2 header"));
      ++number;
    }
    const auto [npts, dt] = at2_header(line, where);
    while (std::getline(in, line))
    {
      ++number;
      AssertThrow(numbers(line, v),
                  ExcMessage(where.at(number) + "not a list of numbers: '" + line + "'"));
      AssertThrow(long(g.a.size() + v.size()) <= npts,
                  ExcMessage(where.at(number) + "the header announces NPTS = " +
                             std::to_string(npts) + " values, the file has more"));
      for (const double x : v)
      {
        g.t.push_back(g.a.size() * dt);
        g.a.push_back(x * standard_gravity * scale);
      }
    }
    AssertThrow(long(g.a.size()) == npts,
                ExcMessage(where.whole() +
                           ": the header announces NPTS = " + std::to_string(npts) +
                           " values, the file has " + std::to_string(g.a.size())));
  }
  else
  {
    double factor = 0.;
    if (units == "g")
      factor = standard_gravity;
    else if (units == "m/s^2")
      factor = 1.;
    else if (units == "cm/s^2")
      factor = 0.01;
    AssertThrow(
        factor > 0.,
        ExcMessage("accelerogram units must be g, m/s^2 or cm/s^2, got '" + units + "'"));
    while (std::getline(in, line))
    {
      ++number;
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#')
        continue;
      AssertThrow(numbers(line, v) && v.size() == 2,
                  ExcMessage(where.at(number) +
                             "expected two numbers 'time value', got '" + line + "'"));
      AssertThrow(g.t.empty() || v[0] > g.t.back(),
                  ExcMessage(where.at(number) + "times must increase"));
      AssertThrow(long(g.a.size()) < max_samples,
                  ExcMessage(where.at(number) + "more than " +
                             std::to_string(max_samples) + " samples"));
      g.t.push_back(v[0]);
      g.a.push_back(v[1] * factor * scale);
    }
  }
  AssertThrow(g.a.size() >= 2, ExcMessage(where.whole() + " has fewer than two samples"));
  return g;
}

double Accelerogram::operator()(const double time) const
{
  if (time < t.front() || time > t.back())
    return 0.;
  const auto it = std::upper_bound(t.begin(), t.end(), time);
  if (it == t.end())
    return a.back();
  const std::size_t i = it - t.begin();
  const double w = (time - t[i - 1]) / (t[i] - t[i - 1]);
  return (1. - w) * a[i - 1] + w * a[i];
}

std::pair<double, double> Accelerogram::peak() const
{
  std::size_t k = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i]) > std::abs(a[k]))
      k = i;
  return {std::abs(a[k]), t[k]};
}
} // namespace hati

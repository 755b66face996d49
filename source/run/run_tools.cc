#include <hati/run/run_tools.h>

#include <iomanip>
#include <iostream>

namespace hati
{
Progress::Progress(const double interval, const double end_time)
    : interval(interval), end_time(end_time), start(std::chrono::steady_clock::now()),
      last(start)
{
}

bool Progress::due()
{
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last).count() < interval)
    return false;
  last = now;
  return true;
}

void Progress::print(const double t, const unsigned long step) const
{
  const double wall = wall_time();
  const double fraction = t / end_time;
  const auto precision = std::cout.precision();
  std::cout << "  t = " << std::setw(12) << std::setprecision(6) << t << " s ("
            << std::setw(5) << std::fixed << std::setprecision(1) << 100. * fraction
            << " %), step " << step << ", wall " << std::setprecision(1) << wall
            << " s, remaining ~"
            << (fraction > 0. ? wall * (1. - fraction) / fraction : 0.) << " s"
            << std::defaultfloat << std::setprecision(precision) << std::endl;
}

double Progress::wall_time() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
} // namespace hati

#ifndef hati_base_wall_clock_h
#define hati_base_wall_clock_h

#include <chrono>

namespace hati
{
/**
 * Wall time accumulated over many short intervals (the output of each
 * step): `std::chrono::steady_clock` only, without the `getrusage` system
 * calls of a deal.II TimerOutput section (about 2 us per interval, more than
 * writing a history row).
 */
class WallClock
{
public:
  /** Adds the wall time of its lifetime to a WallClock. */
  class Scope
  {
  public:
    explicit Scope(WallClock &clock)
        : clock(clock), start(std::chrono::steady_clock::now())
    {
    }
    ~Scope()
    {
      clock.total += std::chrono::steady_clock::now() - start;
      ++clock.count;
    }

  private:
    WallClock &clock;
    const std::chrono::steady_clock::time_point start;
  };

  /** Accumulated wall time (s). */
  double seconds() const { return std::chrono::duration<double>(total).count(); }
  /** Number of intervals. */
  unsigned long calls() const { return count; }

private:
  std::chrono::steady_clock::duration total{};
  unsigned long count = 0;
};
} // namespace hati

#endif

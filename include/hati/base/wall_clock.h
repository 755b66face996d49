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

/**
 * Wall time of very many very short intervals (a micro step's contact
 * resolution and statistics) estimated from one interval in sample_every:
 * the two clock reads of a WallClock::Scope cost about 50 ns, a few per
 * cent of a micro step of the crane (issue #28). seconds() scales the
 * timed intervals' sum by the number of intervals over the number timed.
 */
class SampledWallClock
{
public:
  /** One interval in this many is timed. */
  static constexpr unsigned long sample_every = 16;

  /** Counts its lifetime and, one in sample_every, times it. */
  class Scope
  {
  public:
    explicit Scope(SampledWallClock &clock)
        : clock(clock), timed(clock.count++ % sample_every == 0)
    {
      if (timed)
        start = std::chrono::steady_clock::now();
    }
    ~Scope()
    {
      if (timed)
      {
        clock.total += std::chrono::steady_clock::now() - start;
        ++clock.n_timed;
      }
    }

  private:
    SampledWallClock &clock;
    const bool timed;
    std::chrono::steady_clock::time_point start;
  };

  /** Estimated wall time of all intervals (s). */
  double seconds() const
  {
    return n_timed == 0 ? 0.
                        : std::chrono::duration<double>(total).count() * double(count) /
                              double(n_timed);
  }
  /** Number of intervals. */
  unsigned long calls() const { return count; }

private:
  std::chrono::steady_clock::duration total{};
  unsigned long count = 0, n_timed = 0;
};
} // namespace hati

#endif

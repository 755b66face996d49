#ifndef hati_loading_design_spectrum_h
#define hati_loading_design_spectrum_h

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * `subsection Design spectrum` (doc/user_guide.md, "Qualifying against a
 * design spectrum"): the target pseudo-acceleration spectrum of the
 * artificial records and of a suite's check (DS1, doc/theory.md 13.1).
 */
struct DesignSpectrumParameters
{
  static void declare_parameters(ParameterHandler &prm);
  /**
   * Read and check them (one-line errors naming the entry): a positive
   * Peak ground acceleration for an EC8 type, a Damping ratio in (0, 1), a
   * Period range `first, last` with 0 < first < last, and with a table the
   * table itself (DesignSpectrum::read_table()).
   */
  void parse_parameters(ParameterHandler &prm);

  /** Whether a target is given (Type is not none). */
  bool active() const { return type != "none"; }

  /** none, `EC8 type 1`, `EC8 type 2` or table. */
  std::string type = "none";
  /** A, B, C, D or E (EN 1998-1 Table 3.1). */
  std::string ground_type = "C";
  /** a_g = gamma_I a_gR on rock (m/s^2). */
  double peak_ground_acceleration = 0.;
  /** The viscous damping ratio of the spectrum (-). */
  double damping_ratio = 0.05;
  /** The vertical component (Z) matched to the EC8 vertical spectrum (3.2.2.3). */
  bool vertical = true;
  std::string table_file;
  /** Shortest and longest period of the matching and of the check (s). */
  std::array<double, 2> period_range{{0.02, 4.}};
  /** The table's periods (s) and pseudo-accelerations (m/s^2) (Type = table). */
  std::vector<double> table_periods, table_values;
  /**
   * Type = table: the files of Y and Z (`Table file Y`, `Table file Z`;
   * floor response spectra differ per axis), and their rows; a file left
   * empty leaves its axis on `Table file`.
   */
  std::array<std::string, 2> table_file_yz;
  /** The rows of `Table file Y` and `Table file Z` (empty: not given). */
  std::array<std::vector<double>, 2> table_periods_yz, table_values_yz;
};

/** The corner values of an EC8 elastic spectrum (EN 1998-1 Tables 3.2-3.4). */
struct Ec8Corners
{
  /** Soil factor S (-; 1 for the vertical spectrum). */
  double S = 1.;
  /** Corner periods T_B, T_C, T_D (s). */
  double TB = 0., TC = 0., TD = 0.;
  /** Plateau amplification (2.5 horizontal, 3.0 vertical). */
  double plateau = 2.5;
  /** The peak ground acceleration of the component over a_g (1; a_vg/a_g vertical). */
  double acceleration_ratio = 1.;
};

/**
 * The corners of EN 1998-1 for @p type (1 or 2) and @p ground_type (A-E):
 * horizontal (Tables 3.2, 3.3) or, with @p vertical, Table 3.4 (a_vg/a_g
 * 0.90 for type 1, 0.45 for type 2).
 */
Ec8Corners
ec8_corners(const unsigned int type, const std::string &ground_type, const bool vertical);

/** The EC8 damping correction eta = sqrt(10 / (5 + 100 xi)) >= 0.55 (3.6). */
double ec8_damping_correction(const double damping_ratio);

/**
 * The target spectrum of DesignSpectrumParameters: S_a(T) (m/s^2) per
 * global axis, the horizontal spectrum for X and Y, for Z the vertical one
 * when Vertical (EC8 types); a table gives every axis `Table file`, but Y
 * and Z their own where `Table file Y` or `Table file Z` is given.
 *
 * EC8 (DS1, doc/theory.md 13.1; EN 1998-1 3.2.2.2, 3.2.2.3 with eta):
 * `a S (1 + T/T_B (p eta - 1))` up to T_B, `a S p eta` up to T_C,
 * `a S p eta T_C / T` up to T_D, `a S p eta T_C T_D / T^2` beyond, with
 * `a` = a_g (a_vg vertically), p = 2.5 (3.0 vertically), S = 1 vertically.
 * A table is interpolated linearly in log T and log S_a, and is not
 * extrapolated (the Period range lies within it).
 */
class DesignSpectrum
{
public:
  explicit DesignSpectrum(const DesignSpectrumParameters &parameters);

  /** S_a(@p period) (m/s^2) for the global axis @p axis (0, 1, 2); period >= 0 (s). */
  double operator()(const double period, const unsigned int axis) const;

  /**
   * The zero-period value (m/s^2): a_g S (a_vg vertically), a table's value
   * at its shortest period: the peak ground acceleration the records reach.
   */
  double zero_period_value(const unsigned int axis) const;

  /** E.g. `EC8 type 1, ground type C, a_g = 3 m/s^2, 5 % damping, vertical`. */
  std::string description(const unsigned int axis) const;

  const DesignSpectrumParameters &parameters() const { return p; }

  /**
   * Read a `period, pseudo-acceleration` CSV (s, m/s^2): a first line that
   * is not numeric is a header, lines starting with '#' and empty lines are
   * skipped. Errors name @p entry, the file and the line: not two numbers, a
   * period or value not positive, periods not increasing, no rows.
   */
  static void read_table(const std::string &file,
                         const std::string &entry,
                         std::vector<double> &periods,
                         std::vector<double> &values);

private:
  /** Whether @p axis (Y or Z) has a table of its own (`Table file Y|Z`). */
  bool own_table(const unsigned int axis) const;
  /** The table of @p axis (Type = table): its own, or `Table file`'s. */
  const std::vector<double> &table_periods(const unsigned int axis) const;
  /** The pseudo-accelerations of that table (m/s^2). */
  const std::vector<double> &table_values(const unsigned int axis) const;
  /** The file of that table. */
  const std::string &table_file(const unsigned int axis) const;
  /** Whether @p axis follows the vertical EC8 spectrum. */
  bool is_vertical(const unsigned int axis) const;

  const DesignSpectrumParameters p;
  Ec8Corners horizontal, vertical;
};
} // namespace hati

#endif

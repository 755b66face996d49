#ifndef hati_model_solid_stress_output_h
#define hati_model_solid_stress_output_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/vector.h>

#include <hati/base/summary_value.h>

#include <ostream>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

class FrameSolids;

/**
 * The stress output of the solids of a frame (doc/user_guide.md, section
 * 6): the snapshots of `solids.pvd` (displacement, velocity, the stress
 * tensor and the von Mises stress at the nodes of every cell, evaluated in
 * the cell from its displacement gradient, not averaged between cells), the
 * envelope of the von Mises stress at the quadrature points (per cell for
 * `stress_envelope.vtu`, per solid with its point for summary.json `solids`
 * and the results table). The DoF vectors it takes are in the frame's
 * global numbering, constraints distributed.
 */
class SolidStressOutput
{
public:
  /** The output of @p solids (whose DoFs are distributed). */
  explicit SolidStressOutput(const FrameSolids &solids);

  /**
   * One snapshot of `solids-NNNNN.vtu` at @p time (s) and @p cycle:
   * `displacement` @p U (m), `velocity` @p V (m/s; zero if null), `stress`
   * (Pa, a 3 x 3 tensor) and `von_mises` (Pa), at the points of every cell
   * subdivided `Solid element degree` times along each axis; the cell field
   * `subdomain` when @p subdomain (one value per solid cell) is not empty.
   */
  void write_vtu(std::ostream &out,
                 const Vector<double> &U,
                 const Vector<double> *V,
                 const double time,
                 const unsigned int cycle,
                 const Vector<float> &subdomain) const;

  /**
   * Raise the envelope to the von Mises stresses at the quadrature points
   * for the displacement @p U at time @p time (s); a later equal value
   * keeps the earlier time.
   */
  void update_envelope(const double time, const Vector<double> &U);

  /**
   * `stress_envelope.vtu`: per cell `max_von_mises` (Pa), the largest von
   * Mises stress among its quadrature points over the updates so far, and
   * `max_von_mises_time` (s), when it was reached.
   */
  void write_envelope(std::ostream &out) const;

  /**
   * A `stress_envelope.vtu` of given values: per active cell of the solids
   * `max_von_mises` (Pa) from @p cell_values (one per cell), e.g. the
   * combined von Mises stress of a response-spectrum analysis.
   */
  void write_cell_envelope(std::ostream &out,
                           const std::vector<double> &cell_values) const;

  /**
   * summary.json `solids`: per solid name,
   * `{"max_von_mises": {"value" (Pa), "time" (s), "point" [x, y, z] (m)}}`.
   */
  SummaryValue summary() const;

  /** One line per solid: name, largest von Mises stress (MPa), time, point. */
  std::string results_table() const;

private:
  /** The largest von Mises stress of a solid, when and where. */
  struct Peak
  {
    double value = 0., time = 0.;
    Point<3> point;
  };

  const FrameSolids &solids;
  /** Per active cell: the largest von Mises stress (Pa) and its time (s). */
  std::vector<double> cell_max, cell_time;
  /** Per solid. */
  std::vector<Peak> peaks;
};

/** The von Mises stress sqrt(3/2 s : s) of the stress tensor @p sigma (Pa). */
double von_mises(const SymmetricTensor<2, 3> &sigma);
} // namespace hati

#endif

#ifndef hati_model_frame_section_forces_h
#define hati_model_frame_section_forces_h

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hati/base/summary_value.h>

#include <array>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace hati
{
using namespace dealii;

/** One active cell (element) of a Frame: its member, place, axes and matrices. */
struct FrameCell
{
  /** Index of the member in FrameDescription::members. */
  unsigned int member = 0;
  /** Index of the element along the member, from its start. */
  unsigned int element = 0;
  double length = 0.;
  /** Distance of the element's first node from the member's start (m). */
  double position = 0.;
  /** Rotation from global to local axes (frame_element.h). */
  Tensor<2, 3> rotation;
  /** Global DoFs: the six of the first node, then the six of the second. */
  std::array<types::global_dof_index, 12> dofs;
  /** Local stiffness and consistent mass (section forces at every history row). */
  FullMatrix<double> stiffness, mass;
};

/**
 * Section forces (N, Vy, Vz, T, My, Mz at both ends) of @p cell for the
 * displacement @p U (constraints distributed) from its end forces k u minus
 * its own weight under @p gravity (m/s^2; a span load). Inertia forces are
 * taken as nodal: between nodes the distributed inertia of a dynamic run is
 * not in the section forces.
 */
std::array<double, 12> frame_cell_section_forces(const FrameCell &cell,
                                                 const Vector<double> &U,
                                                 const Tensor<1, 3> &gravity);

/**
 * The post-processor of a frame's section forces: the rows of
 * `section_forces.csv` for the `Section force members` (both ends of each of
 * their elements) and the envelope of the values written, in summary.json
 * (`section_force_envelope`) and in the results table; rows of other
 * origins (the cuts of solids) join them through add_row(). Without section
 * force members and other rows it writes nothing.
 */
class FrameSectionForces
{
public:
  /**
   * @p member_names: the name of every member of the frame (in the order
   * of FrameCell::member); @p output_members: the members to write;
   * @p other_rows: the names of further rows given by add_row() (the cuts
   * of solids, SolidCuts).
   */
  FrameSectionForces(const std::vector<std::string> &member_names,
                     const std::vector<std::string> &output_members,
                     const std::vector<std::string> &other_rows = {});

  /**
   * Header of `section_forces.csv`; empty without section force members
   * and other rows.
   */
  std::string header() const;

  /**
   * One row of `section_forces.csv` at time @p time (s) for @p name, its
   * element @p element and position @p x (m), the section forces @p s (N,
   * Vy, Vz in N; T, My, Mz in N m), to @p out unless it is null; the
   * envelope is updated.
   */
  void add_row(std::ostream *out,
               const double time,
               const std::string &name,
               const unsigned int element,
               const double x,
               const std::array<double, 6> &s);

  /**
   * The rows at time @p time (s) for the displacement @p U (constraints
   * distributed) of the frame of @p cells under @p gravity (m/s^2), to
   * @p out unless it is null; the envelope is updated.
   */
  void write(std::ostream *out,
             const double time,
             const Vector<double> &U,
             const std::vector<FrameCell> &cells,
             const Tensor<1, 3> &gravity);

  /**
   * `section_force_envelope`: the largest |N| (N), |My|, |Mz| (N m) among
   * the section forces written so far, with the member, the position along
   * it (m) and the time (s).
   */
  SummaryEntries summary_entries() const;

  /** The envelope of the section forces as table lines. */
  std::string results_table() const;

private:
  /** Largest absolute value, where (m along the member), when (s) and in which member. */
  struct EnvelopeEntry
  {
    double value = 0., x = 0., time = 0.;
    std::string member;
  };
  /** N, My, Mz. */
  std::array<EnvelopeEntry, 3> envelope;
  const std::vector<std::string> member_names;
  const std::vector<std::string> output_members;
  /** Whether any row is written (members or other rows). */
  const bool enabled;
};
} // namespace hati

#endif

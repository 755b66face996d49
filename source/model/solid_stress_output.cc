#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <hati/model/frame_solids.h>
#include <hati/model/solid_stress_output.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
namespace
{
/**
 * The stress tensor (9 components, a tensor for ParaView) and the von
 * Mises stress at the output points of a cell, from the displacement
 * gradient there and the cell's material (its solid).
 */
class StressPostprocessor : public DataPostprocessor<3>
{
public:
  explicit StressPostprocessor(const FrameSolids &solids) : solids(solids) {}

  void evaluate_vector_field(const DataPostprocessorInputs::Vector<3> &input,
                             std::vector<Vector<double>> &computed) const override
  {
    const auto cell = input.template get_cell<3>();
    for (unsigned int q = 0; q < input.solution_gradients.size(); ++q)
    {
      Tensor<2, 3> grad;
      for (unsigned int c = 0; c < 3; ++c)
        grad[c] = input.solution_gradients[q][c];
      const SymmetricTensor<2, 3> sigma =
          solids.stress(cell->material_id(), symmetrize(grad));
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          computed[q](3 * i + j) = sigma[i][j];
      computed[q](9) = von_mises(sigma);
    }
  }

  std::vector<std::string> get_names() const override
  {
    std::vector<std::string> names(9, "stress");
    names.emplace_back("von_mises");
    return names;
  }

  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  get_data_component_interpretation() const override
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds(
        9, DataComponentInterpretation::component_is_part_of_tensor);
    kinds.push_back(DataComponentInterpretation::component_is_scalar);
    return kinds;
  }

  UpdateFlags get_needed_update_flags() const override { return update_gradients; }

private:
  const FrameSolids &solids;
};

/** The solid DoFs of the global vector @p U, in the numbering of the solids' DoFHandler.
 */
Vector<double> solid_part(const FrameSolids &solids, const Vector<double> &U)
{
  Vector<double> u(solids.n_dofs());
  for (types::global_dof_index i = 0; i < u.size(); ++i)
    u[i] = U[solids.offset() + i];
  return u;
}
} // namespace

double von_mises(const SymmetricTensor<2, 3> &sigma)
{
  return std::sqrt(1.5) * deviator(sigma).norm();
}

SolidStressOutput::SolidStressOutput(const FrameSolids &solids)
    : solids(solids), cell_max(solids.dofs().get_triangulation().n_active_cells(), 0.),
      cell_time(cell_max.size(), 0.), peaks(solids.n_solids())
{
}

void SolidStressOutput::write_vtu(std::ostream &out,
                                  const Vector<double> &U,
                                  const Vector<double> *V,
                                  const double time,
                                  const unsigned int cycle,
                                  const Vector<float> &subdomain) const
{
  const Vector<double> u = solid_part(solids, U);
  const Vector<double> v = V ? solid_part(solids, *V) : Vector<double>(u.size());
  const StressPostprocessor stress(solids);
  const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      3, DataComponentInterpretation::component_is_part_of_vector);
  DataOut<3> data_out;
  data_out.attach_dof_handler(solids.dofs());
  data_out.add_data_vector(
      u, std::vector<std::string>(3, "displacement"), DataOut<3>::type_dof_data, vector);
  data_out.add_data_vector(
      v, std::vector<std::string>(3, "velocity"), DataOut<3>::type_dof_data, vector);
  data_out.add_data_vector(u, stress);
  if (subdomain.size() > 0)
    data_out.add_data_vector(subdomain, "subdomain", DataOut<3>::type_cell_data);
  data_out.build_patches(solids.dofs().get_fe().degree);
  // the fastest zlib level: a snapshot of the 3D crane's solids took 0.3 s
  // at the best compression, most of it in deflate
  data_out.set_flags(
      DataOutBase::VtkFlags(time, cycle, true, DataOutBase::VtkFlags::best_speed));
  data_out.write_vtu(out);
}

void SolidStressOutput::update_envelope(const double time, const Vector<double> &U)
{
  std::vector<SymmetricTensor<2, 3>> stress;
  std::vector<Point<3>> points;
  solids.stresses(U, stress, points);
  const unsigned int n_q = stress.size() / cell_max.size();
  for (const auto &cell : solids.dofs().active_cell_iterators())
  {
    const unsigned int c = cell->active_cell_index();
    Peak &peak = peaks[cell->material_id()];
    for (unsigned int k = c * n_q; k < (c + 1) * n_q; ++k)
    {
      const double s = von_mises(stress[k]);
      if (s > cell_max[c])
      {
        cell_max[c] = s;
        cell_time[c] = time;
      }
      if (s > peak.value)
        peak = {s, time, points[k]};
    }
  }
}

void SolidStressOutput::write_envelope(std::ostream &out) const
{
  const Vector<double> value(cell_max.begin(), cell_max.end());
  const Vector<double> when(cell_time.begin(), cell_time.end());
  DataOut<3> data_out;
  data_out.attach_triangulation(solids.dofs().get_triangulation());
  data_out.add_data_vector(value, "max_von_mises", DataOut<3>::type_cell_data);
  data_out.add_data_vector(when, "max_von_mises_time", DataOut<3>::type_cell_data);
  data_out.build_patches();
  // rewritten at every VTU row: the fastest zlib level
  DataOutBase::VtkFlags flags;
  flags.compression_level = DataOutBase::VtkFlags::best_speed;
  data_out.set_flags(flags);
  data_out.write_vtu(out);
}

void SolidStressOutput::write_cell_envelope(std::ostream &out,
                                            const std::vector<double> &cell_values) const
{
  AssertThrow(cell_values.size() == cell_max.size(), ExcInternalError());
  const Vector<double> value(cell_values.begin(), cell_values.end());
  DataOut<3> data_out;
  data_out.attach_triangulation(solids.dofs().get_triangulation());
  data_out.add_data_vector(value, "max_von_mises", DataOut<3>::type_cell_data);
  data_out.build_patches();
  data_out.write_vtu(out);
}

SummaryValue SolidStressOutput::summary() const
{
  SummaryValue result = SummaryValue::object();
  for (unsigned int s = 0; s < peaks.size(); ++s)
  {
    const Peak &p = peaks[s];
    SummaryValue point = SummaryValue::list();
    for (unsigned int d = 0; d < 3; ++d)
      point.push_back(p.point[d]);
    result.set(solids.solid_name(s),
               SummaryValue::object().set("max_von_mises",
                                          SummaryValue::object()
                                              .set("value", p.value)
                                              .set("time", p.time)
                                              .set("point", point)));
  }
  return result;
}

std::string SolidStressOutput::results_table() const
{
  std::ostringstream s;
  s << "  solids: largest von Mises stress (quadrature points, section force rows):\n";
  for (unsigned int k = 0; k < peaks.size(); ++k)
  {
    const Peak &p = peaks[k];
    s << "    " << std::left << std::setw(16) << solids.solid_name(k) << std::right
      << std::setw(14) << p.value * 1e-6 << " MPa  at t = " << p.time << " s, x = ("
      << p.point[0] << ", " << p.point[1] << ", " << p.point[2] << ") m\n";
  }
  return s.str();
}
} // namespace hati

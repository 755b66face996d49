// The linear response quantities of a frame for a response-spectrum
// analysis (doc/theory.md 14.6): every member's section forces at both ends
// of its elements, every solid's stress tensor at the quadrature points of
// its cells.

#include <hati/model/frame.h>
#include <hati/model/frame_section_forces.h>
#include <hati/model/frame_solids.h>
#include <hati/model/solid_stress_output.h>

#include <algorithm>

namespace hati
{
namespace
{
/** The section forces in the order of frame_cell_section_forces(). */
const char *const section_force_names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
const char *const section_force_units[6] = {"N", "N", "N", "N m", "N m", "N m"};
} // namespace

std::vector<ResponseGroup> Frame::response_groups() const
{
  std::vector<unsigned int> n_cells(frame.members.size(), 0);
  for (const FrameCell &cell : cells)
    ++n_cells[cell.member];
  std::vector<ResponseGroup> groups;
  for (unsigned int m = 0; m < frame.members.size(); ++m)
    if (n_cells[m] > 0)
      for (unsigned int c = 0; c < 6; ++c)
        groups.push_back({frame.members[m].name + "." + section_force_names[c],
                          section_force_units[c],
                          2 * n_cells[m],
                          false});
  if (solids)
  {
    // the points of each solid: its cells' quadrature points
    std::vector<SymmetricTensor<2, 3>> stress;
    std::vector<Point<3>> points;
    solids->stresses(Vector<double>(n_beam_dofs + solids->n_dofs()), stress, points);
    const unsigned int n_cells = solids->dofs().get_triangulation().n_active_cells();
    const unsigned int n_q = n_cells > 0 ? stress.size() / n_cells : 0;
    std::vector<unsigned int> solid_cells(solids->n_solids(), 0);
    for (const auto &cell : solids->dofs().active_cell_iterators())
      ++solid_cells[cell->material_id()];
    for (unsigned int s = 0; s < solids->n_solids(); ++s)
      groups.push_back({solids->solid_name(s) + ".max_von_mises",
                        "Pa",
                        6 * n_q * solid_cells[s],
                        true});
  }
  return groups;
}

void Frame::response_values(const Vector<double> &U,
                            std::vector<double> &values,
                            const bool own_weight) const
{
  Vector<double> u(U);
  constraints.distribute(u);
  // per member, its cells in order (cells are stored member by member, but
  // the order of the groups must not depend on it)
  std::vector<std::vector<unsigned int>> member_cells(frame.members.size());
  for (unsigned int k = 0; k < cells.size(); ++k)
    member_cells[cells[k].member].push_back(k);
  values.clear();
  const Tensor<1, 3> span_load = own_weight ? gravity : Tensor<1, 3>();
  std::vector<std::array<double, 12>> forces;
  for (unsigned int m = 0; m < frame.members.size(); ++m)
  {
    if (member_cells[m].empty())
      continue;
    forces.clear();
    for (const unsigned int k : member_cells[m])
      forces.push_back(frame_cell_section_forces(cells[k], u, span_load));
    for (unsigned int c = 0; c < 6; ++c)
      for (const auto &s : forces)
      {
        values.push_back(s[c]);
        values.push_back(s[6 + c]);
      }
  }
  if (!solids)
    return;
  // per solid, its cells in the order of the active cells: the components
  // xx, yy, zz, xy, yz, xz at each quadrature point
  std::vector<SymmetricTensor<2, 3>> stress;
  std::vector<Point<3>> points;
  solids->stresses(u, stress, points);
  const unsigned int n_cells = solids->dofs().get_triangulation().n_active_cells();
  const unsigned int n_q = n_cells > 0 ? stress.size() / n_cells : 0;
  for (unsigned int s = 0; s < solids->n_solids(); ++s)
    for (const auto &cell : solids->dofs().active_cell_iterators())
      if (cell->material_id() == s)
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const SymmetricTensor<2, 3> &t = stress[cell->active_cell_index() * n_q + q];
          for (const double v : {t[0][0], t[1][1], t[2][2], t[0][1], t[1][2], t[0][2]})
            values.push_back(v);
        }
}

std::vector<std::string> Frame::response_envelope_files() const
{
  if (!solids)
    return {};
  return {"stress_envelope.vtu"};
}

void Frame::write_response_envelope(const std::string &name,
                                    const std::vector<std::vector<double>> &von_mises,
                                    std::ostream &out) const
{
  AssertThrow(solids && name == "stress_envelope.vtu" &&
                  von_mises.size() == solids->n_solids(),
              ExcMessage("no response envelope file " + name));
  const unsigned int n_cells = solids->dofs().get_triangulation().n_active_cells();
  std::vector<double> cell_values(n_cells, 0.);
  for (unsigned int s = 0; s < solids->n_solids(); ++s)
  {
    unsigned int n_solid_cells = 0;
    for (const auto &cell : solids->dofs().active_cell_iterators())
      n_solid_cells += cell->material_id() == s;
    const std::size_t n_q = n_solid_cells > 0 ? von_mises[s].size() / n_solid_cells : 0;
    std::size_t k = 0;
    for (const auto &cell : solids->dofs().active_cell_iterators())
      if (cell->material_id() == s)
      {
        double &v = cell_values[cell->active_cell_index()];
        for (std::size_t q = 0; q < n_q; ++q)
          v = std::max(v, von_mises[s][k++]);
      }
  }
  solids->stress_output().write_cell_envelope(out, cell_values);
}
} // namespace hati

// The linear response quantities of a frame for a response-spectrum
// analysis (doc/theory.md 14.6): every member's section forces at both ends
// of its elements.

#include <hati/model/frame.h>
#include <hati/model/frame_section_forces.h>

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
  return groups;
}

void Frame::response_values(const Vector<double> &U, std::vector<double> &values) const
{
  Vector<double> u(U);
  constraints.distribute(u);
  // per member, its cells in order (cells are stored member by member, but
  // the order of the groups must not depend on it)
  std::vector<std::vector<unsigned int>> member_cells(frame.members.size());
  for (unsigned int k = 0; k < cells.size(); ++k)
    member_cells[cells[k].member].push_back(k);
  values.clear();
  const Tensor<1, 3> no_gravity;
  std::vector<std::array<double, 12>> forces;
  for (unsigned int m = 0; m < frame.members.size(); ++m)
  {
    if (member_cells[m].empty())
      continue;
    forces.clear();
    for (const unsigned int k : member_cells[m])
      forces.push_back(frame_cell_section_forces(cells[k], u, no_gravity));
    for (unsigned int c = 0; c < 6; ++c)
      for (const auto &s : forces)
      {
        values.push_back(s[c]);
        values.push_back(s[6 + c]);
      }
  }
}
} // namespace hati

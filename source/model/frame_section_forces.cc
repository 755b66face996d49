#include <hati/model/frame_element.h>
#include <hati/model/frame_section_forces.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
std::array<double, 12> frame_cell_section_forces(const FrameCell &cell,
                                                 const Vector<double> &U,
                                                 const Tensor<1, 3> &gravity)
{
  // work vectors of this thread: every output row calls this for every
  // element (allocating them cost a third of the crane's output time)
  thread_local Vector<double> ug(12), f(12), span(12), r(12), local(12);
  for (unsigned int i = 0; i < 12; ++i)
    ug[i] = U[cell.dofs[i]];
  to_local(ug, cell.rotation, local);
  cell.stiffness.vmult(f, local);
  // end forces f = k u - F_gravity, F_gravity = m r g in local axes: the
  // element's own weight is a span load (fixed-end forces)
  const Tensor<1, 3> g = cell.rotation * gravity;
  r = 0.;
  for (unsigned int d = 0; d < 3; ++d)
    r[d] = r[6 + d] = g[d];
  cell.mass.vmult(span, r);
  f -= span;
  return section_forces(f);
}

FrameSectionForces::FrameSectionForces(const std::vector<std::string> &member_names,
                                       const std::vector<std::string> &output_members,
                                       const std::vector<std::string> &other_rows)
    : member_names(member_names), output_members(output_members),
      enabled(!output_members.empty() || !other_rows.empty())
{
}

std::string FrameSectionForces::header() const
{
  if (!enabled)
    return "";
  return "time,member,element,x,N,Vy,Vz,T,My,Mz";
}

void FrameSectionForces::add_row(std::ostream *out,
                                 const double time,
                                 const std::string &name,
                                 const unsigned int element,
                                 const double x,
                                 const std::array<double, 6> &s)
{
  // envelope of N, My, Mz (components 0, 4, 5)
  const unsigned int component[3] = {0, 4, 5};
  for (unsigned int e = 0; e < 3; ++e)
  {
    const double v = std::abs(s[component[e]]);
    if (v > envelope[e].value)
      envelope[e] = {v, x, time, name};
  }
  if (out == nullptr)
    return;
  *out << time << ',' << name << ',' << element << ',' << x;
  for (unsigned int k = 0; k < 6; ++k)
    *out << ',' << s[k] + 0.; // + 0.: no "-0" in the file
  *out << '\n';
}

void FrameSectionForces::write(std::ostream *out,
                               const double time,
                               const Vector<double> &U,
                               const std::vector<FrameCell> &cells,
                               const Tensor<1, 3> &gravity)
{
  for (const auto &name : output_members)
    for (const auto &cell : cells)
      if (member_names[cell.member] == name)
      {
        const auto s = frame_cell_section_forces(cell, U, gravity);
        for (unsigned int end = 0; end < 2; ++end)
          add_row(out,
                  time,
                  name,
                  cell.element,
                  cell.position + end * cell.length,
                  {{s[6 * end],
                    s[6 * end + 1],
                    s[6 * end + 2],
                    s[6 * end + 3],
                    s[6 * end + 4],
                    s[6 * end + 5]}});
      }
}

SummaryEntries FrameSectionForces::summary_entries() const
{
  if (!enabled)
    return {};
  SummaryValue result = SummaryValue::object();
  const char *names[3] = {"N", "My", "Mz"};
  for (unsigned int e = 0; e < 3; ++e)
    result.set(names[e],
               SummaryValue::object()
                   .set("max_abs", envelope[e].value)
                   .set("member", envelope[e].member)
                   .set("x", envelope[e].x)
                   .set("time", envelope[e].time));
  return {{"section_force_envelope", result}};
}

std::string FrameSectionForces::results_table() const
{
  if (!enabled)
    return "";
  std::ostringstream s;
  const char *names[3] = {"max |N|  (N)  ", "max |My| (N m)", "max |Mz| (N m)"};
  s << "  section forces of the members written to section_forces.csv (at its rows):\n";
  for (unsigned int e = 0; e < 3; ++e)
    s << "    " << names[e] << std::setw(16) << envelope[e].value << "  in "
      << envelope[e].member << " at x = " << envelope[e].x
      << " m, t = " << envelope[e].time << " s\n";
  return s.str();
}
} // namespace hati

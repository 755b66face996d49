#include <hati/model/beam_stresses.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hati
{
namespace
{
/**
 * Whether the member @p m of @p frame is made rigid by a rigid link between
 * its end nodes (a post of a true height): it has no stresses.
 */
bool rigidly_linked(const FrameDescription &frame, const FrameDescription::Member &m)
{
  const std::string start = m.path.empty() ? m.start : m.path.front(),
                    end = m.path.empty() ? m.end : m.path.back();
  for (const auto &link : frame.solids.rigid_links)
    if ((link.master == start && link.slave == end) ||
        (link.master == end && link.slave == start))
      return true;
  return false;
}
} // namespace

std::vector<const FrameSection *> stressed_member_sections(const FrameDescription &frame)
{
  std::vector<const FrameSection *> sections;
  for (const auto &m : frame.members)
  {
    const auto it = frame.sections.find(m.section);
    sections.push_back(
        it == frame.sections.end() || rigidly_linked(frame, m) ? nullptr : &it->second);
  }
  return sections;
}

bool has_fibre_distances(const FrameSection &section)
{
  return section.c_y > 0. && section.c_z > 0.;
}

BeamSectionStress beam_section_stress(const FrameSection &section,
                                      const std::array<double, 6> &s)
{
  const double N = std::abs(s[0]), Vy = std::abs(s[1]), Vz = std::abs(s[2]),
               T = std::abs(s[3]), My = std::abs(s[4]), Mz = std::abs(s[5]);
  const double axial = N / section.A, bending_y = My * section.c_z / section.Iy,
               bending_z = Mz * section.c_y / section.Iz;
  BeamSectionStress r;
  // S1: the corners, where both bending stresses are largest
  r.normal = axial + bending_y + bending_z;
  const auto von_mises = [](const double sigma, const double tau)
  { return std::sqrt(sigma * sigma + 3. * tau * tau); };
  switch (section.shape)
  {
  case FrameSection::Shape::box:
  {
    // S2: Bredt's shear flow of the torque and the mean shear of the
    // walls that carry each shear force, at the wall centre lines
    const double bm = section.b - section.t_web, hm = section.h - section.t_flange;
    const double q_torsion = T / (2. * bm * hm);
    const double web = (q_torsion + Vz / (2. * hm)) / section.t_web,
                 flange = (q_torsion + Vy / (2. * bm)) / section.t_flange;
    r.shear = std::max(web, flange);
    r.von_mises = von_mises(r.normal, r.shear);
    break;
  }
  case FrameSection::Shape::rectangle:
  {
    // Roark's largest torsional stress of a rectangle (half sides a >= c),
    // at the middle of its long sides; taken at the middle of every side
    const double a = 0.5 * std::max(section.b, section.h),
                 c = 0.5 * std::min(section.b, section.h);
    const double tau_torsion = T * (3. * a + 1.8 * c) / (8. * a * a * c * c);
    // the middles of the faces z = +-h/2 (shear of Vy) and y = +-b/2 (of Vz)
    const double tau_top = tau_torsion + 1.5 * Vy / section.A,
                 tau_side = tau_torsion + 1.5 * Vz / section.A;
    r.shear = std::max(tau_top, tau_side);
    r.von_mises = std::max({r.normal,
                            von_mises(axial + bending_y, tau_top),
                            von_mises(axial + bending_z, tau_side)});
    break;
  }
  case FrameSection::Shape::general:
  {
    const auto per_area = [&](const double V, const double As)
    { return V / (As > 0. && std::isfinite(As) ? As : section.A); };
    r.shear =
        T * std::max(section.c_y, section.c_z) / section.J +
        std::max(per_area(Vy, section.shear_area_y), per_area(Vz, section.shear_area_z));
    r.von_mises = von_mises(r.normal, r.shear);
    break;
  }
  }
  return r;
}

BeamStressEnvelope::BeamStressEnvelope(
    const std::vector<std::string> &member_names,
    const std::vector<const FrameSection *> &member_sections)
    : entry_of_member(member_names.size(), -1)
{
  for (unsigned int m = 0; m < member_names.size(); ++m)
    if (m < member_sections.size() && member_sections[m] &&
        has_fibre_distances(*member_sections[m]))
    {
      entry_of_member[m] = members.size();
      members.push_back({m, member_names[m], member_sections[m], {}, {}});
    }
}

void BeamStressEnvelope::update(const double time,
                                const Vector<double> &U,
                                const std::vector<FrameCell> &cells,
                                const Tensor<1, 3> &gravity)
{
  if (members.empty())
    return;
  for (const FrameCell &cell : cells)
  {
    const int e = entry_of_member[cell.member];
    if (e < 0)
      continue;
    Member &m = members[e];
    const auto f = frame_cell_section_forces(cell, U, gravity);
    for (unsigned int end = 0; end < 2; ++end)
    {
      const BeamSectionStress stress = beam_section_stress(*m.section,
                                                           {{f[6 * end],
                                                             f[6 * end + 1],
                                                             f[6 * end + 2],
                                                             f[6 * end + 3],
                                                             f[6 * end + 4],
                                                             f[6 * end + 5]}});
      const double x = cell.position + end * cell.length;
      if (stress.normal > m.normal.value)
        m.normal = {stress.normal, x, time};
      if (stress.von_mises > m.von_mises.value)
        m.von_mises = {stress.von_mises, x, time};
    }
  }
}

SummaryEntries BeamStressEnvelope::summary_entries() const
{
  if (members.empty())
    return {};
  SummaryValue result = SummaryValue::object();
  const auto peak = [](const Peak &p)
  {
    return SummaryValue::object().set("value", p.value).set("x", p.x).set("time", p.time);
  };
  for (const Member &m : members)
    result.set(m.name,
               SummaryValue::object()
                   .set("max_normal_stress", peak(m.normal))
                   .set("max_von_mises", peak(m.von_mises)));
  return {{"beam_stresses", result}};
}

std::string BeamStressEnvelope::results_table() const
{
  if (members.empty())
    return "";
  std::ostringstream s;
  s << "  beam stresses at the extreme fibres (section force rows; MPa):\n"
    << "    " << std::setw(24) << "member" << std::setw(12) << "normal" << std::setw(10)
    << "at x (m)" << std::setw(10) << "t (s)" << std::setw(12) << "von Mises"
    << std::setw(10) << "at x (m)" << std::setw(10) << "t (s)" << '\n';
  s << std::setprecision(4);
  for (const Member &m : members)
    s << "    " << std::setw(24) << m.name << std::setw(12) << 1e-6 * m.normal.value
      << std::setw(10) << m.normal.x << std::setw(10) << m.normal.time << std::setw(12)
      << 1e-6 * m.von_mises.value << std::setw(10) << m.von_mises.x << std::setw(10)
      << m.von_mises.time << '\n';
  return s.str();
}
} // namespace hati

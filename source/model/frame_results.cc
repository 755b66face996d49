#include <deal.II/numerics/data_out.h>

#include <hati/model/frame.h>
#include <hati/model/frame_solids.h>
#include <hati/model/solid_stress_output.h>

#include <iomanip>
#include <sstream>

namespace hati
{
// The results of a frame: its VTU snapshots (solution.pvd), the summary
// entries, the results table, and the stress output of its solids

SummaryEntries Frame::summary_entries(const std::map<std::string, double> &) const
{
  SummaryEntries entries = section_force_output.summary_entries();
  for (auto &entry : beam_stresses.summary_entries())
    entries.push_back(std::move(entry));
  if (solids)
    entries.emplace_back("solids", solids->stress_output().summary());
  return entries;
}

std::string Frame::results_table() const
{
  return section_force_output.results_table() + beam_stresses.results_table() +
         (solids ? solids->stress_output().results_table() : "");
}

std::vector<std::string> Frame::vtu_series() const
{
  if (!solids)
    return {};
  return {"solids"};
}

void Frame::write_series_vtu(const std::string &series,
                             std::ostream &out,
                             const VtuSnapshot &snapshot) const
{
  AssertThrow(solids && series == "solids", ExcMessage("no VTU series " + series));
  Vector<double> u, v;
  for (const auto &[name, field] : snapshot.fields)
    if (name == "displacement" || name == "velocity")
    {
      Vector<double> &x = name == "displacement" ? u : v;
      x = *field;
      constraints.distribute(x);
    }
  AssertThrow(u.size() > 0, ExcMessage("a solids snapshot without displacement"));
  // the subdomain of the solid cells: their parts follow the beam cells'
  const Vector<float> all = subdomain_field();
  Vector<float> subdomain;
  if (all.size() > triangulation.n_active_cells())
  {
    subdomain.reinit(all.size() - triangulation.n_active_cells());
    for (unsigned int c = 0; c < subdomain.size(); ++c)
      subdomain[c] = all[triangulation.n_active_cells() + c];
  }
  solids->stress_output().write_vtu(
      out, u, v.size() > 0 ? &v : nullptr, snapshot.time, snapshot.cycle, subdomain);
}

bool Frame::member_stress(const std::string &member,
                          const std::array<double, 6> &forces,
                          double &normal,
                          double &von_mises) const
{
  const auto sections = stressed_member_sections(frame);
  for (unsigned int m = 0; m < frame.members.size(); ++m)
    if (frame.members[m].name == member)
    {
      if (!sections[m] || !has_fibre_distances(*sections[m]))
        return false;
      const BeamSectionStress s = beam_section_stress(*sections[m], forces);
      normal = s.normal;
      von_mises = s.von_mises;
      return true;
    }
  return false;
}

std::vector<std::string> Frame::members_without_stresses() const
{
  std::vector<std::string> names;
  const auto sections = stressed_member_sections(frame);
  for (unsigned int m = 0; m < frame.members.size(); ++m)
    if (sections[m] && !has_fibre_distances(*sections[m]))
      names.push_back(frame.members[m].name);
  return names;
}

std::string Frame::geometry_csv() const
{
  std::ostringstream s;
  s << "member,x1,y1,z1,x2,y2,z2\n" << std::setprecision(10);
  for (const auto &cell : triangulation.active_cell_iterators())
  {
    s << frame.members[cells[cell->active_cell_index()].member].name;
    for (unsigned int v = 0; v < 2; ++v)
      for (unsigned int d = 0; d < 3; ++d)
        s << ',' << cell->vertex(v)[d];
    s << '\n';
  }
  return s.str();
}

void Frame::update_envelopes(const double time, const Vector<double> &U) const
{
  if (!solids && !beam_stresses.enabled())
    return;
  Vector<double> u(U);
  constraints.distribute(u);
  beam_stresses.update(time, u, cells, gravity);
  if (solids)
    solids->stress_output().update_envelope(time, u);
}

std::vector<std::string> Frame::envelope_files() const
{
  if (!solids)
    return {};
  return {"stress_envelope.vtu"};
}

void Frame::write_envelope_file(const std::string &name, std::ostream &out) const
{
  AssertThrow(solids && name == "stress_envelope.vtu",
              ExcMessage("no envelope file " + name));
  solids->stress_output().write_envelope(out);
}
void Frame::write_vtu(std::ostream &out, const VtuSnapshot &snapshot) const
{
  const auto &[fields, time, cycle] = snapshot;
  DataOut<1, 3> data_out;
  data_out.attach_dof_handler(dof_handler);
  std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      6, DataComponentInterpretation::component_is_part_of_vector);
  std::vector<Vector<double>> distributed(fields.size());
  Vector<float> member_id(triangulation.n_active_cells());
  std::array<Vector<float>, 6> forces;
  for (auto &f : forces)
    f.reinit(triangulation.n_active_cells());
  for (unsigned int f = 0; f < fields.size(); ++f)
  {
    distributed[f] = *fields[f].second;
    constraints.distribute(distributed[f]);
    if (distributed[f].size() > n_mesh_dofs) // rope-only nodes: not in the mesh
    {
      Vector<double> mesh_part(n_mesh_dofs);
      std::copy(distributed[f].begin(),
                distributed[f].begin() + n_mesh_dofs,
                mesh_part.begin());
      distributed[f].swap(mesh_part);
    }
    std::vector<std::string> names(3, fields[f].first);
    for (unsigned int c = 0; c < 3; ++c)
      names.push_back(fields[f].first + "_rotational");
    data_out.add_data_vector(
        distributed[f], names, DataOut<1, 3>::type_dof_data, interpretation);
    if (fields[f].first == "displacement")
      for (unsigned int c = 0; c < cells.size(); ++c)
      {
        const auto s = frame_cell_section_forces(cells[c], distributed[f], gravity);
        for (unsigned int k = 0; k < 6; ++k)
          forces[k][c] = 0.5 * (s[k] + s[6 + k]); // mid-element value
      }
  }
  for (unsigned int c = 0; c < cells.size(); ++c)
    member_id[c] = cells[c].member;
  data_out.add_data_vector(member_id, "member", DataOut<1, 3>::type_cell_data);
  // the beam cells come first in the parts (then the solids')
  Vector<float> subdomain = subdomain_field();
  if (subdomain.size() > 0)
  {
    Vector<float> beams(triangulation.n_active_cells());
    for (unsigned int c = 0; c < beams.size(); ++c)
      beams[c] = subdomain[c];
    subdomain.swap(beams);
    data_out.add_data_vector(subdomain, "subdomain", DataOut<1, 3>::type_cell_data);
  }
  const char *force_names[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  for (unsigned int k = 0; k < 6; ++k)
    data_out.add_data_vector(forces[k], force_names[k], DataOut<1, 3>::type_cell_data);
  data_out.build_patches();
  data_out.set_flags(DataOutBase::VtkFlags(time, cycle));
  data_out.write_vtu(out);
}

} // namespace hati

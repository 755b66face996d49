#include <hati/model/frame.h>
#include <hati/model/frame_solids.h>
#include <hati/model/solid_stress_output.h>

namespace hati
{
// The results of a frame beyond solution.pvd and section_forces.csv: the
// summary entries, the results table, and the stress output of its solids

SummaryEntries Frame::summary_entries(const std::map<std::string, double> &) const
{
  SummaryEntries entries = section_force_output.summary_entries();
  if (solids)
    entries.emplace_back("solids", solids->stress_output().summary());
  return entries;
}

std::string Frame::results_table() const
{
  return section_force_output.results_table() +
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
  // the subdomain of the solid cells (the hook of Model::select_part()):
  // none, a frame with solids is not decomposed yet
  solids->stress_output().write_vtu(out,
                                    u,
                                    v.size() > 0 ? &v : nullptr,
                                    snapshot.time,
                                    snapshot.cycle,
                                    Vector<float>());
}

void Frame::update_envelopes(const double time, const Vector<double> &U) const
{
  if (!solids)
    return;
  Vector<double> u(U);
  constraints.distribute(u);
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
} // namespace hati

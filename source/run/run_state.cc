#include <deal.II/base/utilities.h>

#include <hati/analysis/reduced_part.h>
#include <hati/base/fnv_hash.h>
#include <hati/base/input_file.h>
#include <hati/run/problem.h>
#include <hati/run/run_state.h>
#include <hati/time/cd_lagrange.h>
#include <hati/time/hati_coupling.h>
#include <hati/time/newmark.h>

#include <algorithm>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <type_traits>
#include <vector>

namespace hati
{
template <class Integrator>
RunState current_run_state(const Integrator &integrator, const Problem &problem)
{
  RunState state;
  state.time = integrator.time();
  state.model = problem.model->description();
  state.model_parameters = problem.state_identity.model_parameters;
  state.model_files = problem.state_identity.model_files;
  state.displacement = integrator.displacement();
  if constexpr (std::is_same_v<Integrator, Newmark>)
  {
    state.velocity = integrator.velocity();
    state.contact_force.reinit(state.velocity.size());
  }
  else if constexpr (std::is_same_v<Integrator, CDLagrange>)
  {
    integrator.integer_velocity(state.velocity);
    integrator.contact_force(state.contact_force);
  }
  else
  {
    state.velocity = integrator.integer_velocity();
    state.contact_force = integrator.contact_force();
    state.interface_multiplier = integrator.interface_multiplier();
    state.interface_signature = coupling_signature(*problem.decomposition);
    // the implicit side's own values of the interface DoFs
    const std::vector<unsigned int> shared = shared_implicit_dofs(*problem.decomposition);
    const Newmark &implicit = integrator.implicit_part();
    state.implicit_interface.reinit(2 * shared.size());
    for (unsigned int s = 0; s < shared.size(); ++s)
    {
      state.implicit_interface[s] = implicit.displacement()[shared[s]];
      state.implicit_interface[shared.size() + s] = implicit.velocity()[shared[s]];
    }
  }
  if constexpr (!std::is_same_v<Integrator, CDLagrange>)
  {
    std::vector<bool> held(state.displacement.size(), false);
    if (problem.decomposition)
      for (const auto &part : problem.decomposition->parts)
        for (const auto i : part.global_dofs)
          held[i] = true;
    for (Vector<double> *v : {&state.displacement, &state.velocity})
    {
      Vector<double> completed = *v;
      problem.model->complete_solution(completed);
      for (unsigned int i = 0; i < v->size(); ++i)
        if (!held[i])
          (*v)[i] = completed[i];
    }
  }
  return state;
}

void model_identity(const dealii::ParameterHandler &prm, RunState &identity)
{
  static const std::vector<std::string> left_out = {"Monitor nodes",
                                                    "Section force members",
                                                    "Solid cuts",
                                                    "Damping type",
                                                    "Damping ratio",
                                                    "Damping band",
                                                    "Initial velocity",
                                                    "Initial height"};
  std::ostringstream text;
  prm.print_parameters(text, dealii::ParameterHandler::ShortPRM);
  std::istringstream in(text.str());
  std::vector<std::string> path;
  std::string line;
  identity.model_parameters.clear();
  identity.model_files.clear();
  while (std::getline(in, line))
  {
    const std::string t = dealii::Utilities::trim(line);
    if (t.rfind("subsection ", 0) == 0)
      path.push_back(dealii::Utilities::trim(t.substr(11)));
    else if (t == "end" && !path.empty())
      path.pop_back();
    else if (t.rfind("set ", 0) == 0 && !path.empty() && path[0] == "Model" &&
             !(path.size() > 1 && path[1] == "Decomposition"))
    {
      const auto equal = t.find('=');
      const std::string entry = dealii::Utilities::trim(t.substr(4, equal - 4)),
                        value = equal == std::string::npos
                                    ? std::string()
                                    : dealii::Utilities::trim(t.substr(equal + 1));
      if (std::find(left_out.begin(), left_out.end(), entry) != left_out.end())
        continue;
      std::string where;
      for (const auto &p : path)
        where += p + "/";
      where += entry;
      identity.model_parameters.push_back(where + " = " + value);
      // the mesh files it names
      std::string words = value, f;
      std::replace_if(
          words.begin(),
          words.end(),
          [](const char c) { return c == ',' || c == ';'; },
          ' ');
      std::istringstream in_words(words);
      while (in_words >> f)
        if (f.size() > 4 && f.compare(f.size() - 4, 4, ".msh") == 0)
        {
          struct stat status;
          const bool regular = ::stat(f.c_str(), &status) == 0 && S_ISREG(status.st_mode);
          identity.model_files.push_back(where + " = " + f + ": " +
                                         (regular ? file_digest(f) : "missing"));
        }
    }
  }
}

std::string coupling_signature(const Decomposition &decomposition)
{
  std::uint64_t hash = 14695981039346656037ull;
  const auto add = [&hash](const void *data, const std::size_t bytes)
  {
    const auto *b = static_cast<const unsigned char *>(data);
    for (std::size_t i = 0; i < bytes; ++i)
      hash = (hash ^ b[i]) * 1099511628211ull;
  };
  for (const SparseRow &row : decomposition.rows[0])
    for (unsigned int i = 0; i < row.dofs.size(); ++i)
    {
      const std::uint64_t dof = decomposition.parts[0].global_dofs[row.dofs[i]];
      add(&dof, sizeof(dof));
      add(&row.coefficients[i], sizeof(double));
    }
  // the implicit part as it is stepped: its DoFs or reduced coordinates
  const std::uint64_t n_implicit = implicit_system(decomposition).n_dofs();
  add(&n_implicit, sizeof(n_implicit));
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << hash;
  return s.str();
}

std::vector<unsigned int> shared_implicit_dofs(const Decomposition &decomposition)
{
  std::vector<unsigned int> shared;
  const auto &explicit_dofs = decomposition.parts[0].global_dofs;
  const auto &implicit_dofs = decomposition.parts[1].global_dofs;
  if (implicit_system(decomposition).n_dofs() != implicit_dofs.size())
    return shared;
  std::vector<bool> held_explicitly;
  for (const auto i : explicit_dofs)
  {
    if (i >= held_explicitly.size())
      held_explicitly.resize(i + 1, false);
    held_explicitly[i] = true;
  }
  for (unsigned int j = 0; j < implicit_dofs.size(); ++j)
    if (implicit_dofs[j] < held_explicitly.size() && held_explicitly[implicit_dofs[j]])
      shared.push_back(j);
  return shared;
}

template RunState current_run_state(const CDLagrange &, const Problem &);
template RunState current_run_state(const Newmark &, const Problem &);
template RunState current_run_state(const HATICoupling &, const Problem &);
} // namespace hati

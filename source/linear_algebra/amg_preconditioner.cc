#include <hati/linear_algebra/amg_preconditioner.h>

#include <vector>

namespace hati
{
TrilinosWrappers::PreconditionAMG::AdditionalData
structural_amg_data(const std::array<Vector<double>, 3> &translations,
                    const unsigned int n)
{
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic = true;
  data.smoother_sweeps = 2;
  // near null space: the rigid translations of the model, where it has any
  for (const auto &r : translations)
    if (r.size() == n && r.linfty_norm() > 0.)
    {
      std::vector<bool> mode(n);
      for (unsigned int i = 0; i < n; ++i)
        mode[i] = (r[i] != 0.);
      data.constant_modes.push_back(mode);
    }
  return data;
}
} // namespace hati

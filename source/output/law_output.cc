#include <hati/output/law_output.h>

namespace hati
{
LawOutputs::LawOutputs(const std::vector<std::unique_ptr<ForceLaw>> &laws,
                       const LawOutputContext &context)
    : laws(laws)
{
  for (const auto &law : laws)
    if (auto output = law->make_output(context))
      outputs.push_back(std::move(output));
}

const LawSample &LawOutputs::take_sample(const double time, const Vector<double> &V)
{
  current.time = time;
  current.every_step = true;
  sample_force_laws(laws, V, current);
  return current;
}

void LawOutputs::add_step(const LawSample &sample, const double dt)
{
  for (const auto &output : outputs)
    output->add_step(sample, dt);
}

void LawOutputs::finish(SummaryEntries &summary,
                        std::ostream &out,
                        const LawOutputTimes &times)
{
  for (const auto &output : outputs)
    output->finish(summary, out, times);
}
} // namespace hati

#include <hati/output/acceleration_peaks.h>
#include <hati/output/postprocessor.h>

namespace hati
{
const Registry<PostprocessorFactory> &postprocessor_registry()
{
  // one entry per post-processor: name, documentation, parameters, factory
  static const Registry<PostprocessorFactory> registry(
      "post-processor",
      {{"absolute accelerations",
        "largest absolute acceleration of every monitor point "
        "(max_absolute_acceleration)",
        {},
        AccelerationPeaks::create}});
  return registry;
}
} // namespace hati

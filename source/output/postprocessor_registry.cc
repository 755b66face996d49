#include <hati/output/acceleration_peaks.h>
#include <hati/output/postprocessor.h>

namespace hati
{
const Registry<PostprocessorFactory> &postprocessor_registry()
{
  // one line per post-processor: name, documentation, parameters, factory
  static const Registry<PostprocessorFactory> registry = []
  {
    Registry<PostprocessorFactory> r("post-processor");
    r.add({"absolute accelerations",
           "largest absolute acceleration of every monitor point "
           "(max_absolute_acceleration)",
           {},
           AccelerationPeaks::create});
    return r;
  }();
  return registry;
}
} // namespace hati

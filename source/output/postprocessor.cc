#include <hati/output/acceleration_peaks.h>
#include <hati/output/postprocessor.h>
#include <hati/output/reaction_peaks.h>
#include <hati/output/response_spectra.h>

namespace hati
{
const Registry<PostprocessorFactory> &postprocessor_registry()
{
  // one line per post-processor; each class gives its own entry
  static const Registry<PostprocessorFactory> registry("post-processor",
                                                       {AccelerationPeaks::registration(),
                                                        ResponseSpectra::registration(),
                                                        ReactionPeaks::registration()});
  return registry;
}
} // namespace hati

#include <hati/model/bridge_crane.h>
#include <hati/model/continuum.h>
#include <hati/model/frame.h>
#include <hati/model/frame_parser.h>
#include <hati/model/model.h>
#include <hati/model/point_mass.h>

namespace hati
{
const Registry<ModelFactory> &model_registry()
{
  // one line per model: name (Model/Type), subsection, documentation
  static const Registry<ModelFactory> registry = []
  {
    Registry<ModelFactory> r("Model/Type");
    add_model<PointMass>(
        r, "point mass", "Point mass", "'point mass' (rigid, 3 DoFs: the bouncing ball)");
    add_model<Bar>(r, "bar", "Bar", "'bar' (1D elastic bar)");
    add_model<Solid>(r, "solid", "Solid", "'solid' (3D elastic prism)");
    add_model<FrameParameters>(r,
                               "frame",
                               "Frame",
                               "'frame' (3D beam frame)",
                               [](const FrameParameters &p)
                               { return std::make_unique<Frame>(p.description); });
    add_model<BridgeCrane>(r,
                           "bridge crane",
                           "Bridge crane",
                           "'bridge crane' (a frame generated from the Bridge crane "
                           "subsection)");
    return r;
  }();
  return registry;
}
} // namespace hati

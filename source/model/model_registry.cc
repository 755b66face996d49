#include <deal.II/base/utilities.h>

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

void declare_model_parameters(ParameterHandler &prm)
{
  const auto &models = model_registry();
  prm.enter_subsection("Model");
  prm.declare_entry("Type",
                    "point mass",
                    Patterns::Selection(models.selection()),
                    "Which model to build: " + models.join(", ", " or ", true) + ".");
  models.declare_parameters(prm);
  prm.enter_subsection("Decomposition");
  DecompositionParameters::declare_parameters(prm);
  prm.leave_subsection();
  prm.leave_subsection();
  CommonModelParameters::declare_parameters(prm);
}

std::unique_ptr<Model> create_model(ParameterHandler &prm)
{
  prm.enter_subsection("Model");
  const std::string type = prm.get("Type");
  std::unique_ptr<Model> model = model_registry().get(type).create(prm);
  prm.leave_subsection();
  prm.enter_subsection("Loading");
  const bool excited_members = !Utilities::trim(prm.get("Excited members")).empty();
  prm.leave_subsection();
  AssertThrow(!excited_members || model->has_members(),
              ExcMessage("Loading/Excited members: only frame models have members; "
                         "leave it empty for Model/Type = " +
                         type));
  return model;
}
} // namespace hati

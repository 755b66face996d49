#include <hati/run/analysis_registry.h>

namespace hati
{
const Registry<AnalysisRunner> &analysis_registry()
{
  static const Registry<AnalysisRunner> registry = []
  {
    Registry<AnalysisRunner> r("Analysis/Type");
    r.add({"transient",
           "transient: time history with the Time integration method",
           {},
           run_transient_analysis});
    r.add({"static",
           "static: K U = F_ext(0) (gravity, nodal loads)",
           {},
           run_static_analysis});
    r.add({"modal",
           "modal: the lowest natural frequencies and mode shapes (modes.csv, mode "
           "shapes in VTU).",
           {},
           run_modal_analysis});
    return r;
  }();
  return registry;
}

const Registry<AnalysisRunner> &method_registry()
{
  static const Registry<AnalysisRunner> registry = []
  {
    Registry<AnalysisRunner> r("Time integration/Method");
    r.add({"CD-Lagrange",
           "CD-Lagrange: explicit event-capturing central differences with "
           "velocity-level Lagrange multipliers (algorithms.md A1-A7, with Rayleigh "
           "damping).",
           {},
           run_cd_lagrange});
    r.add({"event-driven",
           "event-driven: CVODE between impacts, impacts located by root finding, "
           "Newton's restitution law at each event (reference for small rigid "
           "systems).",
           {},
           run_event_driven});
    r.add({"Newmark",
           "Newmark: implicit average acceleration (algorithms.md N1-N3, Trilinos), "
           "for models without contacts; Time step is then DT.",
           {},
           run_newmark});
    r.add({"HATI",
           "HATI: heterogeneous asynchronous coupling (algorithms.md G1-G4, G3'): "
           "CD-Lagrange on the Model/Decomposition explicit subdomain with the Time "
           "step dt, Newmark on the rest with DT = m dt (Time integration/HATI/Time "
           "step ratio).",
           {},
           run_hati});
    return r;
  }();
  return registry;
}
} // namespace hati

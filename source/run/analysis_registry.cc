#include <hati/run/analysis_registry.h>

namespace hati
{
const Registry<AnalysisRunner> &analysis_registry()
{
  static const Registry<AnalysisRunner> registry(
      "Analysis/Type",
      {{"transient",
        "transient: time history with the Time integration method",
        {},
        run_transient_analysis},
       {"static",
        "static: K U = F_ext(0) (gravity, nodal loads)",
        {},
        run_static_analysis},
       {"modal",
        "modal: the lowest natural frequencies and mode shapes (modes.csv, mode "
        "shapes in VTU).",
        {},
        run_modal_analysis},
       {"response spectrum",
        "response spectrum: the modal (response-spectrum) analysis of the linearised "
        "model against subsection Design spectrum, combined as subsection Response "
        "spectrum says (response_spectrum.csv, response_spectrum_modes.csv).",
        {},
        run_response_spectrum_analysis}});
  return registry;
}

const Registry<AnalysisRunner> &method_registry()
{
  static const Registry<AnalysisRunner> registry(
      "Time integration/Method",
      {{"CD-Lagrange",
        "CD-Lagrange: explicit event-capturing central differences with "
        "velocity-level Lagrange multipliers (algorithms.md A1-A7, with Rayleigh "
        "damping).",
        {},
        run_cd_lagrange},
       {"event-driven",
        "event-driven: CVODE between impacts, impacts located by root finding, "
        "Newton's restitution law at each event (reference for small rigid "
        "systems).",
        {},
        run_event_driven},
       {"Newmark",
        "Newmark: implicit average acceleration (algorithms.md N1-N3, Trilinos), "
        "for models without contacts; Time step is then DT.",
        {},
        run_newmark},
       {"HATI",
        "HATI: heterogeneous asynchronous coupling (algorithms.md G1-G4, G3'): "
        "CD-Lagrange on the Model/Decomposition explicit subdomain with the Time "
        "step dt, Newmark on the rest with DT = m dt (Time integration/HATI/Time "
        "step ratio).",
        {},
        run_hati}});
  return registry;
}
} // namespace hati

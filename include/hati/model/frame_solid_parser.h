#ifndef hati_model_frame_solid_parser_h
#define hati_model_frame_solid_parser_h

#include <deal.II/base/parameter_handler.h>

#include <hati/model/solid_description.h>

namespace hati
{
using namespace dealii;

/**
 * Declare the `Model/Frame` entries of solids and their links to the beams:
 * `Solids`, `Solid element degree`, `Ties`, `Solid supports`, `Rigid links`,
 * `Solid cuts` (doc/user_guide.md "Solids and ties"); the caller enters the
 * subsection.
 */
void declare_solid_entries(ParameterHandler &prm);

/**
 * Parse those entries into @p solids, checking the syntax and the values of
 * every item (one-line errors naming the entry and the item); names are
 * checked against the rest of the frame by FrameDescription::validate().
 */
void parse_solid_entries(ParameterHandler &prm, SolidDescription &solids);

/**
 * The `Model/Frame/Monitor nodes` entry @p text: items separated by `;`,
 * each either plain node names `node, node, ...` (into @p nodes) or a solid
 * monitor `name: solid, x, y, z` (m, global axes; into @p solids.monitors,
 * the solid's node nearest to that point). Throws one-line errors naming the
 * entry and the item.
 */
void parse_monitor_entry(const std::string &text,
                         std::vector<std::string> &nodes,
                         SolidDescription &solids);
} // namespace hati

#endif

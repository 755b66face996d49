#ifndef hati_model_frame_parser_h
#define hati_model_frame_parser_h

#include <deal.II/base/parameter_handler.h>

#include <hati/model/frame_description.h>

#include <string>

namespace hati
{
/**
 * Largest number of elements of one member (-): Model/Frame/Members and the
 * bridge crane's Element size.
 */
constexpr double max_elements_per_member = 1e7;

/**
 * The `Model/Frame` subsection: a frame described in a small list language,
 * each entry a list of items `name: value, value, ...; ...` (doc/user_guide.md
 * "Frames"), with the members and named nodes of an optional Gmsh mesh file
 * merged in (gmsh_frame_reader.h). parse_parameters() checks the syntax and
 * the values of every item, naming the entry and the item; the description
 * as a whole is checked by FrameDescription::validate() (called by Frame).
 */
struct FrameParameters
{
  /** Declare the entries in the current subsection (the caller enters it). */
  static void declare_parameters(ParameterHandler &prm);
  /** Parse the entries of the current subsection into description. */
  void parse_parameters(ParameterHandler &prm);

  /** The frame the entries describe. */
  FrameDescription description;
};

/**
 * A cross-section from the Sections syntax after the name, @p text =
 * 'rectangle, b, h' | 'box, b, h, t_web, t_flange' | 'general, A, Iy, Iz, J,
 * Asy, Asz' (m, m^2, m^4; frame_element.h); @p where (the entry and item)
 * starts every error message.
 */
FrameSection parse_frame_section(const std::string &text, const std::string &where);
} // namespace hati

#endif

#ifndef hati_output_plot_script_h
#define hati_output_plot_script_h

#include <string>

namespace hati
{
/**
 * Run `python3 scripts/<script> <folder>` (the script next to the
 * executable's build folder, else in the current directory; the system's
 * /usr/bin/python3 before another one on the PATH), its output in
 * `<folder>/<script stem>.log` (never through a link). Returns the warning
 * if it could not draw, empty if it did.
 */
std::string run_plot_script(const std::string &script, const std::string &folder);
} // namespace hati

#endif

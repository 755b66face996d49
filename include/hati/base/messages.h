#ifndef hati_base_messages_h
#define hati_base_messages_h

#include <exception>
#include <string>

namespace hati
{
/** The message of an exception on one line, without deal.II's banner. */
std::string one_line_message(const std::exception &e);
} // namespace hati

#endif

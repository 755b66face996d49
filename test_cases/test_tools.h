#ifndef hati_test_cases_test_tools_h
#define hati_test_cases_test_tools_h

// Helpers of the unit tests: every check prints its value, reference and
// tolerance, and main() returns finish() (non-zero if a check failed).

#include <cmath>
#include <exception>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace hati_test
{
/** Number of failed checks. */
inline int failures = 0;

/** A condition, printed as ok or FAIL. */
inline void expect(const bool ok, const std::string &what)
{
  std::cout << (ok ? "ok   " : "FAIL ") << what << std::endl;
  failures += ok ? 0 : 1;
}

/** |value - reference| <= tolerance with a finite value, printed. */
inline void check(const std::string &what,
                  const double value,
                  const double reference,
                  const double tolerance)
{
  const bool ok = std::abs(value - reference) <= tolerance && std::isfinite(value);
  std::cout << (ok ? "ok   " : "FAIL ") << std::setprecision(12) << what << ": value "
            << value << ", reference " << reference << ", tolerance " << tolerance
            << std::endl;
  failures += ok ? 0 : 1;
}

/**
 * The message of an exception on one line: deal.II's "Additional
 * information" only (without its banner and stack trace), every run of
 * white space made one blank.
 */
inline std::string message_of(const std::exception &e)
{
  std::string text(e.what());
  const auto begin = text.find("Additional information:");
  if (begin != std::string::npos)
    text = text.substr(begin + 23, text.find("Stacktrace:") - begin - 23);
  std::istringstream in(text);
  std::string word, message;
  while (in >> word)
    message += (message.empty() ? "" : " ") + word;
  return message;
}

/** Print the verdict; the exit code of main(). */
inline int finish()
{
  if (failures == 0)
    std::cout << "all checks passed" << std::endl;
  else
    std::cout << "FAILURES: " << failures << std::endl;
  return failures == 0 ? 0 : 1;
}
} // namespace hati_test

#endif

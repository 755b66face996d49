#ifndef hati_test_cases_test_tools_h
#define hati_test_cases_test_tools_h

// Helpers of the unit tests: every check prints its value, reference and
// tolerance, and each test's function returns finish() (non-zero if a check
// failed). The unit tests are one executable, hati_unit_tests (build time:
// one link, the sources compiled in batches): each test_cases/unit_<name>.cc
// defines its entry with HATI_UNIT_TEST(<name>) inside its own namespace
// hati_unit_<name>, and `hati_unit_tests <name>` runs it
// (test_cases/run_unit_test.cc).

#include <cmath>
#include <exception>
#include <iomanip>
#include <iostream>
#include <map>
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

/** The entry of a unit test: (argc, argv) with argv[0] the test's name. */
using UnitTestFunction = int (*)(int, char **);

/** The unit tests of the executable, by name. */
inline std::map<std::string, UnitTestFunction> &unit_tests()
{
  static std::map<std::string, UnitTestFunction> tests;
  return tests;
}

/** Registers a unit test at static initialisation (HATI_UNIT_TEST). */
struct UnitTestRegistration
{
  UnitTestRegistration(const char *name, const UnitTestFunction function)
  {
    unit_tests()[name] = function;
  }
};
} // namespace hati_test

/**
 * The entry of the unit test @p name, written where main() would be, inside
 * the file's namespace hati_unit_<name>: `HATI_UNIT_TEST(name) { ... return
 * finish(); }` (argc and argv as main's).
 */
#define HATI_UNIT_TEST(name)                                                             \
  int unit_test_main(int argc, char **argv);                                             \
  const hati_test::UnitTestRegistration unit_test_registration(#name, &unit_test_main);  \
  int unit_test_main([[maybe_unused]] int argc, [[maybe_unused]] char **argv)

#endif

// The unit tests' executable: `hati_unit_tests <name> [arguments]` runs the
// test registered by HATI_UNIT_TEST(<name>) in test_cases/unit_<name>.cc and
// returns its exit code (0: every check passed); without a known name it
// lists the tests and returns 2.
#include "test_tools.h"

#include <iostream>

int main(int argc, char **argv)
{
  const auto &tests = hati_test::unit_tests();
  const auto test = argc > 1 ? tests.find(argv[1]) : tests.end();
  if (test == tests.end())
  {
    std::cerr << "usage: hati_unit_tests <name>, one of:";
    for (const auto &entry : tests)
      std::cerr << " " << entry.first;
    std::cerr << std::endl;
    return 2;
  }
  return test->second(argc - 1, argv + 1);
}

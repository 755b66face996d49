#ifndef hati_base_silence_h
#define hati_base_silence_h

#include <iostream>
#include <streambuf>

namespace hati
{
/** std::cout and std::cerr discarded while it lives (a suite's dry runs, its modal and
 * response-spectrum runs). */
class Silence
{
public:
  Silence() : out(std::cout.rdbuf(&null)), err(std::cerr.rdbuf(&null)) {}
  ~Silence()
  {
    std::cout.rdbuf(out);
    std::cerr.rdbuf(err);
  }

private:
  class Null : public std::streambuf
  {
  protected:
    int_type overflow(int_type c) override { return traits_type::not_eof(c); }
  } null;
  std::streambuf *out, *err;
};
} // namespace hati

#endif

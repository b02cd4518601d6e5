#include "contactbench/app/gnuplot_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace contactbench {

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char ch : text)
    quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

std::string gnuplot_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char ch : text)
    quoted += ch == '\'' ? std::string("''") : std::string(1, ch);
  return quoted + "'";
}

std::string gnuplot_number(double value) {
  if (!std::isfinite(value)) return "NaN";
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

bool gnuplot_available() {
  return std::system("command -v gnuplot > /dev/null 2>&1") == 0;
}

}  // namespace contactbench

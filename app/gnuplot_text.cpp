#include "contactbench/app/gnuplot_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include <unistd.h>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"

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

void run_gnuplot(const std::filesystem::path& png, const std::filesystem::path& svg,
                 const std::filesystem::path& drawn, const GnuplotScript& write_script) {
  if (!gnuplot_available())
    throw Error("gnuplot is not installed (Debian: gnuplot-nox), so " + drawn.string() + " was not drawn");
  const std::string suffix = ".partial." + std::to_string(::getpid());
  const std::filesystem::path png_partial = png.empty() ? png : std::filesystem::path(png.string() + suffix);
  const std::filesystem::path svg_partial = svg.empty() ? svg : std::filesystem::path(svg.string() + suffix);
  const std::filesystem::path script =
      (png.empty() ? svg : png).parent_path() / ("." + drawn.filename().string() + ".gp" + suffix);
  const auto absolute = [](const std::filesystem::path& path) {
    return path.empty() ? std::string() : std::filesystem::absolute(path).string();
  };
  write_file_atomically(
      script, [&](std::ostream& out) { write_script(out, absolute(png_partial), absolute(svg_partial)); });
  const int status = std::system(("gnuplot " + shell_quote(script.string()) + " 2>/dev/null").c_str());
  std::filesystem::remove(script);
  if (status != 0) {
    if (!png.empty()) std::filesystem::remove(png_partial);
    if (!svg.empty()) std::filesystem::remove(svg_partial);
    throw Error("gnuplot failed drawing " + drawn.string());
  }
  if (!png.empty()) std::filesystem::rename(png_partial, png);
  if (!svg.empty()) std::filesystem::rename(svg_partial, svg);
}

}  // namespace contactbench

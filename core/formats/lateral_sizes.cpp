#include "contactbench/core/formats/lateral_sizes.hpp"

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// Sizes the caller gives must match the file's to this relative tolerance (TopographyReadOptions).
constexpr Real size_agreement = 1e-6;

}  // namespace

void check_lateral_size(const fs::path& path, long line, std::string_view name, Real value) {
  if (!(std::isfinite(value) && value > 0))
    throw InputError(path, line,
                     std::string(name) + " = " + format_real(value) + " m is not a finite size > 0");
}

void check_agrees(const fs::path& path, long line, std::string_view name, Real from_file,
                  const std::optional<Real>& given) {
  if (!given) return;
  if (!(std::abs(*given - from_file) <= size_agreement * from_file))
    throw InputError(path, line,
                     "the file gives " + std::string(name) + " = " + format_real(from_file) +
                         " m but the caller gave " + std::string(name) + " = " + format_real(*given) +
                         " m; they must agree to 1e-6 relative");
}

}  // namespace contactbench::formats

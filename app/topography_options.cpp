#include "contactbench/app/topography_options.hpp"

#include "contactbench/core/topography_io.hpp"

namespace contactbench {

void TopographyOptions::add_to(CLI::App& command, const std::string& periodic_effect) {
  command
      .add_option("FILE", file,
                  "topography: the project's format, an interferometer or Gwyddion text export, or a plain "
                  "matrix of heights in metres (then --size is needed)")
      ->required();
  command.add_option("--size", size, "lateral size along x [m] (for files that carry none)");
  command.add_option("--size-y", size_y, "lateral size along y [m] (default: square pixels)");
  command.add_flag("--periodic", periodic, "treat the surface as periodic (" + periodic_effect + ")");
}

Surface TopographyOptions::read() const {
  TopographyReadOptions options;
  options.lx = size;
  options.ly = size_y;
  if (periodic) options.periodic = true;
  return read_topography(file, options);
}

}  // namespace contactbench

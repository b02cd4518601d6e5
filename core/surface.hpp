// A rough surface: heights on a grid (docs/theory.md section 0).
#pragma once

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

class Surface {
 public:
  // Throws Error unless the grid is valid, heights is ny x nx and every height is finite.
  Surface(Grid grid, HeightMap heights);

  const Grid& grid() const { return grid_; }
  const HeightMap& heights() const { return heights_; }
  Index nx() const { return grid_.nx; }
  Index ny() const { return grid_.ny; }

  Real mean_height() const { return heights_.mean(); }
  // Sq: root-mean-square height about the mean (no detrending) [m].
  Real rms_height() const;

  // The same heights with the mean removed (docs/theory.md section 0: heights have zero mean).
  Surface centred() const;
  Surface with_periodic(bool periodic) const;

 private:
  Grid grid_;
  HeightMap heights_;
};

}  // namespace contactbench

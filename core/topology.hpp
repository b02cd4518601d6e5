// Which grid points touch: 4- or 8-connectivity and periodic wrap-around (docs/theory.md section 3).
#pragma once

#include <string>

namespace contactbench {

enum class Connectivity { four = 4, eight = 8 };

struct Topology {
  Connectivity connectivity = Connectivity::four;
  bool wrap_x = false;  // column 0 touches column nx-1 (a surface periodic in x)
  bool wrap_y = false;  // row 0 touches row ny-1 (a surface periodic in y)

  // The topology of a surface that is periodic in both directions, or in neither.
  static Topology for_surface(Connectivity connectivity, bool periodic) {
    return {connectivity, periodic, periodic};
  }
};

// "4-connectivity, wrap x and y" and the like, for outputs that must say what was used.
inline std::string describe(const Topology& t) {
  std::string text = t.connectivity == Connectivity::four ? "4-connectivity" : "8-connectivity";
  if (t.wrap_x && t.wrap_y) return text + ", periodic in x and y";
  if (t.wrap_x) return text + ", periodic in x";
  if (t.wrap_y) return text + ", periodic in y";
  return text + ", not periodic";
}

}  // namespace contactbench

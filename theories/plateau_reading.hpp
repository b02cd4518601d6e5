// Which plateau model a plateau computation reads (docs/theory.md section 12.8): the seed paper's or the
// project's Hertz-consistent variant. One definition for the capped curves (plateau_capped.hpp) and the
// distributions at a load (plateau_at_load.hpp).
#pragma once

namespace contactbench {

enum class PlateauReading {
  // Wang, Liang and Yan: the spots are the clusters of {h > z}, their area the bearing area A_c(z), the
  // elastic load E(z).
  paper,
  // The project's variant: the same clusters at its own level, each spot's area half its bearing area, the
  // elastic load E(z)/sqrt(2) (with a hardness: the area max(A_c/2, P/H)).
  hertz,
};

}  // namespace contactbench

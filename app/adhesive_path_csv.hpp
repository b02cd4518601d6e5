// The approach–retract path of `contactbench bem --approach-retract` (bem/adhesive_path.hpp) as CSV: one row
// per state, the jumps, the pull-off and the cycle's energy balance as comment lines (docs/theory.md 10.7).
#pragma once

#include <ostream>

#include "contactbench/app/provenance.hpp"
#include "contactbench/bem/adhesive_path.hpp"

namespace contactbench {

// Loads as P/(E* A0) with `modulus` = E* [Pa]; `points` is the number of nodes (the area fractions' A0).
void write_adhesive_path_csv(std::ostream& out, const AdhesivePath& path, Real modulus, Index points,
                             const Provenance& provenance);

}  // namespace contactbench

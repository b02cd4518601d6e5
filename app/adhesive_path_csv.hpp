// The approach–retract path of `contactbench bem --approach-retract` or of a scene's `approach_retract`
// (bem/adhesive_path.hpp) as CSV: one row per state, the jumps, the pull-off and the cycle's energy balance
// as comment lines (docs/theory.md 10.7).
#pragma once

#include <ostream>
#include <string>

#include "contactbench/app/provenance.hpp"
#include "contactbench/bem/adhesive_path.hpp"

namespace contactbench {

// Loads as P/(E* A0) with `modulus` = E* [Pa]; `points` is the number of nodes (the area fractions' A0).
// `what` opens the first line ("contactbench bem approach-retract path"), the provenance stamps it.
void write_adhesive_path_csv(std::ostream& out, const AdhesivePath& path, Real modulus, Index points,
                             const std::string& what, const Provenance& provenance);

// The column line of that CSV, by which `contactbench plot` knows one.
inline constexpr const char* kAdhesivePathColumns =
    "leg,separation,load,adhesive_load,contact_fraction,attractive_fraction,mean_gap,energy,iterations,"
    "converged";

}  // namespace contactbench

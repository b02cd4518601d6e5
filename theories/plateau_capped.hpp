// The plateau models with a yield limit: the PROJECT's extension of the multi-plateaus model (Wang, Liang and
// Yan) and of the project's Hertz-consistent plateaus, not the paper's model (docs/theory.md section 11.2).
//
// A plateau's mean pressure cannot exceed the hardness H. The model's plateaus at one level are all alike
// (N(z) cylinders of one radius), so the cap holds for their sum: the load may not exceed the ceiling C(z),
// H A_c(z) for the paper's plateaus. Lowering the flat adds the elastic increment dE of the model until the
// ceiling is reached; a plateau at the ceiling flows and carries C(z); plastic flow is permanent, so a later
// elastic increment starts from the reduced load. That is, with E(z) the elastic model's load,
//   P(z) = E(z) + min(0, min over z' >= z of [C(z') - E(z')])            (the sum with its cap)
// which is E(z) while the ceiling is never reached and H A_c(z) as H -> 0 (rigid-perfectly plastic: A = P/H).
//
// Hertz-consistent variant: elastic load E/sqrt(2) and area A_c/2 (theories/plateau_hertz.hpp); a plateau
// whose Hertz area would carry more than H spreads plastically to area P/H, at most its bearing area A_c (the
// truncated paraboloid, the rigid-plastic limit); the ceiling of the load is H A_c. Area = max(A_c/2, P/H).
#pragma once

#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/theories/plastic_curve.hpp"
#include "contactbench/theories/plateau_reading.hpp"

namespace contactbench {

// The capped curve at requested loads P/(E* A0) (finite, > 0, ascending, each below hardness_over_estar =
// H/E*; kNoHardness gives the elastic model's curve). paper_model = plateau_model(sweep). The load is read
// exactly between levels as in plateau_curve_at_loads. Columns: paper reading, the plateaus are all alike, so
// a load is either wholly plastic (plastic area fraction = A/A0, load fraction 1: the level step it lies in
// ends on the cap, the mean pressure is within one step's area of H) or wholly elastic (0, 0); Hertz reading,
// plastic when the area is P/H. method "plateau_capped" or "plateau_hertz_capped".
PlasticCurve plateau_capped_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& paper_model,
                                           std::span<const Real> loads, Real hardness_over_estar,
                                           PlateauReading reading);

}  // namespace contactbench

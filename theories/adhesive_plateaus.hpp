// Adhesive plateaus: the PROJECT's adhesive readings of the multi-plateaus model, not the paper's
// (docs/theory.md section 10.6). The paper's model (theories/plateau_model.hpp) makes the contact at a level
// z N(z) flat punches of one radius r_b = sqrt(A_c A0/(π N)); the Hertz-consistent variant
// (theories/plateau_hertz.hpp) makes them paraboloid tips of contact radius r_b/√2. With a work of adhesion
// w, a spot of contact radius a carries, at that radius, its non-adhesive load less
//   √(8π w E* a³),
// exactly for both shapes: Kendall's adhesive flat punch (K. Kendall, J. Phys. D 4, 1186, 1971:
// P = 2E* a δ − √(8π w E* a³)) and JKR's paraboloid (Johnson, Kendall & Roberts 1971: P = P_Hertz(a) −
// √(8π w E* a³), since √(6π w K a³) = √(8π w E* a³) with K = 4E*/3). So at every level
//   P_adh(z) = P(z) − N √(8π w E* a³)/(E* A0),   A unchanged,
// with a = r_b (paper's punches) or r_b/√2 and P(z)/√2, A_c/2 (Hertz-consistent). Like the plateau model, the
// spots do not interact, and JKR needs w alone: any law is accepted through its w.
// Load control: the approach path, from the top level down: a load takes the first level whose adhesive load
// reaches it (inside a level's interval the separation is linear, as the plateau model's; a load that a
// level's new spots jump over takes that level: the flat snaps in).
#pragma once

#include <span>
#include <string_view>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

enum class AdhesivePlateauSpot {
  kendall_punch,   // the paper's plateaus as adhesive flat punches
  jkr_paraboloid,  // the Hertz-consistent plateaus as JKR contacts
};

// The curve at the requested loads P/(E* A0) (finite, > 0, ascending) from the sweep and the paper's model on
// it (model = plateau_model(sweep)), for E* [Pa] and w [J/m^2]. Loads beyond the last level get NaN, and the
// parameters say from which load. Method "plateau_kendall" or "plateau_hertz_jkr".
LoadAreaCurve adhesive_plateau_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& model, Real estar,
                                              Real work, AdhesivePlateauSpot spot,
                                              std::span<const Real> loads);

}  // namespace contactbench

// Kogut-Etsion's elastic-plastic summits (L. Kogut and I. Etsion, "Elastic-plastic contact analysis of a
// sphere and a rigid flat", J. Appl. Mech. 69, 657-662, 2002; on rough surfaces: L. Kogut and I. Etsion,
// Tribol. Trans. 46, 383-390, 2003; docs/theory.md section 11.1). Finite-element fits of a sphere's contact
// beyond the critical interference wc of Chang-Etsion-Bogy (theories/chang_etsion_bogy.hpp), in units of
// Pc = (4/3) E* R^(1/2) wc^(3/2) (= (2/3) K H pi R wc) and Ac = pi R wc:
//   1 <= w/wc <= 6:    P/Pc = 1.03 (w/wc)^1.425,  A/Ac = 0.93 (w/wc)^1.136   (plastic core under an elastic
//                                                                            surface: no plastic area)
//   6 <= w/wc <= 110:  P/Pc = 1.40 (w/wc)^1.263,  A/Ac = 0.94 (w/wc)^1.146   (the plastic zone reaches the
//                                                                            surface: counted plastic)
//   w/wc >= 110:       A = 2 pi R w,  P = H A                                 (fully plastic)
// The fits are not continuous at 1, 6 and 110: the jumps are the published fits' own (tests measure them).
// Its rigid-plastic limit is A/A0 = P/(H A0), the BEM's cap.
#pragma once

#include <span>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/theories/plastic_summits.hpp"

namespace contactbench {

// The law of one summit of radius R (h = H/E*; kNoHardness: Hertz).
AsperityLaw kogut_etsion_law(Real radius, Real hardness_over_estar, Real poisson_ratio);

// The curve on McCool's GW summits (method "kogut_etsion"), plastic columns: summits beyond 6 wc.
PlasticCurve kogut_etsion_curve(const SpectralMoments& moments, std::span<const Real> loads,
                                Real hardness_over_estar, Real poisson_ratio, Real nominal_area);

}  // namespace contactbench

// What a boundary-element solution says about the contact (docs/theory.md section 6): real contact area by
// node count and perimeter-corrected, the number of contact spots, the mean gap and the largest pressure.
#pragma once

#include <numbers>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/labelling.hpp"

namespace contactbench {

struct ContactStatistics {
  Real area_fraction = 0;            // contact nodes / all nodes
  Real area_fraction_corrected = 0;  // less the perimeter term of Yastrebov, Anciaux and Molinari (2017)
  Index spots = 0;                   // connected contact regions (labeller's topology)
  Real mean_gap = 0;                 // [m], over all nodes (0 on the contact set)
  Real max_pressure = 0;             // [Pa]
  // Non-periodic solves only (0 when the topology wraps): the shares of the contact nodes and of the load in
  // the outer ring of kEdgeRingPixels, where a finite patch's edge acts like a punch's (docs/studies.md
  // "Edges of non-periodic records"; the ring holds 4 w (n - w) / n^2 of the nodes, 29 % on 256 points).
  Real edge_contact_share = 0;
  Real edge_load_share = 0;
};

// The ring of the edge shares, in pixels: the width the issue measured the artefact in (matrix-2 at 2e-2:
// 45 % in contact there against 17.5 % inside), and where scripts/studies/edges.py finds it concentrated.
inline constexpr Index kEdgeRingPixels = 20;

// The perimeter correction (Yastrebov, Anciaux, Molinari, Tribol. Int. 2017): counting contact nodes
// overestimates the area by a band along the contact's edge; with S the length of the boundary between
// contact and non-contact nodes (4-neighbour edges, across the periodic seams when the topology wraps),
//   A_corr = A_nodes - ((pi - 1 + ln 2)/24) S dx,
// which on rectangular pixels is ((pi - 1 + ln 2)/24) dx dy per boundary edge.
inline constexpr Real kPerimeterCorrection = (std::numbers::pi - 1 + std::numbers::ln2) / 24;

// `labeller` decides connectivity and periodicity of the spot count (and keeps its buffers between loads).
ContactStatistics contact_statistics(const ContactSolution& solution, Labeller& labeller);

}  // namespace contactbench

// The distributions at a scene's reference load (`distributions = { load = ..., bins = ... }`,
// scenes/README.md; issue 36): the BEM's histograms of the pressure over the contact nodes and of the gap
// outside contact, and the sizes of its contact clusters, each written as a CSV beside Persson's P(sigma)
// (theories/persson_gap.hpp). Measured once, at that load, only when the scene asks.
#pragma once

#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "contactbench/core/labelling.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/topology.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/summit_gap_density.hpp"

namespace contactbench {

// `distributions = { load = <P/(E* A0)>, bins = <count> }`: the load must be one of the scene's loads.
struct DistributionsSpec {
  Real load = 0;   // P/(E* A0)
  Index bins = 0;  // bins of each histogram
};

// A histogram: bins [edges[i], edges[i+1]) with their node counts and a density (its normalisation is the
// quantity's, below).
struct Histogram {
  std::vector<Real> edges;    // bins + 1, increasing
  std::vector<Index> counts;  // per bin
  std::vector<Real> density;  // per bin
  Real width(std::size_t i) const { return edges[i + 1] - edges[i]; }
  Real centre(std::size_t i) const { return (edges[i] + edges[i + 1]) / 2; }
};

// Pressure over the contact nodes (p > 0, the solver's contact set): uniform bins on [0, max p], the density
// P(sigma) = count / (N width) [1/Pa] over all N nodes, so that sum P dsigma = contact nodes / N = A/A0 (the
// node count) and sum sigma P dsigma = mean pressure (up to the bins' width), as Persson's P(sigma) of the
// same load (its delta at sigma = 0, the rest 1 - A/A0, left out). Empty counts when nothing touches.
Histogram pressure_histogram(const HeightMap& pressure, Index bins);

// Gap outside the contact (p <= 0): uniform bins on [0, max g], density P(g) = count / (N width) [1/m] over
// all N nodes: sum P dg = 1 - A/A0 (the contact set, at g = 0, is the delta the histogram leaves out) and
// sum g P dg = u-bar, the mean gap over the whole surface (up to the bins' width).
Histogram gap_histogram(const HeightMap& pressure, const HeightMap& gap, Index bins);

// Cluster sizes in nodes (core/labelling.hpp areas) on `bins` logarithmic bins from 1 to past the largest
// (edges 1 * r^i, r = (largest + 1)^(1/bins)); density = count / width [1/node], the number density
// n(s). Sum of counts = spots.
Histogram patch_size_histogram(const std::vector<Index>& areas, Index bins);

// Counts of `values` on the bins of `edges` ([edges[i], edges[i+1]), the last bin closed at its top), density
// = count / (all_nodes width); values outside the edges are counted in `below` and `above`.
struct BinnedValues {
  Histogram histogram;
  Index below = 0, above = 0;
};
BinnedValues bin_on_edges(const std::vector<Real>& edges, const std::vector<Real>& values, Index all_nodes);

// The number of integers in [low, high): the sizes (in nodes) a patch-size bin can hold.
Index integers_in(Real low, Real high);

// What a BEM stage measures at the reference load from the fields, before it drops them.
struct MeasuredDistributions {
  Index points = 0;          // nodes N
  Index contact_points = 0;  // nodes with p > 0
  Real mean_pressure = 0;    // [Pa], the repulsive pressure over all nodes
  Real mean_gap = 0;         // [m], over all nodes
  Real pixel_area = 0;       // dx dy [m^2]
  Histogram pressure, gap;
  std::map<int, std::vector<Index>> cluster_areas;  // by connectivity: every cluster's nodes
};

// From one solved load's fields; `labellers` by connectivity (their topology counts the clusters).
MeasuredDistributions measure_distributions(const HeightMap& pressure, const HeightMap& gap, Real pixel_area,
                                            Index bins, std::map<int, Labeller>& labellers);

// The measured distributions of one BEM load, ready to write.
struct LoadDistributions {
  Real load = 0;             // P/(E* A0), the scene's reference load
  Real estar = 0;            // [Pa]
  Real q3_integral = 0;      // int q^3 C(q) dq of the surface (theories/persson.hpp): Persson's P(sigma)
  Real pixel_area = 0;       // dx dy [m^2]: the patch sizes in m^2
  Index points = 0;          // nodes N
  Index contact_points = 0;  // nodes with p > 0
  Real mean_pressure = 0;    // [Pa], over all nodes
  Real mean_gap = 0;         // [m], over all nodes
  int connectivity = 4;      // of the clusters
  Histogram pressure, gap, patch_sizes;

  // The plateau models at the same load (theories/plateau_at_load.hpp; docs/theory.md 12.8), their gaps and
  // spot areas binned on the BEM's edges. `given` false: `note` says why (no cut level at that load).
  struct Plateau {
    bool given = false;
    std::string note;
    Real level = 0, area_fraction = 0;
    Index points = 0;
    BinnedValues gap, patch_sizes;
  };
  Plateau plateau, plateau_hertz;
  // GW-McCool's undeformed-gap density at the same load (theories/summit_gap_density.hpp), or why not.
  std::optional<SummitGap> summit;
  std::string summit_note;
};

// Fills the theories of `d` (its load and BEM histograms set) on the scene's surface: the plateau models on
// its exact sweep with `topology` (the BEM's connectivity), GW-McCool from its moments. A theory that cannot
// answer at the load is marked with its reason, never dropped silently.
void add_distribution_theories(LoadDistributions& d, const Surface& surface, const Topology& topology);

// The power-law fit's range for the patch sizes (docs/theory.md 12.8): sizes of at least 2 nodes (single-node
// patches are the pixel, not the surface) and bins with at least 5 patches (a relative counting error
// 1/sqrt(5) = 45 % or less).
inline constexpr Real kPowerLawMinSize = 2;
inline constexpr Index kPowerLawMinCount = 5;

// `origin`: the stamp line (command, commit, date, threads, machine) each file starts with.
void write_pressure_distribution_csv(std::ostream& out, const LoadDistributions& d,
                                     const std::string& origin);
void write_gap_distribution_csv(std::ostream& out, const LoadDistributions& d, const std::string& origin);
void write_patch_sizes_csv(std::ostream& out, const LoadDistributions& d, const std::string& origin);

}  // namespace contactbench

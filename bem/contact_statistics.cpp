#include "contactbench/bem/contact_statistics.hpp"

namespace contactbench {

namespace {

// Boundary edges between contact and non-contact nodes, 4-neighbours, wrapping where the topology does.
Index boundary_edges(const BinaryMap& contact, const Topology& topology) {
  const Index nx = contact.cols(), ny = contact.rows();
  Index edges = 0;
  if (nx > 1) {
    edges += (contact.rightCols(nx - 1) != contact.leftCols(nx - 1)).count();
    if (topology.wrap_x) edges += (contact.col(0) != contact.col(nx - 1)).count();
  }
  if (ny > 1) {
    edges += (contact.bottomRows(ny - 1) != contact.topRows(ny - 1)).count();
    if (topology.wrap_y) edges += (contact.row(0) != contact.row(ny - 1)).count();
  }
  return edges;
}

}  // namespace

ContactStatistics contact_statistics(const ContactSolution& solution, Labeller& labeller) {
  const BinaryMap contact = (solution.pressure > 0).cast<std::uint8_t>();
  const Real nodes = static_cast<Real>(contact.size());
  ContactStatistics s;
  const Index in_contact = solution.contact_points;
  s.area_fraction = static_cast<Real>(in_contact) / nodes;
  s.area_fraction_corrected =
      (static_cast<Real>(in_contact) -
       kPerimeterCorrection * static_cast<Real>(boundary_edges(contact, labeller.topology()))) /
      nodes;
  s.spots = labeller.label(contact).count;
  s.mean_gap = solution.gap.mean();
  s.max_pressure = solution.pressure.maxCoeff();
  const Topology& topology = labeller.topology();
  const Index nx = contact.cols(), ny = contact.rows();
  const Index ring = kEdgeRingPixels;
  if (!topology.wrap_x && !topology.wrap_y && nx > 2 * ring && ny > 2 * ring) {
    // All less the interior block.
    const auto inside_contact = contact.block(ring, ring, ny - 2 * ring, nx - 2 * ring);
    const auto inside_pressure = solution.pressure.block(ring, ring, ny - 2 * ring, nx - 2 * ring);
    const Real all_pressure = solution.pressure.sum();
    if (in_contact > 0)
      s.edge_contact_share =
          static_cast<Real>(in_contact - inside_contact.cast<Index>().sum()) / static_cast<Real>(in_contact);
    if (all_pressure > 0) s.edge_load_share = (all_pressure - inside_pressure.sum()) / all_pressure;
  }
  return s;
}

}  // namespace contactbench

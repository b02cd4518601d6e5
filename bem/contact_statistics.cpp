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
  return s;
}

}  // namespace contactbench

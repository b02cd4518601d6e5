#include "contactbench/app/distributions_csv.hpp"

#include <algorithm>
#include <cmath>

#include "contactbench/app/json_writer.hpp"
#include "contactbench/theories/persson_gap.hpp"

namespace contactbench {

namespace {

// Uniform bins on [0, largest]; a value at the top edge goes to the last bin.
Histogram uniform_histogram(const std::vector<Real>& values, Real largest, Index bins, Index all_nodes) {
  Histogram h;
  const Real top = largest > 0 ? largest : 1;
  for (Index i = 0; i <= bins; ++i)
    h.edges.push_back(top * static_cast<Real>(i) / static_cast<Real>(bins));
  h.edges.back() = top;
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (const Real v : values) {
    const auto bin = std::min<Index>(bins - 1, static_cast<Index>(v / top * static_cast<Real>(bins)));
    ++h.counts[static_cast<std::size_t>(std::max<Index>(0, bin))];
  }
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    h.density.push_back(static_cast<Real>(h.counts[i]) / (static_cast<Real>(all_nodes) * h.width(i)));
  return h;
}

std::string number(Real value) {
  return json_number(value);
}

}  // namespace

Histogram pressure_histogram(const HeightMap& pressure, Index bins) {
  std::vector<Real> values;
  Real largest = 0;
  for (Index i = 0; i < pressure.size(); ++i)
    if (const Real p = pressure.data()[i]; p > 0) {
      values.push_back(p);
      largest = std::max(largest, p);
    }
  return uniform_histogram(values, largest, bins, pressure.size());
}

Histogram gap_histogram(const HeightMap& pressure, const HeightMap& gap, Index bins) {
  std::vector<Real> values;
  Real largest = 0;
  for (Index i = 0; i < gap.size(); ++i)
    if (pressure.data()[i] <= 0) {
      const Real g = std::max<Real>(0, gap.data()[i]);  // the solver's gap is >= 0 (to its round-off)
      values.push_back(g);
      largest = std::max(largest, g);
    }
  return uniform_histogram(values, largest, bins, gap.size());
}

Histogram patch_size_histogram(const std::vector<Index>& areas, Index bins) {
  Histogram h;
  const Index largest = areas.empty() ? 1 : *std::max_element(areas.begin(), areas.end());
  const Real ratio = std::pow(static_cast<Real>(largest + 1), 1 / static_cast<Real>(bins));
  for (Index i = 0; i <= bins; ++i)
    h.edges.push_back(std::pow(ratio, static_cast<Real>(i)));
  h.edges.front() = 1;
  h.edges.back() = static_cast<Real>(largest + 1);
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (const Index a : areas) {
    // The bin whose [low, high) holds a; searched, not computed from the logarithm, so that a size on an
    // edge lands on the side the edges say.
    const auto upper = std::upper_bound(h.edges.begin(), h.edges.end(), static_cast<Real>(a));
    const auto bin = std::clamp<std::ptrdiff_t>(upper - h.edges.begin() - 1, 0, bins - 1);
    ++h.counts[static_cast<std::size_t>(bin)];
  }
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    h.density.push_back(static_cast<Real>(h.counts[i]) / h.width(i));
  return h;
}

MeasuredDistributions measure_distributions(const HeightMap& pressure, const HeightMap& gap, Real pixel_area,
                                            Index bins, std::map<int, Labeller>& labellers) {
  MeasuredDistributions m;
  m.points = pressure.size();
  m.contact_points = (pressure > 0).count();
  m.mean_pressure = pressure.mean();
  m.mean_gap = gap.mean();
  m.pixel_area = pixel_area;
  m.pressure = pressure_histogram(pressure, bins);
  m.gap = gap_histogram(pressure, gap, bins);
  const BinaryMap contact = (pressure > 0).cast<std::uint8_t>();
  for (auto& [connectivity, labeller] : labellers)
    m.cluster_areas[connectivity] = labeller.label(contact).areas;
  return m;
}

void write_pressure_distribution_csv(std::ostream& out, const LoadDistributions& d,
                                     const std::string& origin) {
  const Real area = static_cast<Real>(d.contact_points) / static_cast<Real>(d.points);
  out << "# " << origin << '\n'
      << "# pressure distribution P(sigma) at load P/(E* A0) = " << number(d.load)
      << ": BEM histogram of the pressure over its contact nodes (p > 0), density = count / (N width) over "
         "all N = "
      << d.points << " nodes, so that sum density * width = A/A0 (node count) = " << number(area)
      << " and sum sigma density width = mean pressure = " << number(d.mean_pressure / d.estar)
      << " E*; sigma in units of E* = " << number(d.estar)
      << " Pa; persson_density: Persson's diffusion solution at the same load at the bin's centre "
         "(docs/theory.md 12.3), whose delta at sigma = 0 is left out as the histogram's is\n"
      << "sigma_low,sigma_high,sigma,count,bem_density,persson_density\n";
  const Histogram& h = d.pressure;
  for (std::size_t i = 0; i < h.counts.size(); ++i) {
    const Real s = h.centre(i) / d.estar;
    out << number(h.edges[i] / d.estar) << ',' << number(h.edges[i + 1] / d.estar) << ',' << number(s) << ','
        << h.counts[i] << ',' << number(h.density[i] * d.estar) << ','
        << number(persson_pressure_density(s, d.load, d.q3_integral)) << '\n';
  }
}

void write_gap_distribution_csv(std::ostream& out, const LoadDistributions& d, const std::string& origin) {
  const Real free = 1 - static_cast<Real>(d.contact_points) / static_cast<Real>(d.points);
  out << "# " << origin << '\n'
      << "# gap distribution P(g) at load P/(E* A0) = " << number(d.load)
      << ": BEM histogram of the gap g [m] outside contact (p <= 0), density = count / (N width) [1/m] over "
         "all N = "
      << d.points << " nodes: sum density width = 1 - A/A0 = " << number(free)
      << " (the contact set is a delta at g = 0 the histogram leaves out) and sum g density width = the mean "
         "gap over the whole surface u-bar = "
      << number(d.mean_gap) << " m (to the bins' width)\n"
      << "gap_low,gap_high,gap,count,density\n";
  const Histogram& h = d.gap;
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    out << number(h.edges[i]) << ',' << number(h.edges[i + 1]) << ',' << number(h.centre(i)) << ','
        << h.counts[i] << ',' << number(h.density[i]) << '\n';
}

void write_patch_sizes_csv(std::ostream& out, const LoadDistributions& d, const std::string& origin) {
  Index spots = 0;
  for (const Index c : d.patch_sizes.counts)
    spots += c;
  out << "# " << origin << '\n'
      << "# contact patch sizes at load P/(E* A0) = " << number(d.load) << ": the BEM's contact clusters ("
      << d.connectivity << "-connectivity, core/labelling.hpp), " << spots
      << " in all, their sizes in nodes on logarithmic bins [size_low, size_high); area = size * dx dy = "
         "size * "
      << number(d.pixel_area)
      << " m^2; density = count / (size_high - size_low) [1/node], n(s) for a "
         "log-log plot\n"
      << "size_low,size_high,size,area_low,area_high,count,density\n";
  const Histogram& h = d.patch_sizes;
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    out << number(h.edges[i]) << ',' << number(h.edges[i + 1]) << ','
        << number(std::sqrt(h.edges[i] * h.edges[i + 1])) << ',' << number(h.edges[i] * d.pixel_area) << ','
        << number(h.edges[i + 1] * d.pixel_area) << ',' << h.counts[i] << ',' << number(h.density[i]) << '\n';
}

}  // namespace contactbench

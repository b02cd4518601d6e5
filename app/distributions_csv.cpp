#include "contactbench/app/distributions_csv.hpp"

#include <algorithm>
#include <cmath>

#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/power_law_fit.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/theories/persson_gap.hpp"
#include "contactbench/theories/plateau_at_load.hpp"
#include "contactbench/theories/plateau_model.hpp"

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

// The sizes a patch-size histogram's bins hold, per size: count / integers in the bin (NaN for a bin that
// holds no integer), the number density per size that the power law is fitted to.
std::vector<Real> density_per_size(const Histogram& h) {
  std::vector<Real> out;
  for (std::size_t i = 0; i < h.counts.size(); ++i) {
    const Index sizes = integers_in(h.edges[i], h.edges[i + 1]);
    out.push_back(sizes > 0 ? static_cast<Real>(h.counts[i]) / static_cast<Real>(sizes) : std::nan(""));
  }
  return out;
}

std::vector<Real> centres(const Histogram& h) {
  std::vector<Real> out;
  for (std::size_t i = 0; i + 1 < h.edges.size(); ++i)
    out.push_back(std::sqrt(h.edges[i] * h.edges[i + 1]));
  return out;
}

PowerLawFit fit_patch_sizes(const Histogram& h) {
  return fit_power_law(centres(h), density_per_size(h), h.counts, kPowerLawMinSize, kPowerLawMinCount);
}

std::string fit_text(const PowerLawFit& fit) {
  if (!fit.fitted) return "no fit (" + fit.reason + ")";
  return "n(s) = c s^(-tau), tau = " + json_number(fit.exponent) + ", c = " + json_number(fit.prefactor) +
         ", least squares on ln density_per_size against ln size over " + std::to_string(fit.bins) +
         " bins, sizes " + json_number(fit.low) + " to " + json_number(fit.high) + " nodes";
}

// A value or an empty field where there is none.
std::string field(Real value) {
  return std::isfinite(value) ? json_number(value) : std::string();
}

LoadDistributions::Plateau plateau_reading(const LoadDistributions& d, const Surface& surface,
                                           const SweepCurve& levels, const LoadAreaCurve& model,
                                           const Topology& topology, PlateauReading reading) {
  LoadDistributions::Plateau out;
  try {
    const PlateauAtLoad at = plateau_at_load(surface, levels, model, topology, d.load, reading);
    out.given = true;
    out.level = at.level;
    out.area_fraction = at.area_fraction;
    out.points = at.points;
    out.gap = bin_on_edges(d.gap.edges, at.gaps, at.points);
    out.patch_sizes = bin_on_edges(d.patch_sizes.edges, at.spot_areas, at.points);
  } catch (const Error& e) {
    out.note = e.what();
  }
  return out;
}

std::string plateau_gap_text(const std::string& name, const LoadDistributions::Plateau& p) {
  if (!p.given) return name + ": n/a (" + p.note + ")";
  Index gap_nodes = p.gap.below + p.gap.above;
  for (const Index c : p.gap.histogram.counts)
    gap_nodes += c;
  return name + ": cut level z = " + json_number(p.level) + " m, A/A0 = " + json_number(p.area_fraction) +
         ", the gaps z - h of the undeformed surface at the " + std::to_string(gap_nodes) + " of its " +
         std::to_string(p.points) + " nodes with h <= z, " + std::to_string(p.gap.above) +
         " of them beyond the last bin";
}

}  // namespace

BinnedValues bin_on_edges(const std::vector<Real>& edges, const std::vector<Real>& values, Index all_nodes) {
  BinnedValues out;
  Histogram& h = out.histogram;
  h.edges = edges;
  const std::size_t bins = edges.size() - 1;
  h.counts.assign(bins, 0);
  for (const Real v : values) {
    if (v < edges.front()) {
      ++out.below;
      continue;
    }
    if (v > edges.back()) {
      ++out.above;
      continue;
    }
    const auto upper = std::upper_bound(edges.begin(), edges.end(), v);
    const auto bin =
        std::clamp<std::ptrdiff_t>(upper - edges.begin() - 1, 0, static_cast<std::ptrdiff_t>(bins) - 1);
    ++h.counts[static_cast<std::size_t>(bin)];
  }
  for (std::size_t i = 0; i < bins; ++i)
    h.density.push_back(static_cast<Real>(h.counts[i]) / (static_cast<Real>(all_nodes) * h.width(i)));
  return out;
}

Index integers_in(Real low, Real high) {
  return std::max<Index>(0, static_cast<Index>(std::ceil(high)) - static_cast<Index>(std::ceil(low)));
}

void add_distribution_theories(LoadDistributions& d, const Surface& surface, const Topology& topology) {
  const SweepCurve levels = sweep(surface, SweepLevels::exact(), topology);
  const LoadAreaCurve model = plateau_model(levels);
  d.plateau = plateau_reading(d, surface, levels, model, topology, PlateauReading::paper);
  d.plateau_hertz = plateau_reading(d, surface, levels, model, topology, PlateauReading::hertz);
  try {
    d.summit = summit_gap_at_load(spectral_moments(surface), d.load);
  } catch (const Error& e) {
    d.summit_note = e.what();
  }
}

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
      << "# beside it, at the same load and on the same bins (docs/theory.md 12.8), density = count / (nodes "
         "width) as the BEM's: "
      << plateau_gap_text("plateau_density, the multi-plateaus model", d.plateau) << "; "
      << plateau_gap_text("plateau_hertz_density, the project's Hertz-consistent variant", d.plateau_hertz)
      << "; summit_density, GW-McCool's undeformed gap exp(-(d - g)^2/(2 sigma^2))/(sqrt(2 pi) sigma), "
      << (d.summit
              ? "d = " + number(d.summit->separation) + " m, sigma = " + number(d.summit->rms_height) + " m"
              : "n/a (" + d.summit_note + ")")
      << ", at the bin's centre\n"
      << "gap_low,gap_high,gap,count,density,plateau_density,plateau_hertz_density,summit_density\n";
  const Histogram& h = d.gap;
  const auto theory = [&](const LoadDistributions::Plateau& p, std::size_t i) {
    return p.given ? number(p.gap.histogram.density[i]) : std::string();
  };
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    out << number(h.edges[i]) << ',' << number(h.edges[i + 1]) << ',' << number(h.centre(i)) << ','
        << h.counts[i] << ',' << number(h.density[i]) << ',' << theory(d.plateau, i) << ','
        << theory(d.plateau_hertz, i) << ','
        << (d.summit ? number(summit_gap_density(*d.summit, h.centre(i))) : std::string()) << '\n';
}

void write_patch_sizes_csv(std::ostream& out, const LoadDistributions& d, const std::string& origin) {
  Index spots = 0;
  for (const Index c : d.patch_sizes.counts)
    spots += c;
  const PowerLawFit bem_fit = fit_patch_sizes(d.patch_sizes);
  const std::vector<Real> bem_per_size = density_per_size(d.patch_sizes);
  const auto plateau_text = [](const std::string& name, const LoadDistributions::Plateau& p) {
    if (!p.given) return name + ": n/a (" + p.note + ")";
    Index n = p.patch_sizes.below + p.patch_sizes.above;
    for (const Index c : p.patch_sizes.histogram.counts)
      n += c;
    return name + ": " + std::to_string(n) + " spots at the cut level z = " + json_number(p.level) + " m, " +
           std::to_string(p.patch_sizes.below) + " below the first bin and " +
           std::to_string(p.patch_sizes.above) + " beyond the last";
  };
  PowerLawFit plateau_fit;
  std::vector<Real> plateau_per_size(d.patch_sizes.counts.size(), std::nan(""));
  if (d.plateau.given) {
    plateau_fit = fit_patch_sizes(d.plateau.patch_sizes.histogram);
    plateau_per_size = density_per_size(d.plateau.patch_sizes.histogram);
  }
  out << "# " << origin << '\n'
      << "# contact patch sizes at load P/(E* A0) = " << number(d.load) << ": the BEM's contact clusters ("
      << d.connectivity << "-connectivity, core/labelling.hpp), " << spots
      << " in all, their sizes in nodes on logarithmic bins [size_low, size_high); area = size * dx dy = "
         "size * "
      << number(d.pixel_area)
      << " m^2; density = count / (size_high - size_low) [1/node], n(s) for a "
         "log-log plot; density_per_size = count / (the integers in the bin), the number of patches per "
         "size\n"
      << "# BEM power law (bem_power_law, c s^(-tau) at the bin's size inside the fitted range): "
      << fit_text(bem_fit) << " (docs/theory.md 12.8)\n"
      << "# beside it, on the same bins and with the same connectivity: "
      << plateau_text("plateau_count, the multi-plateaus model's spots (clusters of {h > z})", d.plateau)
      << ", power law " << (d.plateau.given ? fit_text(plateau_fit) : std::string("n/a")) << "; "
      << plateau_text(
             "plateau_hertz_count, the Hertz-consistent variant's spots (its level's clusters, each "
             "of half the bearing area)",
             d.plateau_hertz)
      << '\n'
      << "size_low,size_high,size,area_low,area_high,count,density,density_per_size,bem_power_law,plateau_"
         "count,"
         "plateau_density_per_size,plateau_hertz_count\n";
  const Histogram& h = d.patch_sizes;
  for (std::size_t i = 0; i < h.counts.size(); ++i) {
    const Real size = std::sqrt(h.edges[i] * h.edges[i + 1]);
    const bool in_fit = bem_fit.fitted && size >= bem_fit.low && size <= bem_fit.high;
    out << number(h.edges[i]) << ',' << number(h.edges[i + 1]) << ',' << number(size) << ','
        << number(h.edges[i] * d.pixel_area) << ',' << number(h.edges[i + 1] * d.pixel_area) << ','
        << h.counts[i] << ',' << number(h.density[i]) << ',' << field(bem_per_size[i]) << ','
        << (in_fit ? number(bem_fit.prefactor * std::pow(size, -bem_fit.exponent)) : std::string()) << ','
        << (d.plateau.given ? std::to_string(d.plateau.patch_sizes.histogram.counts[i]) : std::string())
        << ',' << field(plateau_per_size[i]) << ','
        << (d.plateau_hertz.given ? std::to_string(d.plateau_hertz.patch_sizes.histogram.counts[i])
                                  : std::string())
        << '\n';
  }
}

}  // namespace contactbench

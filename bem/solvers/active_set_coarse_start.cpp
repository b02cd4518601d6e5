#include "contactbench/bem/solvers/active_set_method.hpp"
#include "contactbench/bem/solvers/block_average.hpp"

namespace contactbench {

using namespace active_set_tuning;

namespace {

// Coarse pixel values on the fine grid: bilinear between coarse pixel centres (fine pixel 2y + a sits at
// coarse coordinate y + (2a - 1)/4), wrapped when periodic, clamped at the edges otherwise; each value then
// clamped to [0, cap]. Rows split over `threads` threads.
template <class T>
std::vector<T> interpolate_up(const std::vector<T>& coarse, Index cnx, Index cny, bool periodic, T cap,
                              int threads) {
  auto neighbour = [periodic](Index i, Index step, Index n) {
    const Index j = i + step;
    if (periodic) return (j + n) % n;
    return std::clamp<Index>(j, 0, n - 1);
  };
  const Index nx = 2 * cnx, ny = 2 * cny;
  std::vector<T> rows(static_cast<std::size_t>(cny * nx));
  std::vector<T> fine(static_cast<std::size_t>(ny * nx));
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (Index y = 0; y < cny; ++y)
      for (Index x = 0; x < nx; ++x) {
        const Index c = x / 2, other = neighbour(c, x % 2 == 0 ? -1 : 1, cnx);
        rows[static_cast<std::size_t>(y * nx + x)] =
            static_cast<T>(0.75 * static_cast<double>(coarse[static_cast<std::size_t>(y * cnx + c)]) +
                           0.25 * static_cast<double>(coarse[static_cast<std::size_t>(y * cnx + other)]));
      }
#pragma omp for schedule(static)
    for (Index y = 0; y < ny; ++y) {
      const Index c = y / 2, other = neighbour(c, y % 2 == 0 ? -1 : 1, cny);
      for (Index x = 0; x < nx; ++x)
        fine[static_cast<std::size_t>(y * nx + x)] = std::clamp(
            static_cast<T>(0.75 * static_cast<double>(rows[static_cast<std::size_t>(c * nx + x)]) +
                           0.25 * static_cast<double>(rows[static_cast<std::size_t>(other * nx + x)])),
            T(0), cap);
    }
  }
  return fine;
}

}  // namespace

// The factor that scales the start's pressure to the load (no plastic nodes yet): total over its sum, 0
// when that is 0.
template <class T>
double ActiveSet<T>::start_scale(const std::vector<T>& p, double total) {
  const Sums s = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k)
      part.a += static_cast<double>(p[k]);
  });
  return s.a > 0 ? total / s.a : 0;
}

// The start's displacement: u = G p with p times `factor` on its way in, and on u's way out the elastic
// set {p > 0}; returns the flat's height from the mean of u - h on that set.
template <class T>
double ActiveSet<T>::start_displacement(std::vector<T>& p, double factor) {
  const Sums set = fresh_displacement(
      p,
      [&](std::size_t k) {
        if (factor != 1) p[k] = static_cast<T>(factor * static_cast<double>(p[k]));
      },
      [&](std::size_t k, Sums& part) {
        in_[k] = p[k] > 0;
        if (in_[k]) {
          part.a += static_cast<double>(u_[k]) - static_cast<double>(h_[k]);
          part.b += 1;
        }
      });
  return flat_height(set);
}

// A cold start's set {p - k g > 0} (start_score); returns how many, their scores the first values of z_
// (free until the CG). Each thread writes its nodes' scores from the start of its own range of z_, then
// they are moved to the front in thread order.
template <class T>
std::size_t ActiveSet<T>::score_start(const std::vector<T>& p, double d, double stiffness) {
  over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    std::size_t next = begin;
    for (std::size_t k = begin; k < end; ++k) {
      const T score = start_score(p, k, d, stiffness);
      in_[k] = score > 0;
      if (in_[k]) z_[next++] = score;
    }
    part.a = static_cast<double>(begin);  // exact: below 2^53
    part.b = static_cast<double>(next - begin);
  });
  std::size_t candidates = 0;
  for (const Sums& s : sums_) {
    const auto begin = static_cast<std::ptrdiff_t>(s.a), count = static_cast<std::ptrdiff_t>(s.b);
    std::copy(z_.begin() + begin, z_.begin() + begin + count,
              z_.begin() + static_cast<std::ptrdiff_t>(candidates));  // forward: never past its source
    candidates += static_cast<std::size_t>(count);
  }
  return candidates;
}

// A cold start under load control keeps at most as many nodes as the coarse level's solution has in
// contact (its fraction of the nodes), those of the largest scores (the first `candidates` values of z_):
// returns the lowest score kept, 0 when all are. At a given load a finer grid resolves more roughness and
// touches less, or as much where the surface has none below the coarse pixel; the rule's set is larger
// still, the interpolated pressure being spread over the coarse spots (surface A at 1024^2 and 1 %: 15016
// nodes, the coarse area 13132, the solution's 12095). A start sized to the fine area extrapolated over
// the levels cost more outer steps: the steps shrink a set faster than they grow one (docs/solvers.md).
template <class T>
T ActiveSet<T>::coarse_area_level(std::size_t candidates) {
  const auto most = static_cast<std::size_t>(coarse_->contact_fraction_ * static_cast<double>(n_));
  if (most == 0 || most >= candidates) return T(0);
  const auto last = z_.begin() + static_cast<std::ptrdiff_t>(most - 1);
  std::nth_element(z_.begin(), last, z_.begin() + static_cast<std::ptrdiff_t>(candidates), std::greater<>());
  return *last;
}

// The nested start: the same problem on the surface averaged over 2 x 2 blocks solved to
// kCoarseTolerance (itself nested), its pressure interpolated. Returns the coarse level's outcome (no
// iterations when the grid is too small or odd: then the start is the uniform pressure under load control,
// and under separation control the penetration pressed in by the stiffness of one pixel, as PK's).
template <class T>
ActiveSetOutcome ActiveSet<T>::nested_start(const ActiveSetProblem& problem, std::vector<T>& p,
                                            const std::function<void()>& between) {
  if (!coarse_) {
    p.assign(n_, T(1));
    if (!problem.load_control) {
      const double stiffness = 1 / operator_->self_response();
      for (std::size_t k = 0; k < n_; ++k)
        p[k] = static_cast<T>(std::min(
            std::max(static_cast<double>(h_[k]) - problem.separation, 0.0) * stiffness, problem.hardness));
    }
    return {};
  }
  std::vector<T> coarse_pressure;
  const ActiveSetOutcome o =
      coarse_->solve(problem, kCoarseTolerance, 100000, false, coarse_pressure, between);
  p = interpolate_up(coarse_pressure, grid_.nx / 2, grid_.ny / 2, grid_.periodic, cap_, team());
  return o;
}

// The next coarser level (null when the grid is too small or odd): the surface averaged over 2 x 2 blocks.
// Its plans are estimated: a coarse level is solved once per load to a loose tolerance, far too few
// applications to pay back a measured plan (docs/solvers.md, Planning).
template <class T>
void ActiveSet<T>::make_coarse_level() {
  const Index nx = grid_.nx, ny = grid_.ny;
  if (nx % 2 != 0 || ny % 2 != 0 || nx / 2 < kCoarsest || ny / 2 < kCoarsest) return;
  Grid coarse_grid = grid_;
  coarse_grid.nx = nx / 2;
  coarse_grid.ny = ny / 2;
  coarse_ = std::make_unique<ActiveSet<T>>(coarse_grid, coarse_heights(coarse_grid), modulus_, threads_,
                                           FftRigor::estimate);
}

template <class T>
std::vector<T> ActiveSet<T>::coarse_heights(const Grid& coarse_grid) const {
  return block_averages(h_.data(), grid_.nx, coarse_grid.ny);  // bem/solvers/block_average.hpp
}

// The starting sets. Cold: {p - k g > 0}, k the stiffness of one pixel, g the gap of the nested start
// (under load control with the flat from its mean on the start's own contact set), under load control
// cut to the coarse level's contact area (coarse_area_level). Warm: the start's own contact set {p > 0},
// the previous solution's: under a growing load the set of the rule above overshoots (the scaled
// previous pressure presses the flat too deep; surface A at 256^2, load 0.001 -> 0.002: 8673 nodes for
// the 2472 of the solution), and the outer steps that shrink it back cost more than those that grow the
// previous set (10-load curve: 0.81-0.92 of the cold solves' iterations at 256^2 and 512^2 against
// 0.88-1.10; about 1 at 1024^2, where the cold nested start is as good; docs/solvers.md). Of those,
// the nodes at or above the hardness start plastic. The start's G p is made with p scaled to the load
// on its way in and the set {p > 0} with its mean of u - h on the way out.
// Returns the sums of holding p to them (keep_to_sets); d: the flat's height of the start.
template <class T>
typename ActiveSet<T>::Sums ActiveSet<T>::start_sets(std::vector<T>& p, bool warm, double total, double& d) {
  const double factor = load_control_ ? start_scale(p, total) : 1.0;
  const double start_flat = start_displacement(p, factor);
  d = load_control_ ? start_flat : separation_;
  if (!warm) {
    const double stiffness = 1 / operator_->self_response();
    const std::size_t candidates = score_start(p, d, stiffness);
    const T level = load_control_ && coarse_ ? coarse_area_level(candidates) : T(0);
    if (level > 0)
      over_points([&](std::size_t begin, std::size_t end, Sums&) {
        for (std::size_t k = begin; k < end; ++k)
          if (in_[k]) in_[k] = start_score(p, k, d, stiffness) >= level;  // the same operation as ranked
      });
  }
  // The starting sets' plastic nodes, and the pressure held to the sets; from here each set update holds
  // p to its new sets in its own pass.
  Sums kept = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k) {
      plastic_[k] = in_[k] && p[k] >= cap_;
      in_[k] = in_[k] && !plastic_[k];
      keep_to_sets(p, k, part);
    }
  });
  if (kept.b == 0 && kept.g == 0) {  // load control: every node; separation control: those the flat
    kept = over_points([&](std::size_t begin, std::size_t end, Sums& part) {  // penetrates
      for (std::size_t k = begin; k < end; ++k) {
        in_[k] = load_control_ || static_cast<double>(h_[k]) > separation_;
        keep_to_sets(p, k, part);
      }
    });
  }
  return kept;
}

template typename ActiveSet<double>::Sums ActiveSet<double>::start_sets(std::vector<double>&, bool, double,
                                                                        double&);
template typename ActiveSet<float>::Sums ActiveSet<float>::start_sets(std::vector<float>&, bool, double,
                                                                      double&);
template double ActiveSet<double>::start_scale(const std::vector<double>& p, double total);
template double ActiveSet<float>::start_scale(const std::vector<float>& p, double total);
template double ActiveSet<double>::start_displacement(std::vector<double>& p, double factor);
template double ActiveSet<float>::start_displacement(std::vector<float>& p, double factor);
template std::size_t ActiveSet<double>::score_start(const std::vector<double>& p, double d, double stiffness);
template std::size_t ActiveSet<float>::score_start(const std::vector<float>& p, double d, double stiffness);
template double ActiveSet<double>::coarse_area_level(std::size_t candidates);
template float ActiveSet<float>::coarse_area_level(std::size_t candidates);
template ActiveSetOutcome ActiveSet<double>::nested_start(const ActiveSetProblem& problem,
                                                          std::vector<double>& p,
                                                          const std::function<void()>& between);
template ActiveSetOutcome ActiveSet<float>::nested_start(const ActiveSetProblem& problem,
                                                         std::vector<float>& p,
                                                         const std::function<void()>& between);
template void ActiveSet<double>::make_coarse_level();
template void ActiveSet<float>::make_coarse_level();
template std::vector<double> ActiveSet<double>::coarse_heights(const Grid&) const;
template std::vector<float> ActiveSet<float>::coarse_heights(const Grid&) const;

}  // namespace contactbench

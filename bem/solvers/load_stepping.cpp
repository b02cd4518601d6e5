#include "contactbench/bem/solvers/load_stepping.hpp"

#include <algorithm>

#include "contactbench/bem/solvers/pressure_state.hpp"

namespace contactbench {

template <class T>
void PressureState<T>::start_from(const HeightMap& pressure) {
  for (Index i = 0; i < n_; ++i)
    q_[cur_][static_cast<std::size_t>(i)] = static_cast<T>(std::max(pressure.data()[i], 0.0));
  s_[cur_] = 1;
  warm_ = true;
  loads_solved_ = 0;
}

template <class T>
void PressureState<T>::begin_load(double mean_pressure, bool extrapolate) {
  const double total = mean_pressure * static_cast<double>(n_);
  const bool two_behind = extrapolate && warm_ && loads_solved_ >= 2 && last_load_ != previous_load_;
  if (extrapolate && warm_ && loads_solved_ >= 1) {
    // p = p_last + w (p_last - p_before), w = (P - P_last)/(P_last - P_before): the pressure field's
    // tangent along the load path (negative values clipped: out of contact); the last solution is kept
    // for the next extrapolation.
    if (previous_.empty()) previous_.resize(static_cast<std::size_t>(n_));
    const double w = two_behind ? (mean_pressure - last_load_) / (last_load_ - previous_load_) : 0.0;
    const double s = s_[cur_];
    std::vector<T>& q = q_[cur_];
    for (std::size_t k = 0; k < q.size(); ++k) {
      const double p = s * static_cast<double>(q[k]);
      const double guess = p + w * (p - static_cast<double>(previous_[k]));
      previous_[k] = static_cast<T>(p);
      q[k] = static_cast<T>(std::max(guess, 0.0));
    }
    s_[cur_] = 1;
  }
  if (warm_) s_[cur_] = total / q_sum(q_[cur_]);  // the previous pressure (or its extrapolation) scaled
}

template <class T>
void PressureState<T>::end_load(double mean_pressure) {
  warm_ = true;
  previous_load_ = last_load_;
  last_load_ = mean_pressure;
  ++loads_solved_;
}

template void PressureState<double>::start_from(const HeightMap&);
template void PressureState<float>::start_from(const HeightMap&);
template void PressureState<double>::begin_load(double, bool);
template void PressureState<float>::begin_load(double, bool);
template void PressureState<double>::end_load(double);
template void PressureState<float>::end_load(double);

LoadPathStart load_path_start(const BemSolverOptions& options, const Grid& grid) {
  if (options.load_path != LoadPathStart::solver) return options.load_path;
  const SolverEntry& entry = solver_entry(options.solver);
  const LoadPathStart declared =
      entry.load_path ? entry.load_path(grid, options.hardness.has_value()) : LoadPathStart::scaled;
  return declared == LoadPathStart::solver ? LoadPathStart::scaled : declared;  // never itself
}

Index coarse_start(ContactSolver& solver, const Surface& surface, Real modulus,
                   const BemSolverOptions& options, int threads, Real mean_pressure) {
  // Each coarse pixel's pressure on its four fine pixels.
  constexpr Index kCoarsest = 64;
  constexpr Real kCoarseTolerance = 1e-4;
  const Grid& fine = surface.grid();
  if (fine.nx % 2 != 0 || fine.ny % 2 != 0 || fine.nx / 2 < kCoarsest || fine.ny / 2 < kCoarsest) return 0;
  Grid grid = fine;
  grid.nx /= 2;
  grid.ny /= 2;
  const HeightMap& h = surface.heights();
  HeightMap coarse(grid.ny, grid.nx);
  for (Index y = 0; y < grid.ny; ++y)
    for (Index x = 0; x < grid.nx; ++x)
      coarse(y, x) =
          0.25 * (h(2 * y, 2 * x) + h(2 * y, 2 * x + 1) + h(2 * y + 1, 2 * x) + h(2 * y + 1, 2 * x + 1));
  BemSolverOptions coarse_options = options;
  coarse_options.tolerance = std::max(options.tolerance, kCoarseTolerance);
  coarse_options.hardness = std::nullopt;
  coarse_options.load_path = LoadPathStart::scaled;
  BemSolver coarse_solver(Surface(grid, coarse), modulus, coarse_options, threads);
  const ContactSolution& s = coarse_solver.solve(mean_pressure);
  HeightMap start(fine.ny, fine.nx);
  for (Index y = 0; y < fine.ny; ++y)
    for (Index x = 0; x < fine.nx; ++x)
      start(y, x) = s.pressure(y / 2, x / 2);
  solver.start_from(start);
  return s.iterations + s.coarse_iterations;
}

}  // namespace contactbench

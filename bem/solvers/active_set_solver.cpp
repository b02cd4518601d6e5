#include "contactbench/bem/solvers/active_set_solver.hpp"

#include <limits>

#include "contactbench/core/error.hpp"

namespace contactbench {

template <class T>
ActiveSetContactSolver<T>::ActiveSetContactSolver(const Surface& centred, Real modulus, int threads)
    : PressureState<T>(centred, threads), method_(this->grid_, this->h_, modulus, threads) {}

template <class T>
SolveOutcome ActiveSetContactSolver<T>::solve_load(double mean_pressure, double hardness, double tolerance,
                                                   Index max_iterations, bool extrapolate) {
  this->begin_load(mean_pressure, extrapolate);  // cold: the method makes its own start
  this->hardness_ = std::numeric_limits<double>::infinity();
  const SolveOutcome outcome =
      solve({.mean_pressure = mean_pressure, .hardness = hardness}, tolerance, max_iterations);
  this->end_load(mean_pressure);
  return outcome;
}

template <class T>
SolveOutcome ActiveSetContactSolver<T>::solve_separation(double separation, double hardness, double tolerance,
                                                         Index max_iterations) {
  this->end_load_series();
  this->separation_ = separation;
  this->hardness_ = this->stored(hardness);
  const SolveOutcome outcome = solve({.load_control = false, .separation = separation, .hardness = hardness},
                                     tolerance, max_iterations);
  this->warm_ = true;
  return outcome;
}

template <class T>
void ActiveSetContactSolver<T>::set_heights(const HeightMap& heights) {
  PressureState<T>::set_heights(heights);
  method_.set_heights(this->h_);
}

template <class T>
void ActiveSetContactSolver<T>::impose_load(double, double) {
  throw Error("active_set: impose_load is never needed (a capped load is one solve)");
}

template <class T>
SolveOutcome ActiveSetContactSolver<T>::solve(const ActiveSetProblem& problem, double tolerance,
                                              Index max_iterations) {
  std::vector<T> pressure;
  const int cur = this->cur_;
  if (this->warm_) {
    pressure.resize(static_cast<std::size_t>(this->n_));
    const double s = this->s_[cur];
    for (std::size_t k = 0; k < pressure.size(); ++k)
      pressure[k] = static_cast<T>(s * static_cast<double>(this->q_[cur][k]));
  }
  ActiveSetOutcome result;
  try {
    result = method_.solve(problem, tolerance, max_iterations, this->warm_, pressure, this->g_,
                           this->between_iterations_);
  } catch (...) {
    this->forget();  // abandoned mid-solve: nothing to warm-start from
    throw;
  }
  this->q_[cur] = std::move(pressure);
  this->s_[cur] = 1;
  this->last_sum_ = result.pressure_sum;
  this->hardness_ = this->stored(problem.hardness);
  this->separation_ = result.separation;
  this->gap_offset_ = this->separation_;  // g holds u - h: the gap is g + d
  return SolveOutcome{
      .iterations = result.iterations, .change = result.change, .converged = result.converged};
}

template class ActiveSetContactSolver<double>;
template class ActiveSetContactSolver<float>;

namespace {
// Where active_set's declared start turns from warm to cold (the entry below).
constexpr Index kWarmBelowPoints = 512 * 512;
}  // namespace

SolverEntry active_set_entry() {
  return {.kind = SolverKind::active_set,
          .name = "active_set",
          .description =
              "a primal-dual active-set method: the linear problem on a guessed contact set solved by "
              "a preconditioned CG, the set updated from p and the gap, from a nested coarse start",
          .separation_control = true,
          .hardness = true,
          .single_precision = true,
          // Warm from the last solution's contact set below 512^2 points, cold (the nested coarse start)
          // from there: on the benchmark's 10-load curves (contact 1 % to 30 %, bench/bench_load_path.cpp)
          // the warm curve took 0.88 to 0.91 of the cold solves' iterations at 256^2, 0.98 to 1.03 at 512^2
          // and 1.09 to 1.23 at 1024^2, where the nested start is as good a start as the last solution
          // and the warm set's first update overshoots (docs/solvers.md "Starts"). With a hardness, warm at
          // every grid: the nested coarse start solves the elastic problem, far from a capped one, and on
          // surface A at 512^2 (10 loads up to 16 % contact, 5 % plastic; bench_bem_solvers plastic rows)
          // the capped curve took 518 iterations cold against 293 warm periodic, 563 against 324 not.
          .load_path =
              [](const Grid& grid, bool capped) {
                return capped || grid.points() < kWarmBelowPoints ? LoadPathStart::scaled
                                                                  : LoadPathStart::cold;
              },
          .make = [](const Surface& centred, Real modulus, int threads,
                     bool single_precision) -> std::unique_ptr<ContactSolver> {
            if (single_precision)
              return std::make_unique<ActiveSetContactSolver<float>>(centred, modulus, threads);
            return std::make_unique<ActiveSetContactSolver<double>>(centred, modulus, threads);
          }};
}

}  // namespace contactbench

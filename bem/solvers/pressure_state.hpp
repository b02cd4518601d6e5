// What every solver keeps between solves, whatever its iteration: the heights, the pressure p = s q (an
// array q and a scalar s; two arrays, so that an iteration can measure its change), the gap, the flat's
// height, and the loads solved so far for warm starts (load stepping, bem/solvers/load_stepping.cpp). Also
// the solution's write-out, the same for every solver. Internal to the solvers (bem/solvers/).
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "contactbench/bem/solvers/contact_solver.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

template <class T>
class PressureState : public ContactSolver {
 public:
  // `centred`: the surface with its mean height removed.
  PressureState(const Surface& centred, int threads);

  void forget() override;
  bool warm() const override { return warm_; }
  void start_from(const HeightMap& pressure) override;
  void set_heights(const HeightMap& heights) override;
  double write(ContactSolution& s) const override;
  double max_pressure() const override;
  double separation() const override { return separation_; }
  double mean_pressure() const override { return last_sum_ / static_cast<double>(n_); }

  // The hardness as T holds it. Plastic nodes store static_cast<T>(H), and every test p >= H (the sets of
  // the iteration, write()'s plastic count and residual) must compare with that value: in float, H = 3.2967e9
  // Pa rounds down, and compared with the double H the plastic nodes counted as elastic, so a capped solve
  // reported no plastic node, a residual of 0.24 of the height range and "not converged".
  static double stored(double hardness) {
    return std::isfinite(hardness) ? static_cast<double>(static_cast<T>(hardness)) : hardness;
  }

 protected:
  // Load stepping (load_stepping.cpp). Before a load-controlled solve: when warm, the previous pressure (or
  // the extrapolation of the last two) scaled to the load; cold, nothing (each solver makes its own start).
  void begin_load(double mean_pressure, bool extrapolate);
  // After it: the load joins the series the extrapolation reads.
  void end_load(double mean_pressure);
  // A separation-controlled solve ends the series of loads.
  void end_load_series() { loads_solved_ = 0; }

  static double q_sum(const std::vector<T>& q);

  Grid grid_;
  int threads_;
  Index n_;
  std::vector<T> h_, g_;  // the heights; g holds the gap less gap_offset_
  // q_[cur_] the pressure; q_[1 - cur_] the next one of an iteration that alternates the two, sized only by
  // the solvers that do (active_set's iteration keeps one: 8 MB of zeros at 1024^2 not written, issue 42).
  std::vector<T> q_[2];
  double s_[2] = {1, 1};
  int cur_ = 0;
  double height_range_ = 0;
  double separation_ = 0, gap_offset_ = 0, last_sum_ = 0;
  double hardness_ = std::numeric_limits<double>::infinity();
  bool warm_ = false;

 private:
  // For extrapolated starts: the loads of the last two load-controlled solves and the pressure of the one
  // before the last (the last is q_[cur_]); a solve under separation control ends the series.
  std::vector<T> previous_;
  double last_load_ = 0, previous_load_ = 0;
  Index loads_solved_ = 0;
};

extern template class PressureState<double>;
extern template class PressureState<float>;

}  // namespace contactbench

#include "contactbench/bem/solvers/pressure_state.hpp"

#include <omp.h>
#include <algorithm>
#include <cmath>

namespace contactbench {

template <class T>
PressureState<T>::PressureState(const Surface& centred, int threads)
    : grid_(centred.grid()),
      threads_(threads),
      n_(grid_.points()),
      h_(static_cast<std::size_t>(n_)),
      g_(static_cast<std::size_t>(n_)) {
  q_[0].resize(static_cast<std::size_t>(n_));  // q_[1]: sized by the solvers that alternate (Polonsky-Keer)
  const HeightMap& h = centred.heights();
  for (Index i = 0; i < n_; ++i)
    h_[static_cast<std::size_t>(i)] = static_cast<T>(h.data()[i]);
  height_range_ = h.maxCoeff() - h.minCoeff();
}

template <class T>
void PressureState<T>::set_heights(const HeightMap& heights) {
  for (Index i = 0; i < n_; ++i)
    h_[static_cast<std::size_t>(i)] = static_cast<T>(heights.data()[i]);
  height_range_ = heights.maxCoeff() - heights.minCoeff();
}

template <class T>
void PressureState<T>::forget() {
  warm_ = false;
  loads_solved_ = 0;
}

template <class T>
double PressureState<T>::max_pressure() const {
  T largest = 0;
  for (const T v : q_[cur_])
    largest = std::max(largest, v);
  return s_[cur_] * static_cast<double>(largest);
}

template <class T>
double PressureState<T>::q_sum(const std::vector<T>& q) {
  double sum = 0;
  for (const T v : q)
    sum += static_cast<double>(v);
  return sum;
}

template <class T>
double PressureState<T>::write(ContactSolution& s) const {
  const Index nx = grid_.nx, ny = grid_.ny;
  s.pressure.resize(ny, nx);
  s.gap.resize(ny, nx);
  const bool capped = std::isfinite(hardness_);
  if (capped)
    s.plastic_overlap.setZero(ny, nx);
  else
    s.plastic_overlap.resize(0, 0);
  const std::vector<T>& q = q_[cur_];
  const double scale = s_[cur_];
  // On the team, each thread a block of points, the parts combined in thread order (the same sums every
  // run for a fixed thread count).
  struct Part {
    double residual = 0, sum = 0;
    Index contact = 0, plastic = 0;
  };
  std::vector<Part> parts(static_cast<std::size_t>(std::max(threads_, 1)));
#pragma omp parallel num_threads(static_cast <int>(parts.size()))
  {
    const Index thread = omp_get_thread_num(), team = omp_get_num_threads();
    Part part;
    for (Index i = n_ * thread / team; i < n_ * (thread + 1) / team; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      const T pt = static_cast<T>(scale) * q[k];  // as the iteration computes it
      const double p = static_cast<double>(pt);
      s.pressure.data()[i] = p;
      part.sum += p;
      const double gap = static_cast<double>(g_[k]) + gap_offset_;
      if (!(pt > 0)) {
        s.gap.data()[i] = gap;
      } else {
        // Zero on the contact set; on plastic nodes too (the surface flowed to fit the flat there).
        s.gap.data()[i] = 0;
        ++part.contact;
        if (static_cast<double>(pt) >= hardness_) {
          ++part.plastic;
          s.plastic_overlap.data()[i] = std::max(-gap, 0.0);  // how far the surface pokes through the flat
        } else {
          part.residual = std::max(part.residual, std::abs(gap));
        }
      }
    }
    parts[static_cast<std::size_t>(thread)] = part;
  }
  double residual = 0, sum = 0;
  Index contact = 0, plastic = 0;
  for (const Part& part : parts) {
    residual = std::max(residual, part.residual);
    sum += part.sum;
    contact += part.contact;
    plastic += part.plastic;
  }
  s.separation = separation_;
  s.contact_points = contact;
  s.plastic_points = plastic;
  // Relative to the height range (to 1 m for a flat surface, whose range is 0).
  s.residual = residual / (height_range_ > 0 ? height_range_ : 1.0);
  return sum / static_cast<double>(n_);
}

template class PressureState<double>;
template class PressureState<float>;

}  // namespace contactbench

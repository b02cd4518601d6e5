#include "contactbench/bem/solvers/preconditioned_cg_solver.hpp"

#include "contactbench/bem/fourier_preconditioner.hpp"

namespace contactbench {

namespace {

using cg::Partial;

// The residual r = g - gbar on the elastic set, 0 elsewhere, into the filter's input; its sum.
template <class T>
CB_KERNEL void residual_row(Partial& part, const T* __restrict q, const T* __restrict g, T* __restrict out,
                            Index nx, T gbar) {
  double r_sum = 0;
#pragma omp simd reduction(+ : r_sum)
  for (Index x = 0; x < nx; ++x) {
    const bool in = q[x] > 0;
    const T rv = in ? g[x] - gbar : T(0);
    out[x] = rv;
    r_sum += static_cast<double>(rv);
  }
  part.rr_sum += r_sum;
}

// The filtered residual w kept on the elastic set as z; sums z and r w there.
template <class T>
CB_KERNEL void filtered_row(Partial& part, const T* __restrict q, const T* __restrict g,
                            const T* __restrict w, T* __restrict z, Index nx, T gbar) {
  double z_sum = 0, rz = 0;
#pragma omp simd reduction(+ : z_sum, rz)
  for (Index x = 0; x < nx; ++x) {
    const bool in = q[x] > 0;
    const T zv = in ? w[x] : T(0);
    z[x] = zv;
    z_sum += static_cast<double>(zv);
    rz += in ? static_cast<double>(g[x] - gbar) * static_cast<double>(zv) : 0.0;
  }
  part.z_sum += z_sum;
  part.rz += rz;
}

// t = (z - zbar) + beta t on the elastic set (0 elsewhere); sums (g - gbar) t, t and t^2.
template <class T>
CB_KERNEL void preconditioned_direction_row(Partial& part, const T* __restrict q, const T* __restrict g,
                                            const T* __restrict z, T* __restrict t, T* __restrict out,
                                            Index nx, T gbar, T zbar, T beta) {
  double gt = 0, t_sum = 0, tt = 0;
#pragma omp simd reduction(+ : gt, t_sum, tt)
  for (Index x = 0; x < nx; ++x) {
    const bool in = q[x] > 0;
    const T tv = in ? (z[x] - zbar) + beta * t[x] : T(0);
    t[x] = tv;
    out[x] = tv;
    gt += in ? static_cast<double>(g[x] - gbar) * static_cast<double>(tv) : 0.0;
    t_sum += static_cast<double>(tv);
    tt += static_cast<double>(tv) * static_cast<double>(tv);
  }
  part.gt += gt;
  part.t_sum += t_sum;
  part.tt += tt;
}

}  // namespace

template <class T>
PreconditionedCgSolver<T>::PreconditionedCgSolver(const Surface& centred, Real modulus, int threads)
    : PolonskyKeerSolver<T>(centred, modulus, threads),
      preconditioner_(make_fourier_preconditioner<T>(centred.grid(), modulus, threads)),
      z_(static_cast<std::size_t>(this->n_)) {
  if (preconditioner_->threads() > this->convolution_->threads())
    this->partial_.resize(static_cast<std::size_t>(preconditioner_->threads()));
}

// Producing the residual on the elastic set, consuming its filtered image, kept on the elastic set only as
// z (its mean there is taken out in the direction pass).
template <class T>
typename PreconditionedCgSolver<T>::FilterSums PreconditionedCgSolver<T>::filter_residual(const Pass& pass) {
  const Index nx = this->grid_.nx;
  const T* const g = this->g_.data();
  T* const z = z_.data();
  auto residual = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
    Partial& part = this->partial_[static_cast<std::size_t>(thread)];
    const T gb = pass.gbar;
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      residual_row(part, pass.q + i0, g + i0, buffer + r * ld, nx, gb);
    }
  };
  auto filtered = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
    Partial& part = this->partial_[static_cast<std::size_t>(thread)];
    const T gb = pass.gbar;
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      filtered_row(part, pass.q + i0, g + i0, buffer + r * ld, z + i0, nx, gb);
    }
  };
  this->clear_partials();
  preconditioner_->apply(Producer(residual), Consumer(filtered));
  FilterSums sums;
  for (const Partial& part : this->partial_) {
    sums.rz += part.rz;
    sums.z_sum += part.z_sum;
    sums.r_sum += part.rr_sum;
  }
  return sums;
}

template <class T>
double PreconditionedCgSolver<T>::preconditioned_direction(const Pass& pass, Consumer response) {
  const Index nx = this->grid_.nx;
  const T* const g = this->g_.data();
  const T* const z = z_.data();
  T* const t = this->t_.data();
  auto direction = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
    Partial& part = this->partial_[static_cast<std::size_t>(thread)];
    const T gb = pass.gbar, zb = pass.zbar, b = pass.beta;
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      preconditioned_direction_row(part, pass.q + i0, g + i0, z + i0, t + i0, buffer + r * ld, nx, gb, zb, b);
    }
  };
  return this->convolution_->apply(Producer(direction), response, Hook(), true);
}

template class PreconditionedCgSolver<double>;
template class PreconditionedCgSolver<float>;

SolverEntry preconditioned_cg_entry() {
  return {
      .kind = SolverKind::preconditioned_cg,
      .name = "preconditioned_cg",
      .description = "the same with the gap filtered by |q| in Fourier space before it becomes a direction",
      .separation_control = false,
      .hardness = false,
      .single_precision = true,
      // Warm, the last solution scaled: on the benchmark's 10-load curves (contact 1 % to 30 %,
      // bench/bench_load_path.cpp) 0.94 to 1.00 of the cold solves' iterations at 256^2 and 512^2. The
      // extrapolation took 0.92 to 0.97, but the distributed preconditioned_cg (mpi/) starts scaled and
      // must take the serial one's steps (tests/mpi): docs/solvers.md "Starts".
      .load_path = [](const Grid&, bool) { return LoadPathStart::scaled; },
      .make = [](const Surface& centred, Real modulus, int threads,
                 bool single_precision) -> std::unique_ptr<ContactSolver> {
        if (single_precision)
          return std::make_unique<PreconditionedCgSolver<float>>(centred, modulus, threads);
        return std::make_unique<PreconditionedCgSolver<double>>(centred, modulus, threads);
      }};
}

}  // namespace contactbench

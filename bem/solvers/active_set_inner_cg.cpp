#include "contactbench/bem/solvers/active_set_method.hpp"

namespace contactbench {

using namespace active_set_tuning;

namespace {

// Sums over a row of nx points of z on the contact set (in), with and without the transpose of the
// extension. E^T adds to each set node the window sum of z off the set, so each off-set z is added once per
// set node in its window (count, the window's count of set nodes): the sum on the set after E^T, made while
// z is written, before the transpose itself runs.
template <class T>
double sum_after_transpose(const std::uint8_t* in, const T* z, const std::uint16_t* count, Index nx) {
  double sum = 0;
#pragma omp simd reduction(+ : sum)
  for (Index x = 0; x < nx; ++x) {
    const double times = count[x];  // (loaded whatever in[x]: the loop vectorises)
    sum += static_cast<double>(z[x]) * (in[x] ? 1.0 : times);
  }
  return sum;
}
template <class T>
double sum_on_set(const std::uint8_t* in, const T* z, Index nx) {
  double sum = 0;
#pragma omp simd reduction(+ : sum)
  for (Index x = 0; x < nx; ++x) {
    const double value = z[x];
    sum += in[x] ? value : 0.0;
  }
  return sum;
}

}  // namespace

// The window counts moved by the pending flips, then the weights of the nodes in their windows.
template <class T>
template <class WeightOf>
void ActiveSet<T>::update_weights(Index radius, WeightOf weight_of) {
  const Index nx = grid_.nx, ny = grid_.ny;
  const bool periodic = grid_.periodic;
  auto over_window = [&](std::size_t node, auto visit) {
    const Index ky = static_cast<Index>(node) / nx, kx = static_cast<Index>(node) % nx;
    for (Index dy = -radius; dy <= radius; ++dy) {
      Index y = ky + dy;
      if (periodic) y = (y + ny) % ny;
      if (y < 0 || y >= ny) continue;
      for (Index dx = -radius; dx <= radius; ++dx) {
        Index x = kx + dx;
        if (periodic) x = (x + nx) % nx;
        if (x < 0 || x >= nx) continue;
        visit(static_cast<std::size_t>(y * nx + x));
      }
    }
  };
  for (const Flip& flip : pending_flips_)
    over_window(flip.node, [&](std::size_t j) {
      window_count_[j] = static_cast<std::uint16_t>(window_count_[j] + (flip.entered ? 1 : -1));
    });
  for (const Flip& flip : pending_flips_)
    over_window(flip.node, [&](std::size_t j) {
      extension_weight_[j] = weight_of(j, static_cast<double>(window_count_[j]));
    });
}

// The preconditioned CG for G p = h - d on the elastic set (p held elsewhere), from p with its values off
// the plastic set times `scale` (the load's rescaling; u_ then scales with p when current, which the
// caller makes sure only without plastic nodes); under load control sum p fixed (the direction has zero sum
// on the set, which also leaves d free), under separation control d = separation_ and the sum free; u_ ends
// as G p. Stops when the residual's L2 norm has fallen by `reduction` (0: never on that count), or when its
// largest value is at most `absolute` and the last step's relative change of the pressure at most
// `step_change`, or after `budget` iterations. Returns the iterations.
//
// The residual is the gap less its mean on the set under load control (the mean is the flat's unknown
// height), the gap d + u - h under separation control. The preconditioner is z = E^T F E r, E the extension
// of r off the set (kExtensionRadius above): Er = r on the set and, off it, the window sum of r on the set
// times the node's weight (1 / the window's count of set nodes, floored). F alone on r with zeros off the
// set bounds G's restriction to the set from above, but far too high for a pressure that varies slowly
// across many small spots: those are the CG's slow modes (scripts/extended_filter_model.py, a numpy model
// of this CG: the largest eigenvalue of the preconditioned operator on an H = 0.8 surface at 512^2 and
// 10 % contact is 11.5 without E and 3.2 with a window of radius 6; the smallest is 1 with or without).
// An iteration is two convolutions (bem/convolution.hpp), the window sums riding in their producers
// (bem/box_sum.hpp, WindowRows: each thread's rows come in order):
//   filter:    producing Er (off the set the weighted window sums of r on the set) | consuming F E r, in
//              single precision: kept on the set, times the weight off it, and the sum on the set that
//              E^T will leave (sum_after_transpose); <r, z> is <Er, F Er>, the transform's own product;
//   operator:  producing the direction t from z on the set plus the window sums of z off it (E^T) | the
//              step length from <t, G t>, the transform's product, before any row comes back | consuming
//              G t: p, u and r stepped, and the sums of the next residual.
// Sums are per thread and combined in thread order: deterministic for a fixed thread count.
template <class T>
Index ActiveSet<T>::cg_on_set(std::vector<T>& p, double scale, double reduction, double absolute,
                              double step_change, Index budget, const std::function<void()>& between) {
  const std::uint8_t* const in = in_.data();
  const T* const h = h_.data();
  const T* const u = u_.data();
  const Sums count = count_on_set(p, scale);
  set_size_ = count.c;
  set_mean_ = 0;
  if (set_size_ == 0) return 0;
  // The residual is r - c on the set: r stepped by the CG (r -= tau G t), c the mean those steps add to it
  // under load control (0 under separation control). Stepped, not formed from u - h at each step: in single
  // precision u - h carries the round-off of u (about 1e-14 m on a micrometre surface), and at 2048^2 the
  // residual's norm never fell below that floor (the solve ran on for minutes). Of x = r - c on the set:
  // its sum, its sum of squares, its largest and its smallest value (as the largest of -x).
  T* const r = r_.data();
  CgStep step;
  step.radius = extension_radius();
  // r = u - h less its mean on the set (load control), u - h + d (separation control).
  const double start_shift = load_control_ ? count.a / set_size_ : -separation_;
  const Sums start = over_points([&, start_shift](std::size_t begin, std::size_t end, Sums& part) {
    part.e = part.f = -std::numeric_limits<double>::infinity();
    for (std::size_t k = begin; k < end; ++k)  // (r off the set is the extension's, written before use)
      if (in[k]) {
        r[k] = static_cast<T>(static_cast<double>(u[k]) - static_cast<double>(h[k]) - start_shift);
        add_residual(part, static_cast<double>(r[k]));
      }
  });
  double norm = 0, largest = 0;
  // c moved to the mean of x (load control), and the residual's norm and largest value from the sums.
  auto settle = [&](const Sums& s) {
    const double shift = load_control_ ? s.a / set_size_ : 0.0;
    step.c += shift;
    norm = std::sqrt(std::max(s.b - 2 * shift * s.a + set_size_ * shift * shift, 0.0));
    largest = std::max(s.e - shift, s.f + shift);
  };
  settle(start);
  const double r0 = norm;
  double rz_old = 0;
  Index iterations = 0;
  last_step_change_ = 0;  // no step yet: the pressure has not moved
  for (; iterations < budget; ++iterations) {
    // While the set still changes (reduction > 0) a gap within the threshold everywhere on the set also
    // ends the solve: what is left to reduce is below what the update and the convergence test resolve.
    const bool within = largest <= absolute && (reduction > 0 || last_step_change_ <= step_change);
    if (within || norm <= reduction * r0 || norm == 0) break;
    if (between) between();
    if (iterations == 0 && step.radius > 0) make_extension_weights(step.radius);
    for (Sums& s : sums_)
      s = Sums{};
    step.shift_c = static_cast<T>(step.c);
    // Into the filter scaled by a power of two to about 1 (float's range: a residual of 1e-20 m squared
    // in the product would underflow), out scaled back: exact apart from float's rounding.
    step.to_filter = std::ldexp(1.0, -std::ilogb(largest));
    step.from_filter = std::ldexp(1.0, std::ilogb(largest));
    restart_windows();
    step.rz = filter_pass(step);  // <r, z>
    step.zbar = static_cast<T>(load_control_ ? combined().a / set_size_ : 0.0);
    if (!(step.rz > 0)) break;  // no descent left (a set of one node, or round-off)
    step.beta = static_cast<T>(rz_old > 0 ? step.rz / rz_old : 0.0);
    rz_old = step.rz;
    for (Sums& s : sums_) {
      s = Sums{};
      s.e = s.f = -std::numeric_limits<double>::infinity();
    }
    restart_windows();
    operator_pass(p, step);
    displacement_fresh_ = false;  // u stepped
    if (!(step.t_gt > 0)) break;  // nothing moved: tau was 0
    const Sums f = combined();
    const double pressure_sum = f.d + count.g;  // sum |p|: the elastic set's and the plastic nodes'
    last_step_change_ = pressure_sum > 0 ? f.c / pressure_sum : 0;
    settle(f);
  }
  set_mean_ = start_shift + step.c;  // u - h = r + start_shift on the set, r stepped as u is
  return iterations;
}

template <class T>
typename ActiveSet<T>::Sums ActiveSet<T>::count_on_set(std::vector<T>& p, double scale) {
  const std::uint8_t* const in = in_.data();
  const std::uint8_t* const plastic = plastic_.data();
  const T* const h = h_.data();
  T* const u = u_.data();
  T* const pp = p.data();
  // The set's size and the sum of u - h on it, counted in the pass that makes the load's rescaling: p
  // times `scale` off the plastic set, and u = G p with it when current; else u = G p made afresh, the
  // rescaling on p's way into the transform and the count on u's way out. From here u is kept by the
  // steps (u -= tau G t). The start's mean from a pass of its own, before the residual's: sums of squares
  // about a far-off mean would lose the residual to cancellation (u - h is about -d on the set, the
  // residual many decades smaller).
  auto rescaled = [&](std::size_t k) {
    if (scale != 1 && !plastic[k]) pp[k] = static_cast<T>(scale * static_cast<double>(pp[k]));
  };
  // Also the plastic nodes' sum of p (H each): off both sets p = 0, so the sum of |p| the CG's relative
  // change needs is that of the elastic set, where p moves, and this constant.
  auto counted = [&](std::size_t k, Sums& part) {
    if (in[k]) {
      part.a += static_cast<double>(u[k]) - static_cast<double>(h[k]);
      part.c += 1;
    }
    part.g += plastic[k] ? static_cast<double>(pp[k]) : 0.0;
  };
  Sums count;
  if (displacement_current_) {
    count = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k) {
        rescaled(k);
        // No plastic nodes here, or a factor within kUnitScaleSlack of 1 (active_set_method.hpp).
        if (scale != 1) u[k] = static_cast<T>(scale * static_cast<double>(u[k]));
        counted(k, part);
      }
    });
  } else {
    count = fresh_displacement(p, rescaled, counted);
  }
  return count;
}

// The extension's weights of this set, made before the first iteration (none when the start is already
// within the stopping test).
template <class T>
void ActiveSet<T>::make_extension_weights(Index radius) {
  const std::uint8_t* const in = in_.data();
  float* const weight = extension_weight_.data();
  const Index nx = grid_.nx;
  const double floor = kExtensionFloor * static_cast<double>((2 * radius + 1) * (2 * radius + 1));
  auto weight_of = [&](std::size_t k, double count) {
    return in[k] ? 0.0f : static_cast<float>(1 / std::max(count, floor));
  };
  if (weights_current_) {
    update_weights(radius, weight_of);
  } else {
    box_sum(
        grid_.nx, grid_.ny, radius, grid_.periodic,
        [&](Index y, double* values) {
          const std::uint8_t* const in_row = in + y * nx;
          for (Index x = 0; x < nx; ++x)
            values[x] = in_row[x] ? 1.0 : 0.0;
        },
        [&](Index y, const double* sums, int) {
          for (Index x = 0; x < nx; ++x) {
            const std::size_t k = static_cast<std::size_t>(y * nx + x);
            window_count_[k] = static_cast<std::uint16_t>(sums[x]);
            weight[k] = weight_of(k, sums[x]);
          }
        },
        window_rows_, team());
  }
  weights_current_ = true;
  pending_flips_.clear();
}

// Filter: r in; z = its image kept on the set out, with its sum. Returns <r, z>.
template <class T>
double ActiveSet<T>::filter_pass(const CgStep& step) {
  using FilterProducer = Convolution<float>::Producer;
  using FilterConsumer = Convolution<float>::Consumer;
  const std::uint8_t* const in = in_.data();
  const T* const r = r_.data();
  T* const z = z_.data();
  const float* const weight = extension_weight_.data();
  const Index nx = grid_.nx, radius = step.radius;
  const T& shift_c = step.shift_c;
  const double &to_filter = step.to_filter, &from_filter = step.from_filter;
  // E's inputs: the residual on the set, 0 off it.
  auto extension_inputs = [&](Index y, double* values) {
    const std::uint8_t* const in_row = in + y * nx;
    const T* const r_row = r + y * nx;
    const T cc = shift_c;
    for (Index x = 0; x < nx; ++x) {
      const T rv = r_row[x];
      values[x] = static_cast<double>((in_row[x] ? rv : cc) - cc);
    }
  };
  auto residual_in = [&](Index first, Index rows, float* buffer, Index ld, int thread) {
    const T cc = shift_c;
    const double scale_in = to_filter;
    WindowRows& window = window_rows_[static_cast<std::size_t>(thread)];
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      float* const out = buffer + y * ld;
      if (radius > 0) {  // off the set: the window sum of r on the set x weight
        const double* const sums = window.sums(first + y, extension_inputs);
        for (Index x = 0; x < nx; ++x) {
          const double on_set = static_cast<double>(r[i0 + x] - cc);
          const double off_set = sums[x] * static_cast<double>(weight[i0 + x]);
          out[x] = static_cast<float>((in[i0 + x] ? on_set : off_set) * scale_in);
        }
      } else {
        for (Index x = 0; x < nx; ++x) {
          const double on_set = static_cast<double>(r[i0 + x] - cc);
          out[x] = static_cast<float>((in[i0 + x] ? on_set : 0.0) * scale_in);
        }
      }
    }
  };
  auto filtered_out = [&](Index first, Index rows, const float* buffer, Index ld, int thread) {
    const double scale_out = from_filter;
    double z_sum = 0;
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      for (Index x = 0; x < nx; ++x) {
        const T filtered = static_cast<T>(static_cast<double>(buffer[y * ld + x]) * scale_out);
        const T w = static_cast<T>(weight[i0 + x]);
        z[i0 + x] = in[i0 + x] ? filtered : (radius > 0 ? filtered * w : T(0));
      }
      z_sum += radius > 0 ? sum_after_transpose(in + i0, z + i0, window_count_.data() + i0, nx)
                          : sum_on_set(in + i0, z + i0, nx);
    }
    sums_[static_cast<std::size_t>(thread)].a += z_sum;
  };
  return filter_->apply(FilterProducer(residual_in), FilterConsumer(filtered_out), {}, true) * from_filter *
         from_filter;
}

// Operator: the direction t = (z - zbar) + beta t on the set in; the step tau = <r, z>/<t, G t> once the
// spectrum is multiplied; G t out: p -= tau t, u -= tau G t, and the sums of the new residual and of the
// pressure's change.
template <class T>
void ActiveSet<T>::operator_pass(std::vector<T>& p, CgStep& step) {
  using Producer = typename Convolution<T>::Producer;
  using Consumer = typename Convolution<T>::Consumer;
  using ProductHook = typename Convolution<T>::ProductHook;
  const std::uint8_t* const in = in_.data();
  const T* const z = z_.data();
  T* const t = t_.data();
  T* const u = u_.data();
  T* const r = r_.data();
  T* const pp = p.data();
  const Index nx = grid_.nx, radius = step.radius;
  const T &zbar = step.zbar, &beta = step.beta;
  T& tau = step.tau;
  double& t_gt = step.t_gt;
  const double &rz = step.rz, &c = step.c;
  // E^T's inputs: z off the set (already times its weight), 0 on it.
  auto transpose_inputs = [&](Index y, double* values) {
    const std::uint8_t* const in_row = in + y * nx;
    const T* const z_row = z + y * nx;
    for (Index x = 0; x < nx; ++x) {
      const double off_set = static_cast<double>(z_row[x]);
      values[x] = in_row[x] ? 0.0 : off_set;
    }
  };
  auto direction_in = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
    const T zb = zbar, b = beta;
    WindowRows& window = window_rows_[static_cast<std::size_t>(thread)];
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      // z on the set gains the window sums of z off it (E^T)
      const double* const sums = radius > 0 ? window.sums(first + y, transpose_inputs) : nullptr;
      for (Index x = 0; x < nx; ++x)  // t is read and written on the set only (b = 0 at a start)
        if (in[i0 + x]) {
          const T zk = sums ? static_cast<T>(static_cast<double>(z[i0 + x]) + sums[x]) : z[i0 + x];
          const T tv = (zk - zb) + b * t[i0 + x];
          t[i0 + x] = tv;
          buffer[y * ld + x] = tv;
        } else {
          buffer[y * ld + x] = T(0);
        }
    }
  };
  auto step_length = [&](double product) {
    t_gt = product;
    tau = static_cast<T>(t_gt > 0 ? rz / t_gt : 0.0);
  };
  auto stepped_out = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
    Sums s;  // local: see over_points
    s.e = s.f = -std::numeric_limits<double>::infinity();
    const T step = tau;
    const double shift = c;
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      double moved = 0, sum = 0;
      for (Index x = 0; x < nx; ++x) {
        const std::size_t k = static_cast<std::size_t>(i0 + x);
        const T w = buffer[y * ld + x];
        u[k] -= step * w;
        if (in[k]) {  // t = 0 off the set: p moves on it only
          const T change = step * t[k];
          moved += std::abs(static_cast<double>(change));
          pp[k] -= change;
          sum += std::abs(static_cast<double>(pp[k]));
          r[k] -= step * w;
          add_residual(s, static_cast<double>(r[k]) - shift);
        }
      }
      s.c += moved;
      s.d += sum;
    }
    sums_[static_cast<std::size_t>(thread)].add(s);
  };
  operator_->apply(Producer(direction_in), Consumer(stepped_out), {}, true, ProductHook(step_length));
}

template Index ActiveSet<double>::cg_on_set(std::vector<double>& p, double scale, double reduction,
                                            double absolute, double step_change, Index budget,
                                            const std::function<void()>& between);
template Index ActiveSet<float>::cg_on_set(std::vector<float>& p, double scale, double reduction,
                                           double absolute, double step_change, Index budget,
                                           const std::function<void()>& between);

template typename ActiveSet<double>::Sums ActiveSet<double>::count_on_set(std::vector<double>&, double);
template typename ActiveSet<float>::Sums ActiveSet<float>::count_on_set(std::vector<float>&, double);
template void ActiveSet<double>::make_extension_weights(Index);
template void ActiveSet<float>::make_extension_weights(Index);
template double ActiveSet<double>::filter_pass(const CgStep&);
template double ActiveSet<float>::filter_pass(const CgStep&);
template void ActiveSet<double>::operator_pass(std::vector<double>&, CgStep&);
template void ActiveSet<float>::operator_pass(std::vector<float>&, CgStep&);

}  // namespace contactbench

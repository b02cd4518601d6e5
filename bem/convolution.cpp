#include "contactbench/bem/convolution.hpp"

#include <algorithm>
#include <complex>
#include <cstring>
#include <string>

#include <fftw3.h>
#include <omp.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/fftw_precision.hpp"

namespace contactbench {

namespace {

// FFTW-aligned storage of n values of V (zeroed).
template <class T, class V>
class Aligned {
 public:
  Aligned() = default;
  explicit Aligned(Index n) : n_(n) {
    data_ = static_cast<V*>(Fftw<T>::malloc(sizeof(V) * static_cast<std::size_t>(std::max<Index>(n, 1))));
    if (!data_) throw Error("FFT: out of memory for a buffer of " + std::to_string(n) + " values");
    std::memset(static_cast<void*>(data_), 0, sizeof(V) * static_cast<std::size_t>(n));
  }
  ~Aligned() { Fftw<T>::free(data_); }
  Aligned(Aligned&& o) noexcept : data_(o.data_), n_(o.n_) { o.data_ = nullptr; }
  Aligned& operator=(Aligned&& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(n_, o.n_);
    return *this;
  }
  V* get() const { return data_; }
  V& operator[](Index i) const { return data_[i]; }
  void zero() { std::memset(static_cast<void*>(data_), 0, sizeof(V) * static_cast<std::size_t>(n_)); }

 private:
  V* data_ = nullptr;
  Index n_ = 0;
};

constexpr Index kRowsPerChunk = 8;  // rows per transform call: a chunk of 2 nx doubles a row fits in L2

// The element-wise work around the column transforms, compiled for SSE2 and AVX2 (chosen at load time).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CB_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define CB_KERNEL
#endif

// A block of `cols` spectral columns (rows `stride` apart, `rows` of them) into `block`, transposed so that
// each column is contiguous and `length` long, the rows beyond `rows` zero (the padding).
template <class C>
CB_KERNEL void load_block(const C* __restrict from, Index stride, Index rows, Index length, Index cols,
                          C* __restrict block) {
  for (Index y = 0; y < rows; ++y)
    for (Index j = 0; j < cols; ++j)
      block[j * length + y] = from[y * stride + j];
  for (Index j = 0; j < cols; ++j)
    for (Index y = rows; y < length; ++y)
      block[j * length + y] = C(0);
}

// The block back into the spectrum, conjugated: the column transform back is the forward one between two
// conjugations (backward(c) = conj(forward(conj c))), the first folded into multiply_column, this the second,
// so that one measured plan serves both directions (docs/solvers.md, Planning).
template <class C>
CB_KERNEL void store_block(const C* __restrict block, Index length, Index rows, Index cols, C* __restrict to,
                           Index stride) {
  for (Index y = 0; y < rows; ++y)
    for (Index j = 0; j < cols; ++j)
      to[y * stride + j] = std::conj(block[j * length + y]);
}

// One column (length values, interleaved re, im) times the even multiplier m (m[k] for k <= length/2,
// m[length - k] beyond), conjugated (for the transform back, see store_block); with `energy`, returns
// sum m |c|^2 of the column before the product.
template <class T>
CB_KERNEL double multiply_column(std::complex<T>* column, const T* __restrict m, Index length, bool energy) {
  T* __restrict c = reinterpret_cast<T*>(column);
  const Index half = length / 2;
  double sum = 0;
  if (energy) {
#pragma omp simd reduction(+ : sum)
    for (Index k = 0; k <= half; ++k) {
      const T re = c[2 * k], im = c[2 * k + 1];
      sum += static_cast<double>(m[k]) * (static_cast<double>(re) * re + static_cast<double>(im) * im);
    }
#pragma omp simd reduction(+ : sum)
    for (Index k = half + 1; k < length; ++k) {
      const T re = c[2 * k], im = c[2 * k + 1];
      sum +=
          static_cast<double>(m[length - k]) * (static_cast<double>(re) * re + static_cast<double>(im) * im);
    }
  }
#pragma omp simd
  for (Index k = 0; k <= half; ++k) {
    c[2 * k] *= m[k];
    c[2 * k + 1] *= -m[k];
  }
#pragma omp simd
  for (Index k = half + 1; k < length; ++k) {
    c[2 * k] *= m[length - k];
    c[2 * k + 1] *= -m[length - k];
  }
  return sum;
}

}  // namespace

template <class T>
struct Convolution<T>::Impl {
  using F = Fftw<T>;
  using Cx = std::complex<T>;
  static constexpr Index kColumnsPerBlock =
      64 / static_cast<Index>(sizeof(Cx));  // a 64-byte stretch (measured best)

  Index nxh = 0;                // lx/2 + 1 columns of the half spectrum
  Index mult_rows = 0;          // ly/2 + 1 rows of the multiplier kept (it is even in ky)
  Aligned<T, Cx> spectrum;      // ny x nxh: the rows' transforms, then the result before the last stage
  Aligned<T, T> multiplier;     // nxh columns of mult_rows values, a column contiguous
  std::vector<double> weights;  // per spectral column: 1 or 2 (its Hermitian partner counted)
  std::vector<Aligned<T, T>> rows_in, rows_out;  // per thread: kRowsPerChunk x lx
  std::vector<Aligned<T, Cx>> columns;           // per thread: ly x kColumnsPerBlock
  struct alignas(64) Partial {
    double energy = 0;
  };
  std::vector<Partial> partial;
  // One column plan for every block and both directions (a block of fewer columns runs it on a buffer
  // padded with zero columns; the transform back is the forward one between conjugations): fewer plans to
  // measure on a first run (docs/solvers.md, Planning).
  typename F::Plan r2c_full = nullptr, r2c_rest = nullptr, c2r_full = nullptr, c2r_rest = nullptr;
  typename F::Plan columns_forward = nullptr;

  ~Impl() {
    auto lock = lock_fftw_planner();
    for (auto p : {r2c_full, r2c_rest, c2r_full, c2r_rest, columns_forward})
      F::destroy(p);
  }
};

template <class T>
Convolution<T>::Convolution(Index nx, Index ny, bool padded, int threads, FftRigor plan_rigor)
    : nx_(nx),
      ny_(ny),
      padded_(padded),
      lx_(padded ? 2 * nx : nx),
      ly_(padded ? 2 * ny : ny),
      threads_(1),
      impl_(std::make_unique<Impl>()) {
  if (nx < 1 || ny < 1)
    throw Error("convolution: the grid must be at least 1 x 1, got " + std::to_string(nx) + " x " +
                std::to_string(ny));
  threads_ = team_size(lx_ * ly_, threads);
  Impl& m = *impl_;
  using F = typename Impl::F;
  using FCx = typename F::Cx;
  constexpr Index B = Impl::kColumnsPerBlock;
  m.nxh = lx_ / 2 + 1;
  m.mult_rows = ly_ / 2 + 1;
  m.spectrum = Aligned<T, typename Impl::Cx>(ny_ * m.nxh);
  m.multiplier = Aligned<T, T>(m.mult_rows * m.nxh);
  m.weights.assign(static_cast<std::size_t>(m.nxh), 2.0);
  m.weights[0] = 1;
  if (lx_ % 2 == 0) m.weights[static_cast<std::size_t>(lx_ / 2)] = 1;
  for (int t = 0; t < threads_; ++t) {
    m.rows_in.emplace_back(kRowsPerChunk * lx_);
    m.rows_out.emplace_back(kRowsPerChunk * lx_);
    m.columns.emplace_back(ly_ * B);
  }
  m.partial.resize(static_cast<std::size_t>(threads_));

  // Every chunk of rows starts at the same alignment as the first (checked, not assumed: otherwise FFTW is
  // told the arrays may be unaligned).
  auto* spectrum = reinterpret_cast<FCx*>(m.spectrum.get());
  bool aligned = true;
  for (Index row = 0; row < ny_; row += kRowsPerChunk)
    aligned = aligned && F::alignment_of(reinterpret_cast<T*>(spectrum + row * m.nxh)) ==
                             F::alignment_of(reinterpret_cast<T*>(spectrum));
  // Measured plans apply 10-30 % faster than estimated ones (measured at 128^2 to 1024^2) and cost 0.25 s
  // (256^2) to 1.3 s (1024^2, padded) to make, once per shape and process unless FFTW's wisdom holds them
  // (docs/solvers.md, Planning); a convolution has three (r2c and c2r of a chunk of rows, the c2c of a block
  // of columns; two more for a last chunk of fewer rows), of which only the column plan is ever measured.
  // `measure` measures lattices of kMinPointsForThreads points and more;
  // `by_work` takes measured plans the wisdom holds already (FFTW_WISDOM_ONLY: none made otherwise) and
  // else lets choose_fft_rigor decide; small lattices and `estimate` are estimated.
  const int n_x = static_cast<int>(lx_), n_y = static_cast<int>(ly_), nxh = static_cast<int>(m.nxh);
  const int rest_rows = static_cast<int>(ny_ % kRowsPerChunk);
  const bool has_rest_rows = rest_rows && ny_ > kRowsPerChunk;
  auto* columns = reinterpret_cast<FCx*>(m.columns[0].get());
  const unsigned alignment = aligned ? 0u : FFTW_UNALIGNED;
  // The column plan at `rigor`, the row plans always estimated: measured rows save 0.5 ms of CPU a
  // convolution at 1024^2 (8 % of its transforms) and nothing at 2048^2, for about 0.3 s more of a first
  // run's planning (bench/fft_planning_cost.cpp; docs/solvers.md, Planning). False (none kept) when one
  // could not be made.
  auto make_plans = [&](unsigned rigor) {
    const unsigned flags = FFTW_ESTIMATE | alignment;
    const int full_rows = static_cast<int>(std::min<Index>(kRowsPerChunk, ny_));
    m.r2c_full = F::r2c(n_x, full_rows, m.rows_in[0].get(), n_x, spectrum, nxh, flags);
    m.c2r_full = F::c2r(n_x, full_rows, spectrum, nxh, m.rows_out[0].get(), n_x, flags);
    if (has_rest_rows) {
      m.r2c_rest = F::r2c(n_x, rest_rows, m.rows_in[0].get(), n_x, spectrum, nxh, flags);
      m.c2r_rest = F::c2r(n_x, rest_rows, spectrum, nxh, m.rows_out[0].get(), n_x, flags);
    }
    m.columns_forward =
        F::c2c(n_y, static_cast<int>(std::min<Index>(B, m.nxh)), columns, FFTW_FORWARD, rigor);
    const bool made =
        m.r2c_full && m.c2r_full && m.columns_forward && (!has_rest_rows || (m.r2c_rest && m.c2r_rest));
    if (!made)
      for (auto* plan : {&m.r2c_full, &m.r2c_rest, &m.c2r_full, &m.c2r_rest, &m.columns_forward}) {
        F::destroy(*plan);
        *plan = nullptr;
      }
    return made;
  };
  const Index points = lx_ * ly_;
  bool made = false;
  {
    auto lock = lock_fftw_planner();
    const FftwPlanningClock clock;
    F::plan_with_nthreads(1);
    if (plan_rigor == FftRigor::by_work && points >= kMinPointsForMeasuredPlans) {
      made = make_plans(FFTW_MEASURE | FFTW_WISDOM_ONLY);
      if (made) planned_rigor_ = FftRigor::measure;
    }
    if (!made) {
      const FftRigor rigor = choose_fft_rigor(plan_rigor, points);
      planned_rigor_ = rigor == FftRigor::measure && points >= kMinPointsForThreads ? FftRigor::measure
                                                                                    : FftRigor::estimate;
      made = make_plans(planned_rigor_ == FftRigor::measure ? FFTW_MEASURE : FFTW_ESTIMATE);
    }
  }
  if (!made)
    throw Error("convolution: FFTW could not plan the transforms of a " + std::to_string(lx_) + " x " +
                std::to_string(ly_) + " lattice");
  // Measuring wrote into the buffers: the padding of the input rows must be zero.
  for (auto& b : m.rows_in)
    b.zero();
}

template <class T>
Convolution<T>::~Convolution() = default;

template <class T>
void Convolution<T>::set_multiplier(
    const Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& multiplier) {
  Impl& m = *impl_;
  if (multiplier.rows() != ly_ || multiplier.cols() != m.nxh)
    throw Error("convolution: the multiplier must be " + std::to_string(ly_) + " x " + std::to_string(m.nxh) +
                ", got " + std::to_string(multiplier.rows()) + " x " + std::to_string(multiplier.cols()));
  for (Index ky = 0; ky < m.mult_rows; ++ky)
    for (Index c = 0; c < m.nxh; ++c)
      m.multiplier[c * m.mult_rows + ky] = static_cast<T>(multiplier(ky, c));
  double sum = 0;
  for (Index ky = 0; ky < ly_; ++ky)
    for (Index c = 0; c < m.nxh; ++c)
      sum += m.weights[static_cast<std::size_t>(c)] * multiplier(ky, c);
  self_response_ = sum;
}

template <class T>
double Convolution<T>::apply(Producer produce, Consumer consume, Hook between, bool product,
                             ProductHook multiplied) {
  Impl& m = *impl_;
  using F = typename Impl::F;
  using FCx = typename F::Cx;
  using Cx = typename Impl::Cx;
  constexpr Index B = Impl::kColumnsPerBlock;
  const Index nxh = m.nxh, ny = ny_, ly = ly_, mult_rows = m.mult_rows;
  const bool want_energy = product || static_cast<bool>(multiplied);
  const Index row_chunks = (ny + kRowsPerChunk - 1) / kRowsPerChunk;
  const Index column_blocks = (nxh + B - 1) / B;
  const bool inverse = static_cast<bool>(consume);
  Cx* const spectrum = m.spectrum.get();
  const T* const multiplier = m.multiplier.get();
  for (auto& p : m.partial)
    p.energy = 0;

#pragma omp parallel num_threads(threads_) if (threads_ > 1)
  {
    const int thread = omp_get_thread_num();
    T* const rows_in = m.rows_in[static_cast<std::size_t>(thread)].get();
    T* const rows_out = m.rows_out[static_cast<std::size_t>(thread)].get();
    Cx* const columns = m.columns[static_cast<std::size_t>(thread)].get();

    // 1. Rows: the caller writes them, real-to-complex along x.
#pragma omp for schedule(static)
    for (Index chunk = 0; chunk < row_chunks; ++chunk) {
      const Index first = chunk * kRowsPerChunk, rows = std::min(kRowsPerChunk, ny - first);
      produce(first, rows, rows_in, lx_, thread);
      F::execute_r2c(rows == kRowsPerChunk || ny < kRowsPerChunk ? m.r2c_full : m.r2c_rest, rows_in,
                     reinterpret_cast<FCx*>(spectrum + first * nxh));
    }

    if (between) {
#pragma omp single
      between();
    }

    // 2. Columns, a block at a time in cache: along y, multiply, back.
    double energy = 0;
#pragma omp for schedule(static)
    for (Index block = 0; block < column_blocks; ++block) {
      const Index c0 = block * B, cols = std::min(B, nxh - c0);
      load_block(spectrum + c0, nxh, ny, ly, cols, columns);
      // The last block of fewer columns runs the block's plan too, on zero columns beyond its own.
      if (cols < B && nxh > B) std::fill(columns + cols * ly, columns + B * ly, Cx(0));
      F::execute_c2c(m.columns_forward, reinterpret_cast<FCx*>(columns));
      for (Index j = 0; j < cols; ++j) {
        const double sum =
            multiply_column(columns + j * ly, multiplier + (c0 + j) * mult_rows, ly, want_energy);
        energy += m.weights[static_cast<std::size_t>(c0 + j)] * sum;
      }
      if (inverse) {
        F::execute_c2c(m.columns_forward, reinterpret_cast<FCx*>(columns));  // back: see store_block
        store_block(columns, ly, ny, cols, spectrum + c0, nxh);
      }
    }
    m.partial[static_cast<std::size_t>(thread)].energy = energy;
    if (multiplied) {
#pragma omp barrier
#pragma omp single
      {
        double all = 0;  // in thread order: the same sum every run
        for (const auto& p : m.partial)
          all += p.energy;
        multiplied(all);
      }
    }

    // 3. Rows: complex-to-real along x, read by the caller.
    if (inverse) {
#pragma omp for schedule(static)
      for (Index chunk = 0; chunk < row_chunks; ++chunk) {
        const Index first = chunk * kRowsPerChunk, rows = std::min(kRowsPerChunk, ny - first);
        F::execute_c2r(rows == kRowsPerChunk || ny < kRowsPerChunk ? m.c2r_full : m.c2r_rest,
                       reinterpret_cast<FCx*>(spectrum + first * nxh), rows_out);
        consume(first, rows, rows_out, lx_, thread);
      }
    }
  }
  double energy = 0;
  for (const auto& p : m.partial)
    energy += p.energy;
  return energy;
}

template <class T>
void Convolution<T>::apply(const T* in, T* out) {
  const Index nx = nx_;
  auto produce = [&](Index first, Index rows, T* buffer, Index ld, int) {
    for (Index r = 0; r < rows; ++r)
      std::copy_n(in + (first + r) * nx, nx, buffer + r * ld);
  };
  auto consume = [&](Index first, Index rows, const T* buffer, Index ld, int) {
    for (Index r = 0; r < rows; ++r)
      std::copy_n(buffer + r * ld, nx, out + (first + r) * nx);
  };
  apply(Producer(produce), Consumer(consume));
}

template class Convolution<double>;
template class Convolution<float>;

}  // namespace contactbench

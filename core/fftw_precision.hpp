// FFTW's double (fftw_*) and single-precision (fftwf_*) interfaces behind one name, for the engines that
// run in either precision (bem/convolution.cpp, mpi/slab_convolution_engine.cpp): one-dimensional plans of
// many lines, executed on new arrays.
#pragma once

#include <cstddef>

#include <fftw3.h>

namespace contactbench {

template <class T>
struct Fftw;

template <>
struct Fftw<double> {
  using Plan = fftw_plan;
  using Cx = fftw_complex;
  static void* malloc(std::size_t bytes) { return fftw_malloc(bytes); }
  static void free(void* p) { fftw_free(p); }
  static int alignment_of(double* p) { return fftw_alignment_of(p); }
  static void plan_with_nthreads(int n) { fftw_plan_with_nthreads(n); }
  static Plan r2c(int n, int howmany, double* in, int idist, Cx* out, int odist, unsigned flags) {
    return fftw_plan_many_dft_r2c(1, &n, howmany, in, nullptr, 1, idist, out, nullptr, 1, odist, flags);
  }
  static Plan c2r(int n, int howmany, Cx* in, int idist, double* out, int odist, unsigned flags) {
    return fftw_plan_many_dft_c2r(1, &n, howmany, in, nullptr, 1, idist, out, nullptr, 1, odist, flags);
  }
  static Plan c2c(int n, int howmany, Cx* data, int sign, unsigned flags) {  // contiguous, in place
    return fftw_plan_many_dft(1, &n, howmany, data, nullptr, 1, n, data, nullptr, 1, n, sign, flags);
  }
  static void execute_r2c(Plan p, double* in, Cx* out) { fftw_execute_dft_r2c(p, in, out); }
  static void execute_c2r(Plan p, Cx* in, double* out) { fftw_execute_dft_c2r(p, in, out); }
  static void execute_c2c(Plan p, Cx* data) { fftw_execute_dft(p, data, data); }
  static void destroy(Plan p) {
    if (p) fftw_destroy_plan(p);
  }
};

template <>
struct Fftw<float> {
  using Plan = fftwf_plan;
  using Cx = fftwf_complex;
  static void* malloc(std::size_t bytes) { return fftwf_malloc(bytes); }
  static void free(void* p) { fftwf_free(p); }
  static int alignment_of(float* p) { return fftwf_alignment_of(p); }
  static void plan_with_nthreads(int n) { fftwf_plan_with_nthreads(n); }
  static Plan r2c(int n, int howmany, float* in, int idist, Cx* out, int odist, unsigned flags) {
    return fftwf_plan_many_dft_r2c(1, &n, howmany, in, nullptr, 1, idist, out, nullptr, 1, odist, flags);
  }
  static Plan c2r(int n, int howmany, Cx* in, int idist, float* out, int odist, unsigned flags) {
    return fftwf_plan_many_dft_c2r(1, &n, howmany, in, nullptr, 1, idist, out, nullptr, 1, odist, flags);
  }
  static Plan c2c(int n, int howmany, Cx* data, int sign, unsigned flags) {  // contiguous, in place
    return fftwf_plan_many_dft(1, &n, howmany, data, nullptr, 1, n, data, nullptr, 1, n, sign, flags);
  }
  static void execute_r2c(Plan p, float* in, Cx* out) { fftwf_execute_dft_r2c(p, in, out); }
  static void execute_c2r(Plan p, Cx* in, float* out) { fftwf_execute_dft_c2r(p, in, out); }
  static void execute_c2c(Plan p, Cx* data) { fftwf_execute_dft(p, data, data); }
  static void destroy(Plan p) {
    if (p) fftwf_destroy_plan(p);
  }
};

}  // namespace contactbench

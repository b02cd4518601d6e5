// What FFTW_MEASURE costs for the plans of one bem/convolution.cpp Convolution<double> (issue 42: the first,
// cold run of `contactbench bem` on 1024^2 spends half its time here), plan by plan, and what a planning
// time limit (fftw_set_timelimit) does to the plans and to the wisdom a run would keep.
//
// Standalone (FFTW only, not part of the CMake build), so that it measures the planner and nothing else:
//   g++ -O2 -std=c++20 bench/fft_planning_cost.cpp -lfftw3 -o /tmp/fft_planning_cost
//   OMP_WAIT_POLICY=PASSIVE /tmp/fft_planning_cost 1024 3
// (lattice side, repetitions). The plans are the convolution's: batched 1D transforms of one chunk, single-
// threaded (each thread of the solve's team runs its own chunks), on FFTW-aligned buffers of the same shapes:
// r2c / c2r of 8 rows of n, and c2c forward / backward of a block of 4 columns of n (64 bytes of doubles),
// and of the 1 column left over (n/2+1 = 4 k + 1 columns).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include <fftw3.h>

namespace {

// CPU seconds of this (single-threaded) process: on the shared machine the wall time of a plan is inflated by
// other processes, its CPU time much less.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

struct Buffers {
  int n;
  double* rows;         // 8 x n
  fftw_complex* half;   // 8 x (n/2+1)
  fftw_complex* block;  // 4 x n, a column contiguous
  explicit Buffers(int side) : n(side) {
    rows = fftw_alloc_real(8 * static_cast<size_t>(n));
    half = fftw_alloc_complex(8 * static_cast<size_t>(n / 2 + 1));
    block = fftw_alloc_complex(4 * static_cast<size_t>(n));
  }
  ~Buffers() {
    fftw_free(rows);
    fftw_free(half);
    fftw_free(block);
  }
};

struct PlanKind {
  const char* name;
  int per_application;  // executions per application of the convolution (n x n periodic)
  std::function<fftw_plan(Buffers&, unsigned)> make;
};

std::vector<PlanKind> kinds(int n) {
  const int h = n / 2 + 1;
  auto c2c = [](Buffers& b, int howmany, int sign, unsigned flags) {
    return fftw_plan_many_dft(1, &b.n, howmany, b.block, nullptr, 1, b.n, b.block, nullptr, 1, b.n, sign,
                              flags);
  };
  return {
      {"r2c, 8 rows", n / 8,
       [h](Buffers& b, unsigned f) {
         return fftw_plan_many_dft_r2c(1, &b.n, 8, b.rows, nullptr, 1, b.n, b.half, nullptr, 1, h, f);
       }},
      {"c2r, 8 rows", n / 8,
       [h](Buffers& b, unsigned f) {
         return fftw_plan_many_dft_c2r(1, &b.n, 8, b.half, nullptr, 1, h, b.rows, nullptr, 1, b.n, f);
       }},
      {"c2c forward, 4 columns", h / 4, [c2c](Buffers& b, unsigned f) { return c2c(b, 4, FFTW_FORWARD, f); }},
      {"c2c backward, 4 columns", h / 4,
       [c2c](Buffers& b, unsigned f) { return c2c(b, 4, FFTW_BACKWARD, f); }},
      {"c2c forward, 1 column (rest)", h % 4,
       [c2c](Buffers& b, unsigned f) { return c2c(b, 1, FFTW_FORWARD, f); }},
      {"c2c backward, 1 column (rest)", h % 4,
       [c2c](Buffers& b, unsigned f) { return c2c(b, 1, FFTW_BACKWARD, f); }},
  };
}

// CPU seconds to make the plan with `flags` (the plan is kept in *made).
double plan_seconds(const PlanKind& kind, Buffers& b, unsigned flags, fftw_plan* made) {
  const double start = cpu_seconds();
  *made = kind.make(b, flags);
  const double t = cpu_seconds() - start;
  if (!*made) {
    std::fprintf(stderr, "fft_planning_cost: FFTW made no plan for %s\n", kind.name);
    std::exit(1);
  }
  return t;
}

// CPU microseconds per execution (the median of 7 batches of 200, after 50 unmeasured).
double execute_microseconds(fftw_plan plan) {
  for (int i = 0; i < 50; ++i)
    fftw_execute(plan);
  std::vector<double> batches;
  for (int batch = 0; batch < 7; ++batch) {
    const double start = cpu_seconds();
    for (int i = 0; i < 200; ++i)
      fftw_execute(plan);
    batches.push_back((cpu_seconds() - start) / 200 * 1e6);
  }
  return median(batches);
}

std::string plan_text(fftw_plan plan) {
  char* text = fftw_sprint_plan(plan);
  std::string s(text);
  std::free(text);
  s.erase(std::remove(s.begin(), s.end(), '\n'), s.end());
  return s;
}

int count_of(const std::string& text, const std::string& what) {
  int count = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++count;
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1024;
  const int repetitions = argc > 2 ? std::atoi(argv[2]) : 3;
  Buffers b(n);
  const auto plans = kinds(n);
  std::printf("# FFTW planning of one Convolution<double> at %d^2 periodic (%s), medians of %d\n\n", n,
              fftw_version, repetitions);

  // 1. Each plan alone, no wisdom: planning seconds at MEASURE, and each plan's execution, estimated /
  // measured.
  std::printf(
      "| plan | executions per application | plan MEASURE alone [CPU s] | execute ESTIMATE / MEASURE [CPU "
      "us] | "
      "saved per application [ms] | same algorithm |\n|---|---:|---:|---:|---:|---|\n");
  double saved_total = 0;
  for (const auto& kind : plans) {
    std::vector<double> planning, estimated, measured;
    bool same = true;
    for (int r = 0; r < repetitions; ++r) {
      fftw_forget_wisdom();
      fftw_plan e, m;
      plan_seconds(kind, b, FFTW_ESTIMATE, &e);
      planning.push_back(plan_seconds(kind, b, FFTW_MEASURE, &m));
      estimated.push_back(execute_microseconds(e));
      measured.push_back(execute_microseconds(m));
      same = same && plan_text(e) == plan_text(m);
      fftw_destroy_plan(e);
      fftw_destroy_plan(m);
    }
    const double saved = (median(estimated) - median(measured)) * kind.per_application * 1e-3;
    saved_total += saved;
    std::printf("| %s | %d | %.3f | %.2f / %.2f | %.3f | %s |\n", kind.name, kind.per_application,
                median(planning), median(estimated), median(measured), saved, same ? "yes" : "no");
  }
  std::printf("\nSaved per application of the convolution by the measured plans: %.3f ms\n\n", saved_total);

  // 2. The plan sets a convolution makes, in its order, from no wisdom (later plans reuse the sub-plans the
  // earlier ones measured): all six; without the rest plans (the last block run by the 4-column plans); and
  // without the backward c2c too (backward = conj forward conj).
  std::printf(
      "| plans measured, in order from no wisdom | planning [CPU s], median | each [CPU s] "
      "|\n|---|---:|---|\n");
  const std::vector<std::pair<const char*, std::vector<int>>> sets = {
      {"all six (r2c, c2r, c2c fwd/bwd 4 columns, c2c fwd/bwd 1 column)", {0, 1, 2, 3, 4, 5}},
      {"four (no rest plans)", {0, 1, 2, 3}},
      {"three (no rest plans, no backward c2c)", {0, 1, 2}},
  };
  for (const auto& [name, members] : sets) {
    std::vector<double> totals;
    for (int r = 0; r < repetitions; ++r) {
      fftw_forget_wisdom();
      double total = 0;
      for (int k : members) {
        fftw_plan p;
        total += plan_seconds(plans[static_cast<std::size_t>(k)], b, FFTW_MEASURE, &p);
        fftw_destroy_plan(p);
      }
      totals.push_back(total);
    }
    std::string each;
    for (double t : totals)
      each += (each.empty() ? "" : " / ") + std::to_string(t).substr(0, 5);
    std::printf("| %s | %.3f | %s |\n", name, median(totals), each.c_str());
  }

  // 3. A time limit per plan: planning time, whether the plans are the measured ones, what the wisdom keeps,
  // and what a later run with that wisdom and the same limit gets.
  std::printf(
      "\n| time limit per plan [s] | planning, 3 plans [CPU s] | plans equal to unlimited MEASURE's | wisdom "
      "TIMEOUT entries | later run: found by WISDOM_ONLY | later run's planning [CPU s] |\n"
      "|---:|---:|---|---:|---|---:|\n");
  fftw_forget_wisdom();
  std::vector<std::string> unlimited;
  for (int k = 0; k < 3; ++k) {
    fftw_plan p;
    plan_seconds(plans[static_cast<std::size_t>(k)], b, FFTW_MEASURE, &p);
    unlimited.push_back(plan_text(p));
    fftw_destroy_plan(p);
  }
  for (double limit : {0.01, 0.03, 0.1, 0.3}) {
    fftw_forget_wisdom();
    fftw_set_timelimit(limit);
    double total = 0;
    int equal = 0;
    for (int k = 0; k < 3; ++k) {
      fftw_plan p;
      total += plan_seconds(plans[static_cast<std::size_t>(k)], b, FFTW_MEASURE, &p);
      equal += plan_text(p) == unlimited[static_cast<std::size_t>(k)];
      fftw_destroy_plan(p);
    }
    char* exported = fftw_export_wisdom_to_string();
    const std::string wisdom(exported);
    std::free(exported);
    fftw_forget_wisdom();
    fftw_import_wisdom_from_string(wisdom.c_str());
    int found = 0;
    double later = 0;
    for (int k = 0; k < 3; ++k) {
      fftw_plan p = plans[static_cast<std::size_t>(k)].make(b, FFTW_MEASURE | FFTW_WISDOM_ONLY);
      if (p) {
        ++found;
        fftw_destroy_plan(p);
      }
      later += plan_seconds(plans[static_cast<std::size_t>(k)], b, FFTW_MEASURE, &p);
      fftw_destroy_plan(p);
    }
    fftw_set_timelimit(FFTW_NO_TIMELIMIT);
    std::printf("| %.2f | %.3f | %d of 3 | %d | %d of 3 | %.3f |\n", limit, total, equal,
                count_of(wisdom, "TIMEOUT"), found, later);
  }
  return 0;
}

// FFTW's wisdom (the plans its planner chose by measuring) kept in a file between processes, so that a
// measured plan is paid once per machine and not once per run (docs/solvers.md, Planning).
//
// One text file holds both precisions, which are separate FFTW libraries (fftw_ for double, fftwf_ for
// float): a header line naming the key the file is valid for, then FFTW's own export of each. A plan made
// after importing is the plan the exporting process measured, so its transforms are bit-identical to that
// process's; without wisdom FFTW_MEASURE chooses again by timing, and may choose an algorithm with
// different round-off.
//
// Library functions only: which file, and what to say when it is bad, is the application's (app/).
#pragma once

#include <filesystem>
#include <string>

namespace contactbench {

// What a wisdom file is valid for, as its header names it: this FFTW build (version and SIMD codelets, e.g.
// "fftw-3.3.10-sse2-avx2"), the thread count of the command and the planner rigor. FFTW itself keeps each
// plan's shape, precision and flags inside the file; a file of another key is foreign and is not imported.
// `distributed`: the process runs FFTW-MPI's planners too (rank 0 under mpiexec), whose wisdom names solvers
// a process without FFTW-MPI refuses (the whole double part with them): such wisdom has a key of its own.
std::string fftw_wisdom_key(int threads, bool distributed = false);

// What reading a wisdom file did.
struct WisdomImport {
  bool found = false;        // the file exists (a missing file is no problem: nothing to import yet)
  bool wisdom_file = false;  // it starts with a wisdom header (any key); a file that does not is not ours
  bool imported = false;     // both precisions' wisdom was accepted
  std::string problem;       // why nothing or only part was imported (empty when imported or not found)
};

// Reads `path` and gives its wisdom to both planners when its header names `key`. Never throws for bad
// content: a foreign, corrupt, unreadable or oversized file imports nothing (FFTW keeps its wisdom as it was
// when a part is refused) and says why in `problem`.
WisdomImport import_fftw_wisdom(const std::filesystem::path& path, const std::string& key);

// The planners' wisdom as the file holds it, under `key`.
std::string fftw_wisdom_text(const std::string& key);

// Writes fftw_wisdom_text(key) to `path` atomically (core/atomic_file.hpp): a reader sees the old file or the
// new one, never half of one. Throws Error when it cannot be written; `path` then holds what it held.
void export_fftw_wisdom(const std::filesystem::path& path, const std::string& key);

// Drops every plan choice both planners remember (plans already made stay valid). For tests.
void forget_fftw_wisdom();

}  // namespace contactbench

// A scene whose [surface] file is a line scan (docs/formats.md "line scans"): one profile h(x) of a stylus
// profilometer. It drives the methods that read the surface's moments alone (the analytic theories), which
// see the isotropic surface whose every profile has this profile's moments; every method that needs heights
// over an area is refused in preflight, saying why (app/scene_run.cpp).
#pragma once

#include <string>

#include "contactbench/app/surface_source.hpp"
#include "contactbench/core/profile_statistics.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

struct LineScanSurface {
  // The levelled profile as one row of heights over x (its steps may be uneven: only the nominal area is
  // read from this grid, lx = ly = the scan's length, a square patch of the surface the profile samples).
  Surface profile;
  ProfileStatistics statistics;  // of the levelled profile (core/profile_statistics.hpp)
  SpectralMoments moments;       // isotropic_moments(statistics)
  std::string source;            // "dektak" or "x h text"
  Levelling level = Levelling::none;
};

// Whether the scene's surface is a file holding a line scan (reads the file's start to tell).
bool is_line_scan(const SurfaceSpec& spec);

// Reads and levels the line scan of a file surface (`unit` and `level` apply; the keys of a 2-D file,
// size, periodic, channel, fill, crop and align_rows, are refused naming them). Throws InputError.
LineScanSurface read_line_scan_surface(const SurfaceSpec& spec);

// The report's sentence on the scan: points, length, sampling, levelling, and what the theories assume.
std::string describe(const LineScanSurface& scan);

}  // namespace contactbench

// Where a scene's surface comes from, all in one place: the [surface] keys (read and written back), and
// making the surface they describe (generated, or read from a topography file), with its heights measured
// from their mean plane, the plane every method's separation is measured from (docs/theory.md section 0).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <variant>

#include "contactbench/core/formats/crop.hpp"
#include "contactbench/core/formats/row_alignment.hpp"
#include "contactbench/core/formats/surface_repair.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/topography_io.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

class Section;     // app/scene_toml.hpp
struct SceneKeys;  // app/scene_keys.hpp

// [surface] generate = { ... }: the paper's self-affine generator (docs/theory.md section 2), SI units.
struct GeneratedSurfaceSpec {
  Real sigma = 0;          // rms height [m]
  Real hurst = 0;          // Hurst exponent, (0, 1]
  Real qr = 0;             // roll-off wavevector [1/m]
  std::optional<Real> qs;  // cut-off wavevector [1/m]; default: the grid's Nyquist wavevector
  Real size = 0;           // lateral size [m] (square)
  Index grid = 0;          // points a side of the generated surface
  std::uint64_t seed = 1;  // random seed
  Index refine = 0;        // points a side after Fourier refinement; 0 = no refinement
  Real anisotropy = 1;     // requested m2x/m2y
};

// [surface] file = "...": a measured (or any) topography, read by core/topography_io.
struct FileSurfaceSpec {
  std::filesystem::path path;    // resolved against the scene file's folder when relative
  std::optional<Real> size_x;    // [m], required when the file does not state its size
  std::optional<Real> size_y;    // [m]
  std::optional<bool> periodic;  // absent: the file's own (the project's format says; others are not)
  // docs/formats.md: which channel (name or 0-based index as text), how invalid points are filled, levelling.
  std::optional<std::string> channel;
  FillMethod fill = FillMethod::none;
  Levelling level = Levelling::none;
  // unit = "nm": the unit of a file that states none (matrices, .npy, x y z lists); docs/formats.md.
  std::optional<std::string> unit;
  // crop = "measured" | "px:..." | "m:..."; align_rows = "none" | "mean" | "median" | "linear".
  std::optional<CropSpec> crop;
  RowAlignment align_rows = RowAlignment::none;
};

struct SurfaceSpec {
  std::variant<GeneratedSurfaceSpec, FileSurfaceSpec> source;
};

// Points a side of the surface as the scene defines it, when known without reading a file.
std::optional<Index> points_a_side(const SurfaceSpec& surface);

// Reads [surface] (the Section is the scene's root); nullopt when it has problems (reported).
std::optional<SurfaceSpec> read_surface_keys(const Section& root, const std::filesystem::path& folder);

// Writes [surface] back, defaults filled in. Throws Error for a seed above 2^63 - 1 (no TOML integer).
void write_surface_keys(const SurfaceSpec& surface, SceneKeys& root);

// The surface the spec describes, its heights centred on their mean plane.
Surface make_surface(const SurfaceSpec& spec, int threads);
// The options a file surface is read with (make_surface's, for a reader of slabs:
// app/distributed_stages.cpp).
TopographyReadOptions read_options(const FileSurfaceSpec& file, int threads);

}  // namespace contactbench

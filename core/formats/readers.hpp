// One reader per instrument format (docs/formats.md). Each takes the whole file in memory and returns every
// channel it holds, heights in metres, invalid points as NaN; any defect throws InputError naming the file.
#pragma once

#include <filesystem>
#include <string_view>

#include "contactbench/core/formats/raw_topography.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench::formats {

RawTopography read_x3p(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_sdf(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_npy(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_metropro(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_nanoscope(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_sensofar(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_digital_surf(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_wyko(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_netcdf(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_gwy(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_alicona(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_nanosurf(const std::filesystem::path& path, std::string_view bytes);
RawTopography read_agilent_mi(const std::filesystem::path& path, std::string_view bytes);

// Content signatures, each looking only at the first bytes.
bool looks_like_zip(std::string_view bytes);
bool looks_like_sdf(std::string_view bytes);
bool looks_like_npy(std::string_view bytes);
bool looks_like_metropro(std::string_view bytes);
bool looks_like_nanoscope(std::string_view bytes);
bool looks_like_sensofar(std::string_view bytes);
bool looks_like_digital_surf(std::string_view bytes);
bool looks_like_wyko(std::string_view bytes);
bool looks_like_netcdf(std::string_view bytes);
bool looks_like_gwy(std::string_view bytes);
bool looks_like_alicona(std::string_view bytes);
bool looks_like_nanosurf(std::string_view bytes);
bool looks_like_agilent_mi(std::string_view bytes);

// ISO 25178-72 with float64 heights, grid increments from the surface's sizes, and MD5 checksums of the data
// and of main.xml: read_x3p returns the same doubles.
void write_x3p(const std::filesystem::path& path, const Surface& surface);
// NumPy .npy version 1.0, little-endian float64 in C order, shape (ny, nx): read_npy returns the same
// doubles.
void write_npy(const std::filesystem::path& path, const Surface& surface);
// Gwyddion .gwy: a GwyContainer with the GwyDataField "/0/data" (float64 heights in m, sizes in m): read_gwy
// returns the same doubles and sizes.
void write_gwy(const std::filesystem::path& path, const Surface& surface);

}  // namespace contactbench::formats

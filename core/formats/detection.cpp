#include "contactbench/core/formats/detection.hpp"

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/line_scan.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_readers.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

constexpr std::array<BinaryFormat, 13> binary_formats = {{
    {TopographyFormat::x3p, {".x3p", "", ""}, looks_like_zip, read_x3p},
    {TopographyFormat::sdf, {".sdf", "", ""}, looks_like_sdf, read_sdf},
    {TopographyFormat::npy, {".npy", "", ""}, looks_like_npy, read_npy},
    {TopographyFormat::metropro, {".dat", "", ""}, looks_like_metropro, read_metropro},
    {TopographyFormat::nanoscope, {".di", ".spm", ""}, looks_like_nanoscope, read_nanoscope},
    {TopographyFormat::digital_surf, {".sur", "", ""}, looks_like_digital_surf, read_digital_surf},
    {TopographyFormat::wyko, {".opd", "", ""}, looks_like_wyko, read_wyko},
    {TopographyFormat::netcdf, {".nc", "", ""}, looks_like_netcdf, read_netcdf},
    {TopographyFormat::gwy, {".gwy", "", ""}, looks_like_gwy, read_gwy},
    {TopographyFormat::alicona, {".al3d", "", ""}, looks_like_alicona, read_alicona},
    {TopographyFormat::nanosurf, {".nid", "", ""}, looks_like_nanosurf, read_nanosurf},
    {TopographyFormat::agilent_mi, {".mi", "", ""}, looks_like_agilent_mi, read_agilent_mi},
    // Last: .plu has no magic, only a self-consistent header.
    {TopographyFormat::sensofar, {".plu", "", ""}, looks_like_sensofar, read_sensofar},
}};

}  // namespace

std::string lower_extension(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return extension;
}

const BinaryFormat* binary_format_of(const fs::path& path, std::string_view bytes) {
  for (const BinaryFormat& candidate : binary_formats)
    if (candidate.detect(bytes)) return &candidate;
  const std::string extension = lower_extension(path);
  for (const BinaryFormat& candidate : binary_formats)
    for (const std::string_view known : candidate.extensions)
      if (!known.empty() && extension == known) return &candidate;
  return nullptr;
}

TopographyFormat text_format_of(const fs::path& path, std::span<const Line> lines) {
  if (lines.empty()) throw InputError(path, 0, "empty file: no data rows");
  const std::string_view first = lines.front().text;
  if (first.starts_with(project_prefix)) return TopographyFormat::project;
  if (first.starts_with("h=")) return TopographyFormat::interferometer;
  if (first.starts_with('#')) return TopographyFormat::gwyddion;
  if (looks_like_line_scan(lines)) return TopographyFormat::line_scan;
  if (looks_like_point_list(path, lines)) return TopographyFormat::xyz_points;
  return TopographyFormat::plain_matrix;
}

}  // namespace contactbench::formats

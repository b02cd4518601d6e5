// NetCDF (.nc) as ContactMechanics and Tamaas write a topography, docs/formats.md "netcdf": a variable
// "heights" with dimensions (x, y) (x the slow index in the file), optional variables "x" and "y" whose
// attributes give the lateral sizes ("length"), the unit ("unit") and periodicity ("periodic"); the heights'
// own "unit" attribute must agree with the lateral unit. Read with the NetCDF library, from memory.
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <netcdf.h>
#include <netcdf_mem.h>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

std::optional<Real> length_unit(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\xc2\xb5m" || unit == "\xce\xbcm") return 1e-6;
  if (unit == "nm") return 1e-9;
  if (unit == "pm") return 1e-12;
  return std::nullopt;
}

class NetcdfFile {
 public:
  NetcdfFile(const fs::path& path, std::string_view bytes) : path_(path), memory_(bytes) {
    const int status = nc_open_mem(path.string().c_str(), NC_NOWRITE, memory_.size(), memory_.data(), &id_);
    if (status != NC_NOERR)
      throw InputError(path, 0, std::string("not a readable NetCDF file: ") + nc_strerror(status));
  }
  ~NetcdfFile() { nc_close(id_); }
  NetcdfFile(const NetcdfFile&) = delete;
  NetcdfFile& operator=(const NetcdfFile&) = delete;

  int id() const { return id_; }
  std::optional<int> variable(const char* name) const {
    int variable_id = 0;
    if (nc_inq_varid(id_, name, &variable_id) != NC_NOERR) return std::nullopt;
    return variable_id;
  }
  std::optional<std::string> text_attribute(int variable, const char* name) const {
    nc_type type = 0;
    std::size_t length = 0;
    if (nc_inq_att(id_, variable, name, &type, &length) != NC_NOERR || type != NC_CHAR || length > 4096)
      return std::nullopt;
    std::string text(length, '\0');
    if (nc_get_att_text(id_, variable, name, text.data()) != NC_NOERR) return std::nullopt;
    while (!text.empty() && text.back() == '\0')
      text.pop_back();
    return text;
  }
  std::optional<Real> number_attribute(int variable, const char* name) const {
    nc_type type = 0;
    std::size_t length = 0;
    if (nc_inq_att(id_, variable, name, &type, &length) != NC_NOERR || length != 1 || type == NC_CHAR ||
        type == NC_STRING)
      return std::nullopt;
    double value = 0;
    if (nc_get_att_double(id_, variable, name, &value) != NC_NOERR) return std::nullopt;
    return value;
  }

 private:
  fs::path path_;
  std::string memory_;  // nc_open_mem wants writable memory it may keep until nc_close
  int id_ = -1;
};

}  // namespace

bool looks_like_netcdf(std::string_view bytes) {
  return bytes.starts_with("CDF\x01") || bytes.starts_with("CDF\x02") || bytes.starts_with("CDF\x05") ||
         bytes.starts_with("\x89HDF\r\n\x1a\n");
}

RawTopography read_netcdf(const fs::path& path, std::string_view bytes) {
  if (!looks_like_netcdf(bytes))
    throw InputError(path, 0, "wrong magic: a NetCDF file begins with 'CDF' or '\\x89HDF'");
  const NetcdfFile file(path, bytes);
  const std::optional<int> heights = file.variable("heights");
  if (!heights) throw InputError(path, 0, "the NetCDF file has no variable 'heights'");
  int dimensions = 0;
  if (nc_inq_varndims(file.id(), *heights, &dimensions) != NC_NOERR || dimensions != 2)
    throw InputError(
        path, 0, "NetCDF 'heights' has " + std::to_string(dimensions) + " dimensions; a topography needs 2");
  int dimension_ids[2] = {0, 0};
  std::size_t extents[2] = {0, 0};
  if (nc_inq_vardimid(file.id(), *heights, dimension_ids) != NC_NOERR ||
      nc_inq_dimlen(file.id(), dimension_ids[0], &extents[0]) != NC_NOERR ||
      nc_inq_dimlen(file.id(), dimension_ids[1], &extents[1]) != NC_NOERR)
    throw InputError(path, 0, "cannot read the dimensions of NetCDF 'heights'");
  const auto nx = static_cast<long long>(std::min<std::size_t>(extents[0], std::size_t{1} << 40));
  const auto ny = static_cast<long long>(std::min<std::size_t>(extents[1], std::size_t{1} << 40));
  const std::uint64_t size = grid_bytes(path, nx, ny, 8, "NetCDF 'heights'");
  if (size > static_cast<std::uint64_t>(bytes.size()) * 8 + 4096)
    throw InputError(path, 0, "NetCDF 'heights' promises more data than the file can hold");

  // Unit and sizes from the coordinate variables' attributes.
  Real unit = 1;
  std::optional<Real> lx, ly;
  bool periodic = false;
  const std::optional<int> x = file.variable("x");
  const std::optional<int> y = file.variable("y");
  std::optional<std::string> unit_name = x ? file.text_attribute(*x, "unit") : std::nullopt;
  if (!unit_name) unit_name = file.text_attribute(*heights, "unit");
  if (unit_name) {
    const std::optional<Real> factor = length_unit(*unit_name);
    if (!factor)
      throw InputError(path, 0, "NetCDF unit '" + *unit_name + "' is not a length unit (m, mm, um, nm, pm)");
    unit = *factor;
  }
  if (const std::optional<std::string> height_unit = file.text_attribute(*heights, "unit");
      height_unit && unit_name && *height_unit != *unit_name)
    throw InputError(path, 0, "NetCDF heights are in '" + *height_unit + "' but x in '" + *unit_name + "'");
  if (x && y) {
    const std::optional<Real> length_x = file.number_attribute(*x, "length");
    const std::optional<Real> length_y = file.number_attribute(*y, "length");
    if (length_x && length_y) {
      lx = *length_x * unit;
      ly = *length_y * unit;
    }
    if (const std::optional<Real> flag = file.number_attribute(*x, "periodic")) periodic = *flag != 0;
  }

  std::vector<double> stored(static_cast<std::size_t>(nx * ny));
  const int status = nc_get_var_double(file.id(), *heights, stored.data());
  if (status != NC_NOERR)
    throw InputError(path, 0, std::string("cannot read NetCDF 'heights': ") + nc_strerror(status));
  // Points never written hold the fill value (the variable's _FillValue, else the library's default).
  const double fill_value = file.number_attribute(*heights, "_FillValue").value_or(NC_FILL_DOUBLE);
  Channel channel = make_channel("heights", true, unit_name.value_or("m"), nx, ny);
  channel.lx = lx;
  channel.ly = ly;
  channel.values.resize(stored.size());
  for (long long ix = 0; ix < nx; ++ix)
    for (long long iy = 0; iy < ny; ++iy) {
      const double value = stored[static_cast<std::size_t>(ix * ny + iy)];
      channel.values[static_cast<std::size_t>(iy * nx + ix)] =
          std::isfinite(value) && value != fill_value ? value * unit : std::numeric_limits<Real>::quiet_NaN();
    }
  RawTopography topography;
  topography.periodic = periodic;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats

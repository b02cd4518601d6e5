// Reading a 4096^2 file of each binary format (docs/formats.md), against plain memory passes over the same
// bytes measured in the same run:
//   formats_read/<format>/memory_sum        sum of the file's bytes, already in memory, as 8-byte words
//   formats_read/<format>/file_to_memory    the file read into memory (std::ifstream into a string)
//   formats_read/<format>/read              read_topography_reading: detection, parse, channel, metres
//   formats_read/<format>/read_plane        the same and levelling by the least-squares plane
//   formats_read/<format>/read_rows_plane   the same with row alignment (mean per scan line) before the plane
// Each file is written from the format's description (docs/formats.md and its reader; the writers for x3p,
// npy and gwy) when its format's first benchmark runs, in a temporary folder, and removed before the next
// format's is made: one file on disk at a time (a 4096^2 float64 file is 128 MiB). The readers run on one
// thread (none is parallel), and so do both references. scripts/bench.sh formats_read records the medians.
#include <unistd.h>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "bench_surfaces.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::bench {
namespace {

namespace fs = std::filesystem;

constexpr Index kSide = 4096;
constexpr Real kLength = 1e-4;  // lateral size of every file [m]

// A smooth field plus seeded noise, about 1 um rms: the content does not change the cost of a read, but it
// must be finite everywhere (no invalid points, so that no fill is needed) and not flat.
Real height(Index x, Index y) {
  std::uint64_t state = static_cast<std::uint64_t>(y * kSide + x) * 0x9E3779B97F4A7C15ull + 7;
  state ^= state >> 31;
  state *= 0xBF58476D1CE4E5B9ull;
  state ^= state >> 29;
  const Real noise = static_cast<Real>(state >> 11) / static_cast<Real>(1ull << 53) - 0.5;
  return 1e-6 *
         (std::sin(0.003 * static_cast<Real>(x)) + std::cos(0.002 * static_cast<Real>(y)) + 0.2 * noise);
}

// Little- or big-endian bytes of a number, appended to `out` or written at `offset`.
template <typename T>
void put(std::string& out, T value, bool big = false) {
  auto raw = std::bit_cast<std::array<char, sizeof(T)>>(value);
  if (big == (std::endian::native == std::endian::little)) std::reverse(raw.begin(), raw.end());
  out.append(raw.data(), raw.size());
}
template <typename T>
void put_at(std::string& out, std::size_t offset, T value, bool big = false) {
  std::string bytes;
  put(bytes, value, big);
  if (out.size() < offset + bytes.size()) out.resize(offset + bytes.size(), '\0');
  out.replace(offset, bytes.size(), bytes);
}
void put_text_at(std::string& out, std::size_t offset, std::string_view text) {
  if (out.size() < offset + text.size()) out.resize(offset + text.size(), '\0');
  out.replace(offset, text.size(), text);
}

// How a format orders its values: rows (x fastest) from y = 0 up, rows from the top (largest y) down, or
// columns (y fastest) from x = 0, each from y = 0 up.
enum class Order { rows_up, rows_down, columns };

// Writes `header`, then the grid's values in `order` as `encode` appends them, one line at a time so that no
// second copy of the grid is held, then `trailer`.
void write_grid(const fs::path& path, const std::string& header,
                const std::function<void(std::string&, Real)>& encode, Order order = Order::rows_up,
                const std::string& trailer = {}) {
  std::ofstream out(path, std::ios::binary);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  std::string line;
  for (Index a = 0; a < kSide; ++a) {
    line.clear();
    for (Index b = 0; b < kSide; ++b)
      encode(line, order == Order::columns   ? height(a, b)
                   : order == Order::rows_up ? height(b, a)
                                             : height(b, kSide - 1 - a));
    out.write(line.data(), static_cast<std::streamsize>(line.size()));
  }
  out.write(trailer.data(), static_cast<std::streamsize>(trailer.size()));
  if (!out) throw Error("bench_formats_read: could not write " + path.string());
}

Surface generated_surface() {
  HeightMap heights(kSide, kSide);
  for (Index y = 0; y < kSide; ++y)
    for (Index x = 0; x < kSide; ++x)
      heights(y, x) = height(x, y);
  return Surface(Grid{kSide, kSide, kLength, kLength, false}, std::move(heights));
}

// --- One builder per format, each from its section of docs/formats.md. ---

void build_with_writer(const fs::path& path) {
  write_topography(path, generated_surface());
}

// ISO 25178-71 binary: the 81-byte packed header, float64 values (DataType 7), x fastest.
void build_sdf(const fs::path& path) {
  std::string header = "bISO-1.0";
  header.resize(42, '\0');
  put_at(header, 42, static_cast<std::uint16_t>(kSide));
  put_at(header, 44, static_cast<std::uint16_t>(kSide));
  put_at(header, 46, kLength / kSide);  // Xscale
  put_at(header, 54, kLength / kSide);  // Yscale
  put_at(header, 62, 1.0);              // Zscale: values in metres
  put_at(header, 70, 1e-12);            // Zresolution
  put_at(header, 78, std::int8_t{0});   // Compression
  put_at(header, 79, std::int8_t{7});   // DataType float64
  put_at(header, 80, std::int8_t{0});   // CheckType
  write_grid(path, header, [](std::string& out, Real h) { put(out, h); });
}

// MetroPro header format 1 (834 bytes, big-endian), no intensity block, int32 phase counts.
void build_metropro(const fs::path& path) {
  std::string header(834, '\0');
  put_text_at(header, 0, "\x88\x1b\x03\x6f");
  put_at(header, 6, std::uint32_t{834}, true);
  put_at(header, 68, static_cast<std::uint16_t>(kSide), true);
  put_at(header, 70, static_cast<std::uint16_t>(kSide), true);
  put_at(header, 164, 0.5f, true);                                 // interferometric scale factor S
  put_at(header, 168, 632.8e-9f, true);                            // wavelength [m]
  put_at(header, 176, 1.0f, true);                                 // obliquity factor O
  put_at(header, 184, static_cast<float>(kLength / kSide), true);  // lateral resolution [m]
  put_at(header, 218, std::int16_t{1}, true);                      // phase_res code: R = 32768
  const double per_count = 0.5 * 1.0 * static_cast<double>(632.8e-9f) / 32768;
  write_grid(path, header, [per_count](std::string& out, Real h) {
    put(out, static_cast<std::int32_t>(std::lround(h / per_count)), true);
  });
}

// Nanoscope: the text header (one height image, 4-byte counts) padded to the data offset.
void build_nanoscope(const fs::path& path) {
  constexpr std::size_t offset = 8192;
  const std::uint64_t length = static_cast<std::uint64_t>(kSide) * kSide * 4;
  std::string header =
      "\\*File list\r\n\\Version: 0x09300201\r\n\\*Scanner list\r\n\\@Sens. Zsens: V 2000 nm/V\r\n"
      "\\*Ciao image list\r\n\\Data offset: " +
      std::to_string(offset) + "\r\n\\Data length: " + std::to_string(length) +
      "\r\n\\Bytes/pixel: 4\r\n\\Samps/line: " + std::to_string(kSide) +
      "\r\n\\Number of lines: " + std::to_string(kSide) +
      "\r\n\\Scan Size: 100 100 ~m\r\n\\@2:Image Data: S [Height] \"Height\"\r\n"
      "\\@2:Z scale: V [Sens. Zsens] (0.000152588 V/LSB) 10 V\r\n\\*File list end\r\n\x1a";
  header.resize(offset, '\0');
  const double per_count = 10 / 65536.0 * 2000e-9 / 65536.0;  // 10 um over the int32 range
  write_grid(
      path, header,
      [per_count](std::string& out, Real h) {
        put(out, static_cast<std::int32_t>(std::lround(h / per_count)));
      },
      Order::rows_down);  // the first stored line is the top of the image
}

// Sensofar .plu: the 500-byte header (type 3, one layer), then the layer: ny, nx, float32 um, min, max.
void build_sensofar(const fs::path& path) {
  std::string header(500, '\0');
  put_at(header, 388, static_cast<std::uint32_t>(kSide));  // ny
  put_at(header, 392, static_cast<std::uint32_t>(kSide));  // nx
  put_at(header, 396, static_cast<std::uint32_t>(kSide * kSide));
  put_at(header, 404, static_cast<float>(kLength / kSide * 1e6));  // um per pixel in x
  put_at(header, 408, static_cast<float>(kLength / kSide * 1e6));
  put_at(header, 428, std::uint32_t{3});  // topography
  put_at(header, 489, std::uint8_t{1});   // one layer
  put(header, static_cast<std::uint32_t>(kSide));
  put(header, static_cast<std::uint32_t>(kSide));
  std::string trailer;
  put(trailer, -3.0f);
  put(trailer, 3.0f);
  write_grid(
      path, header, [](std::string& out, Real h) { put(out, static_cast<float>(h * 1e6)); }, Order::rows_up,
      trailer);
}

// Digital Surf .sur: the 512-byte header, int32 values in nm steps of the z scale.
void build_digital_surf(const fs::path& path) {
  std::string header(512, '\0');
  put_text_at(header, 0, "DIGITAL SURF");
  put_at(header, 14, std::uint16_t{1});  // one object
  put_at(header, 98, std::uint16_t{32});
  put_at(header, 100, std::int32_t{-4000000});
  put_at(header, 104, std::int32_t{4000000});
  put_at(header, 108, static_cast<std::int32_t>(kSide));
  put_at(header, 112, static_cast<std::int32_t>(kSide));
  put_at(header, 116, static_cast<std::uint32_t>(kSide * kSide));
  put_at(header, 120, static_cast<float>(kLength / kSide * 1e6));  // x spacing [um]
  put_at(header, 124, static_cast<float>(kLength / kSide * 1e6));
  put_at(header, 128, 0.001f);  // z scale [nm per count]
  put_text_at(header, 180, "um");
  put_text_at(header, 196, "um");
  put_text_at(header, 212, "nm");
  const double per_count = static_cast<double>(0.001f) * 1e-9;
  write_grid(path, header, [per_count](std::string& out, Real h) {
    put(out, static_cast<std::int32_t>(std::lround(h / per_count)));
  });
}

// Wyko .opd: two bytes, the directory (Directory, RAW DATA, Wavelength, Mult, Aspect, Pixel_size), the
// blocks in that order; the data block float32, column by column from the top down.
void build_wyko(const fs::path& path) {
  const auto entry = [](std::string& out, std::string_view name, std::int16_t type, std::int32_t length) {
    std::string field(name);
    field.resize(16, '\0');
    out += field;
    put(out, type);
    put(out, length);
    put(out, std::uint16_t{0});
  };
  const std::int32_t data_length = 6 + static_cast<std::int32_t>(kSide * kSide * 4);
  std::string header(2, '\0');
  entry(header, "Directory", 1, 6 * 24);
  entry(header, "Wavelength", 7, 4);
  entry(header, "Mult", 6, 2);
  entry(header, "Aspect", 7, 4);
  entry(header, "Pixel_size", 7, 4);
  entry(header, "RAW DATA", 3, data_length);
  const float wavelength_nm = 632.8f;
  put(header, wavelength_nm);
  put(header, std::uint16_t{1});
  put(header, 1.0f);
  put(header, static_cast<float>(kLength / kSide * 1e3));  // mm
  put(header, static_cast<std::uint16_t>(kSide));
  put(header, static_cast<std::uint16_t>(kSide));
  put(header, std::uint16_t{4});
  // Column x holds y from the top (ny - 1) down.
  std::ofstream out(path, std::ios::binary);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  std::string column;
  for (Index x = 0; x < kSide; ++x) {
    column.clear();
    for (Index stored = 0; stored < kSide; ++stored)
      put(column, static_cast<float>(height(x, kSide - 1 - stored) / (wavelength_nm * 1e-9)));
    out.write(column.data(), static_cast<std::streamsize>(column.size()));
  }
  if (!out) throw Error("bench_formats_read: could not write " + path.string());
}

// NetCDF classic with 64-bit offsets (CDF\2), big-endian: dimensions x, y; scalar variables x and y whose
// attributes give the lengths and the unit; `heights` (x, y) as doubles, x the slow index.
void build_netcdf(const fs::path& path) {
  const auto u32 = [](std::string& out, std::uint32_t v) { put(out, v, true); };
  const auto name = [&](std::string& out, std::string_view text) {
    u32(out, static_cast<std::uint32_t>(text.size()));
    out += text;
    out.resize((out.size() + 3) / 4 * 4, '\0');
  };
  const auto attributes = [&](std::string& out, double length) {
    u32(out, 0x0C);
    u32(out, 2);
    name(out, "length");
    u32(out, 6);  // double
    u32(out, 1);
    put(out, length, true);
    name(out, "unit");
    u32(out, 2);  // char
    name(out, "m");
  };
  const auto build = [&](std::uint64_t data_begin) {
    std::string h = "CDF\x02";
    u32(h, 0);  // records
    u32(h, 0x0A);
    u32(h, 2);
    name(h, "x");
    u32(h, static_cast<std::uint32_t>(kSide));
    name(h, "y");
    u32(h, static_cast<std::uint32_t>(kSide));
    u32(h, 0);  // no global attributes
    u32(h, 0);
    u32(h, 0x0B);
    u32(h, 3);
    for (const char* axis : {"x", "y"}) {  // scalars: their values are not read
      name(h, axis);
      u32(h, 0);
      attributes(h, kLength);
      u32(h, 6);
      u32(h, 8);
      put(h, data_begin + static_cast<std::uint64_t>(kSide * kSide * 8) + (axis[0] == 'y' ? 8 : 0), true);
    }
    name(h, "heights");
    u32(h, 2);
    u32(h, 0);
    u32(h, 1);
    u32(h, 0);  // no attributes
    u32(h, 0);
    u32(h, 6);
    u32(h, static_cast<std::uint32_t>(kSide * kSide * 8));  // vsize
    put(h, data_begin, true);
    return h;
  };
  std::string header = build(0);
  header = build(header.size());
  std::string trailer(16, '\0');
  write_grid(
      path, header, [](std::string& out, Real h) { put(out, h, true); }, Order::columns, trailer);
}

// Alicona .al3d: the magic, 52-byte tags, the float32 depth image (4096 columns: rows need no padding).
void build_alicona(const fs::path& path) {
  constexpr std::size_t offset = 1024;
  const std::pair<std::string, std::string> tags[] = {{"Version", "1"},
                                                      {"TagCount", "6"},
                                                      {"Cols", std::to_string(kSide)},
                                                      {"Rows", std::to_string(kSide)},
                                                      {"PixelSizeXMeter", "2.44140625e-08"},
                                                      {"PixelSizeYMeter", "2.44140625e-08"},
                                                      {"DepthImageOffset", std::to_string(offset)},
                                                      {"InvalidPixelValue", "-1"}};
  std::string header("AliconaImaging\0\r\n", 17);
  for (const auto& [key, value] : tags) {
    std::string k = key, v = value;
    k.resize(20, '\0');
    v.resize(30, '\0');
    header += k + v + "\r\n";
  }
  header.resize(offset, '\0');
  write_grid(path, header, [](std::string& out, Real h) { put(out, static_cast<float>(h)); });
}

// Nanosurf .nid: the INI header of one data set (32-bit signed, Intel order), "#!", the counts.
void build_nanosurf(const fs::path& path) {
  const std::string side = std::to_string(kSide);
  const std::string header =
      "[DataSet]\r\nVersion=2\r\nGroupCount=1\r\nGr0-Name=Scan "
      "forward\r\nGr0-Count=1\r\nGr0-Ch0=DataSet-0:0\r\n"
      "\r\n[DataSet-0:0]\r\nFrame=Scan forward\r\nPoints=" +
      side + "\r\nLines=" + side +
      "\r\nSaveBits=32\r\nSaveSign=Signed\r\nSaveOrder=Intel\r\nDim0Name=X*\r\nDim0Range=1e-4\r\nDim0Unit="
      "m\r\n"
      "Dim1Name=Y*\r\nDim1Range=1e-4\r\nDim1Unit=m\r\nDim2Name=Z-Axis\r\nDim2Range=1e-5\r\nDim2Unit=m\r\n#!";
  write_grid(path, header, [](std::string& out, Real h) {
    put(out, static_cast<std::int32_t>(std::lround(h / 1e-5 * 4294967296.0)));
  });
}

// Agilent .mi: the 14-character-key header of one Topography buffer, "data BINARY_32", the counts.
void build_agilent_mi(const fs::path& path) {
  const auto line = [](std::string key, const std::string& value) {
    key.resize(14, ' ');
    return key + value + "\n";
  };
  const std::string header =
      line("fileType", "Image") + line("xPixels", std::to_string(kSide)) +
      line("yPixels", std::to_string(kSide)) + line("xLength", "1e-4") + line("yLength", "1e-4") +
      line("scanUp", "FALSE") + line("bufferLabel", "Topography") + line("direction", "Trace") +
      line("bufferRange", "1e-5") + line("bufferUnit", "m") + line("data", "BINARY_32");
  write_grid(path, header, [](std::string& out, Real h) {
    put(out, static_cast<std::int32_t>(std::lround(h / 1e-5 * 2147483648.0)));
  });
}

struct Format {
  const char* name;
  const char* extension;
  void (*build)(const fs::path&);
};

const Format kFormats[] = {
    {"x3p", ".x3p", build_with_writer},
    {"sdf", ".sdf", build_sdf},
    {"npy", ".npy", build_with_writer},
    {"metropro", ".dat", build_metropro},
    {"nanoscope", ".spm", build_nanoscope},
    {"sensofar", ".plu", build_sensofar},
    {"digital_surf", ".sur", build_digital_surf},
    {"wyko", ".opd", build_wyko},
    {"netcdf", ".nc", build_netcdf},
    {"gwy", ".gwy", build_with_writer},
    {"alicona", ".al3d", build_alicona},
    {"nanosurf", ".nid", build_nanosurf},
    {"agilent_mi", ".mi", build_agilent_mi},
};

// The one file on disk: made when a format's first benchmark runs, removed when another format's is made
// and at exit.
class CurrentFile {
 public:
  ~CurrentFile() { remove(); }
  const fs::path& of(const Format& format) {
    if (name_ != format.name) {
      remove();
      folder_ = fs::temp_directory_path() / ("contactbench_formats_read_" + std::to_string(::getpid()));
      fs::create_directories(folder_);
      path_ = folder_ / (std::string("surface") + format.extension);
      name_ = format.name;
      try {
        format.build(path_);
        check(format);
      } catch (...) {
        remove();  // an exception out of a benchmark ends the process without unwinding: no file is left
        throw;
      }
    }
    return path_;
  }
  // The file's bytes, read once per format for the memory pass.
  const std::string& bytes() {
    if (bytes_.empty()) bytes_ = slurp(path_);
    return bytes_;
  }
  static std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string out(static_cast<std::size_t>(fs::file_size(path)), '\0');
    in.read(out.data(), static_cast<std::streamsize>(out.size()));
    return out;
  }

 private:
  // A file the reader would not recognise, or read into another grid, would time the wrong work.
  void check(const Format& format) {
    const TopographyFormat detected = detect_topography_format(path_);
    if (to_string(detected) != format.name)
      throw Error("bench_formats_read: the " + std::string(format.name) + " file was detected as " +
                  std::string(to_string(detected)));
    TopographyReadOptions options;
    if (!format_carries_sizes(detected)) options.lx = kLength;
    const Surface surface = read_topography(path_, options);
    const Real expected = height(123, 456), got = surface.heights()(456, 123);
    if (surface.grid().nx != kSide || surface.grid().ny != kSide || std::abs(got - expected) > 1e-3 * 1e-6)
      throw Error("bench_formats_read: the " + std::string(format.name) + " file reads back wrong (height " +
                  std::to_string(got) + " m where " + std::to_string(expected) + " m was written)");
  }
  void remove() {
    bytes_.clear();
    bytes_.shrink_to_fit();
    if (!folder_.empty()) fs::remove_all(folder_);
    name_.clear();
  }
  std::string name_;
  fs::path folder_, path_;
  std::string bytes_;
};

CurrentFile& current_file() {
  static CurrentFile file;
  return file;
}

void report_bytes(benchmark::State& state, const fs::path& path) {
  const auto size = static_cast<std::int64_t>(fs::file_size(path));
  state.SetBytesProcessed(state.iterations() * size);
  state.counters["file_bytes"] = static_cast<double>(size);
}

void memory_sum(benchmark::State& state, const Format* format) {
  const fs::path& path = current_file().of(*format);
  const std::string& bytes = current_file().bytes();
  for (auto _ : state) {
    std::uint64_t sum = 0;
    const std::size_t words = bytes.size() / 8;
    for (std::size_t k = 0; k < words; ++k) {
      std::uint64_t word;
      std::memcpy(&word, bytes.data() + 8 * k, 8);
      sum += word;
    }
    benchmark::DoNotOptimize(sum);
  }
  report_bytes(state, path);
}

void file_to_memory(benchmark::State& state, const Format* format) {
  const fs::path& path = current_file().of(*format);
  for (auto _ : state) {
    std::string bytes = CurrentFile::slurp(path);
    benchmark::DoNotOptimize(bytes.data());
  }
  report_bytes(state, path);
}

void read_surface(benchmark::State& state, const Format* format, Levelling level, RowAlignment rows) {
  const fs::path& path = current_file().of(*format);
  TopographyReadOptions options;
  if (std::string_view(format->name) == "npy") options.lx = kLength;  // the one format without sizes
  options.level = level;
  options.align_rows = rows;
  for (auto _ : state) {
    TopographyReading reading = read_topography_reading(path, options);
    benchmark::DoNotOptimize(reading.surface.heights().data());
  }
  report_bytes(state, path);
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  using namespace contactbench;
  using namespace contactbench::bench;
  for (const Format& format : kFormats) {
    const std::string prefix = std::string("formats_read/") + format.name + "/";
    register_timed(prefix + "memory_sum", memory_sum, &format);
    register_timed(prefix + "file_to_memory", file_to_memory, &format);
    register_timed(prefix + "read", read_surface, &format, Levelling::none, RowAlignment::none);
    register_timed(prefix + "read_plane", read_surface, &format, Levelling::plane, RowAlignment::none);
    register_timed(prefix + "read_rows_plane", read_surface, &format, Levelling::plane, RowAlignment::mean);
  }
  const int status = run_benchmarks(argc, argv, {{"side", std::to_string(kSide)}});
  return status;
}

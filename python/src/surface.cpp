// Surfaces: from numpy, from a file, from the paper's generator; refinement; spectral moments
// (core/surface.hpp, core/topography_io.hpp, core/generation.hpp, core/spectrum.hpp).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "bindings.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/surface_repair.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::python {

namespace {

Surface surface_from_array(const py::handle& heights, Real lx, std::optional<Real> ly, bool periodic) {
  HeightMap map = height_map_from_array(heights, "heights");
  // Square pixels unless ly is given, as for a plain matrix file (core/topography_io.hpp).
  const Real y_size = ly.value_or(lx * static_cast<Real>(map.rows()) / static_cast<Real>(map.cols()));
  const Grid grid{.nx = map.cols(), .ny = map.rows(), .lx = lx, .ly = y_size, .periodic = periodic};
  return Surface(grid, std::move(map));  // throws Error for a bad size or a NaN/Inf height
}

// The CLI's `contactbench generate` exactly: coefficients of the realisation on `grid`, synthesised on the
// grid itself or, with refine, on a finer one (the same realisation, never a new one).
Surface generate(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed, std::optional<Index> refine,
                 std::optional<Index> refine_y, int threads) {
  checked_threads(threads);
  const SpectrumMap hhat = generate_coefficients(grid, psd, seed);
  const Index nx = refine.value_or(grid.nx);
  const Index ny = refine_y.value_or(refine.value_or(grid.ny));
  py::gil_scoped_release unlocked;
  return synthesize(grid, hhat, nx, ny, threads);
}

// A channel as the readers take it (core/topography_io.hpp): a name, or a 0-based index written as text;
// Python callers may pass the index as an int.
// A named choice checked against the names core declares for it (the same the command line and scenes
// accept).
template <typename Choice>
Choice parsed_choice(const char* key, const std::string& text,
                     std::optional<Choice> (*parse)(std::string_view),
                     const std::vector<std::string_view>& names) {
  if (const std::optional<Choice> choice = parse(text)) return *choice;
  std::string accepted;
  for (std::size_t k = 0; k < names.size(); ++k)
    accepted += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + ("\"" + std::string(names[k]) + "\"");
  throw Error(std::string(key) + ": accepted values are " + accepted + ", got \"" + text + "\"");
}

std::string channel_text(const std::variant<std::int64_t, std::string>& channel) {
  if (const auto* name = std::get_if<std::string>(&channel)) return *name;
  const std::int64_t index = std::get<std::int64_t>(channel);
  if (index < 0)
    throw Error("channel: accepted values are a name or a 0-based index >= 0, got " + std::to_string(index));
  return std::to_string(index);
}

}  // namespace

void register_surface(py::module_& m) {
  py::class_<Grid>(m, "Grid",
                   "The sampling lattice: nx x ny points over lx x ly [m], periodic or not (core/grid.hpp).")
      .def(py::init([](Index nx, Index ny, Real lx, Real ly, bool periodic) {
             const Grid grid{.nx = nx, .ny = ny, .lx = lx, .ly = ly, .periodic = periodic};
             validate(grid, "Grid");
             return grid;
           }),
           py::kw_only(), py::arg("nx"), py::arg("ny"), py::arg("lx"), py::arg("ly"),
           py::arg("periodic") = true, "Grid(*, nx, ny, lx [m], ly [m], periodic=True)")
      .def_readonly("nx", &Grid::nx, "points along x (columns)")
      .def_readonly("ny", &Grid::ny, "points along y (rows)")
      .def_readonly("lx", &Grid::lx, "lateral size along x [m]")
      .def_readonly("ly", &Grid::ly, "lateral size along y [m]")
      .def_readonly("periodic", &Grid::periodic, "does the surface repeat with periods lx, ly?")
      .def_property_readonly("dx", &Grid::dx, "spacing along x [m]")
      .def_property_readonly("dy", &Grid::dy, "spacing along y [m]")
      .def_property_readonly("nominal_area", &Grid::nominal_area, "A0 = lx ly [m^2]")
      .def_property_readonly("nyquist", &Grid::nyquist, "pi / max(dx, dy) [1/m]")
      .def("__repr__", [](const Grid& g) {
        return "Grid(nx=" + std::to_string(g.nx) + ", ny=" + std::to_string(g.ny) +
               ", lx=" + std::string(py::repr(py::float_(g.lx))) +
               ", ly=" + std::string(py::repr(py::float_(g.ly))) +
               ", periodic=" + (g.periodic ? "True" : "False") + ")";
      });

  py::class_<SpectralMoments>(
      m, "SpectralMoments",
      "Profile (Nayak) moments along x and y, mean excluded (docs/theory.md section 1): "
      "m0 [m^2], m2x, m2y [-], m4x, m4y [1/m^2].")
      .def_readonly("m0", &SpectralMoments::m0, "[m^2]")
      .def_readonly("m2x", &SpectralMoments::m2x, "[-]")
      .def_readonly("m4x", &SpectralMoments::m4x, "[1/m^2]")
      .def_readonly("m2y", &SpectralMoments::m2y, "[-]")
      .def_readonly("m4y", &SpectralMoments::m4y, "[1/m^2]")
      .def_property_readonly("rms_height", &SpectralMoments::rms_height, "sqrt(m0) [m]")
      .def_property_readonly("rms_gradient", &SpectralMoments::rms_gradient,
                             "areal gbar = sqrt(m2x + m2y) [-]")
      .def_property_readonly("alpha_x", &SpectralMoments::alpha_x, "Nayak's bandwidth m0 m4x / m2x^2 [-]")
      .def_property_readonly("alpha_y", &SpectralMoments::alpha_y, "Nayak's bandwidth m0 m4y / m2y^2 [-]")
      .def("__repr__", [](const SpectralMoments& s) {
        return "SpectralMoments(m0=" + std::string(py::repr(py::float_(s.m0))) +
               ", m2x=" + std::string(py::repr(py::float_(s.m2x))) +
               ", m2y=" + std::string(py::repr(py::float_(s.m2y))) +
               ", m4x=" + std::string(py::repr(py::float_(s.m4x))) +
               ", m4y=" + std::string(py::repr(py::float_(s.m4y))) + ")";
      });

  py::class_<Surface>(
      m, "Surface",
      "A rough surface: heights [m] on a grid (docs/theory.md section 0). Immutable.\n\n"
      "Surface(heights, *, lx, ly=None, periodic=False): heights is a 2-D, C-contiguous "
      "float64 numpy array, rows along y (heights[iy, ix] at x = ix dx, y = iy dy), copied once; "
      "lx, ly the lateral sizes [m] (ly defaults to lx ny/nx: square pixels). Other dtypes, "
      "dimensions, strided views and NaN/Inf heights raise contactbench.Error.")
      .def(py::init(&surface_from_array), py::arg("heights"), py::kw_only(), py::arg("lx"),
           py::arg("ly") = py::none(), py::arg("periodic") = false)
      .def_property_readonly(
          "heights",
          [](const py::object& self) { return view_of(self.cast<const Surface&>().heights(), self); },
          "heights [m] as a read-only (ny, nx) float64 view of the surface's own storage (no copy)")
      .def_property_readonly("grid", &Surface::grid, "the Grid (sizes [m], points, periodicity)")
      .def_property_readonly("nx", &Surface::nx, "points along x (columns)")
      .def_property_readonly("ny", &Surface::ny, "points along y (rows)")
      .def_property_readonly(
          "lx", [](const Surface& s) { return s.grid().lx; }, "lateral size along x [m]")
      .def_property_readonly(
          "ly", [](const Surface& s) { return s.grid().ly; }, "lateral size along y [m]")
      .def_property_readonly(
          "periodic", [](const Surface& s) { return s.grid().periodic; },
          "does the surface repeat with periods lx, ly?")
      .def_property_readonly("mean_height", &Surface::mean_height, "mean height [m]")
      .def_property_readonly("rms_height", &Surface::rms_height, "Sq: rms height about the mean [m]")
      .def_property_readonly(
          "rms_gradient", [](const Surface& s) { return spectral_moments(s, 1).rms_gradient(); },
          "areal rms gradient gbar = sqrt(m2x + m2y) [-] of the spectral moments (Hann window when not "
          "periodic), the gbar of kappa and of the theories; the same as moments().rms_gradient")
      .def("centred", &Surface::centred, "the same heights with the mean removed")
      .def("with_periodic", &Surface::with_periodic, py::arg("periodic"),
           "the same heights, declared periodic or not")
      .def(
          "moments",
          [](const Surface& s, int threads) {
            checked_threads(threads);
            py::gil_scoped_release unlocked;
            return spectral_moments(s, threads);
          },
          py::kw_only(), py::arg("threads") = 1,
          "spectral_moments(self): profile moments, Hann window when not periodic (docs/theory.md section 1)")
      .def(
          "write", [](const Surface& s, const std::filesystem::path& path) { write_surface(path, s); },
          py::arg("path"),
          "writes the project's lossless text format (read back bit for bit by read_topography)")
      .def("__repr__", [](const Surface& s) {
        return "Surface(" + std::to_string(s.nx()) + " x " + std::to_string(s.ny()) + " points, " +
               std::string(py::repr(py::float_(s.grid().lx))) + " x " +
               std::string(py::repr(py::float_(s.grid().ly))) + " m, " +
               (s.grid().periodic ? "periodic" : "not periodic") + ")";
      });

  m.def(
      "read_topography",
      [](const std::filesystem::path& path, std::optional<Real> lx, std::optional<Real> ly,
         std::optional<bool> periodic, std::optional<std::variant<std::int64_t, std::string>> channel,
         const std::string& fill, const std::string& level, std::optional<std::string> unit,
         std::optional<std::string> crop, const std::string& align_rows) {
        TopographyReadOptions options;
        options.lx = lx;
        options.ly = ly;
        options.periodic = periodic;
        if (channel) options.channel = channel_text(*channel);
        options.fill = parsed_choice("fill", fill, parse_fill_method, fill_method_names());
        options.level = parsed_choice("level", level, parse_levelling, levelling_names());
        options.align_rows =
            parsed_choice("align_rows", align_rows, parse_row_alignment, row_alignment_names());
        options.unit = unit;  // checked by the reader, which names the file
        if (crop) {
          options.crop = parse_crop(*crop);
          if (!options.crop)
            throw Error("crop: accepted values are " + std::string(kCropAccepted) + ", got \"" + *crop +
                        "\"");
        }
        return read_topography(path, options);
      },
      py::arg("path"), py::kw_only(), py::arg("lx") = py::none(), py::arg("ly") = py::none(),
      py::arg("periodic") = py::none(), py::arg("channel") = py::none(), py::arg("fill") = "none",
      py::arg("level") = "none", py::arg("unit") = py::none(), py::arg("crop") = py::none(),
      py::arg("align_rows") = "none",
      "Reads a topography file in any format the project reads (docs/formats.md: x3p, sdf, npy, MetroPro, "
      "Nanoscope, Sensofar, Digital Surf, Wyko, NetCDF, the project's, interferometer and Gwyddion text "
      "exports, "
      "plain matrices in metres), detected from its content. lx, ly [m] are required for a plain matrix or "
      "an "
      "npy array and must agree with a file that states its sizes. periodic defaults to False for measured "
      "data and to the stored flag for the project's format. channel: a name (str) or a 0-based index (int "
      "or its text; default: the first height channel). fill: \"none\" (refuse invalid points), \"harmonic\" "
      "or "
      "\"mean\". level: \"none\", \"mean\", \"plane\" or \"quadratic\". unit: the length unit of a file that "
      "states none "
      "(\"m\", \"mm\", \"um\", \"nm\", \"pm\"; default metres). crop: \"measured\", \"px:X0,Y0,NX,NY\" or "
      "\"m:X0,Y0,LX,LY\". align_rows: \"none\", \"mean\", \"median\" or \"linear\" (per scan line). The "
      "order is "
      "crop, fill, align_rows, level (docs/formats.md). Heights come back in metres (no mean removed "
      "unless levelled). A bad file raises contactbench.InputError naming the file and line.");
  m.def(
      "spectral_moments",
      [](const Surface& s, int threads) { return spectral_moments(s, checked_threads(threads)); },
      py::arg("surface"), py::kw_only(), py::arg("threads") = 1,
      "Profile moments m0 [m^2], m2x, m2y [-], m4x, m4y [1/m^2] (docs/theory.md section 1).");
  m.def(
      "radial_psd",
      [](const Surface& s, int bins_per_decade) {
        const SampledPsd psd = radial_psd(fourier_coefficients(s), bins_per_decade);
        return py::make_tuple(py::array_t<double>(psd.q.size(), psd.q.data()),
                              py::array_t<double>(psd.c.size(), psd.c.data()));
      },
      py::arg("surface"), py::kw_only(), py::arg("bins_per_decade") = 10,
      "Radially averaged 2D PSD (Persson's convention): a tuple (q [1/m], C(q) [m^4]) of new arrays.");

  py::class_<SelfAffinePsd>(
      m, "SelfAffinePsd",
      "The generator's PSD (docs/theory.md section 2): C0 below qr, C0 (q/qr)^(-2(1+H)) up "
      "to qs, 0 above; normalised to the rms height sigma on the lattice.")
      .def(py::init([](Real sigma, Real hurst, Real qr, std::optional<Real> qs, Real anisotropy) {
             return SelfAffinePsd{
                 .sigma = sigma, .hurst = hurst, .qr = qr, .qs = qs, .anisotropy = anisotropy};
           }),
           py::kw_only(), py::arg("sigma"), py::arg("hurst"), py::arg("qr"), py::arg("qs") = py::none(),
           py::arg("anisotropy") = 1.0,
           "SelfAffinePsd(*, sigma [m], hurst in (0, 1], qr [1/m], qs [1/m] = the grid's Nyquist, anisotropy "
           "= "
           "m2x/m2y = 1)")
      .def_readwrite("sigma", &SelfAffinePsd::sigma, "rms height [m]")
      .def_readwrite("hurst", &SelfAffinePsd::hurst, "Hurst exponent H in (0, 1]")
      .def_readwrite("qr", &SelfAffinePsd::qr, "roll-off wavevector [1/m]")
      .def_readwrite("qs", &SelfAffinePsd::qs, "cut-off wavevector [1/m]; None: the grid's Nyquist")
      .def_readwrite("anisotropy", &SelfAffinePsd::anisotropy, "requested m2x/m2y");

  m.def("generate_surface", &generate, py::arg("grid"), py::arg("psd"), py::arg("seed") = 1, py::kw_only(),
        py::arg("refine") = py::none(), py::arg("refine_y") = py::none(), py::arg("threads") = 1,
        "A periodic random self-affine surface on `grid` (docs/theory.md section 2), bit-identical to "
        "`contactbench generate` with the same parameters and seed (any thread count). refine, refine_y: "
        "resample the same realisation on refine x refine_y points (Fourier interpolation), like --refine.");
  m.def(
      "refine",
      [](const Surface& s, Index nx, std::optional<Index> ny, int threads) {
        checked_threads(threads);
        py::gil_scoped_release unlocked;
        return refine(s, nx, ny.value_or(nx), threads);
      },
      py::arg("surface"), py::arg("nx"), py::arg("ny") = py::none(), py::kw_only(), py::arg("threads") = 1,
      "The same periodic surface resampled on nx x ny (default nx) points by Fourier interpolation: moments "
      "and the heights at the original nodes unchanged. Refuses a non-periodic surface.");

  py::module_ paper = m.def_submodule("paper", "The paper's inputs (docs/theory.md section 2, Table 1).");
  paper.def("grid", &paper::grid, "L = 200 um, 256 x 256, periodic");
  paper.def("surface_a", &paper::surface_a,
            "surface A's PSD: sigma = 0.5 um, H = 0.5, qr = 3.14e4 1/m, qs = Nyquist");
  paper.def("surface_b", &paper::surface_b, "surface B's PSD with qs at Nyquist (reproduces Table 2)");
  paper.def("surface_b_printed_qs", &paper::surface_b_printed_qs,
            "surface B's PSD with Table 1's qs = 3.00e6 1/m");
  m.def(
      "surface_a",
      [](std::uint64_t seed, int threads) {
        return generate(paper::grid(), paper::surface_a(), seed, {}, {}, threads);
      },
      py::arg("seed") = 1, py::kw_only(), py::arg("threads") = 1,
      "The paper's surface A on the paper's grid: generate_surface(paper.grid(), paper.surface_a(), seed).");
  m.def(
      "surface_b",
      [](std::uint64_t seed, int threads) {
        return generate(paper::grid(), paper::surface_b(), seed, {}, {}, threads);
      },
      py::arg("seed") = 1, py::kw_only(), py::arg("threads") = 1,
      "The paper's surface B on the paper's grid: generate_surface(paper.grid(), paper.surface_b(), seed).");
}

}  // namespace contactbench::python

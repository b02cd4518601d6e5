#include "contactbench/app/surface_source.hpp"

#include <cmath>
#include <limits>
#include <system_error>

#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSizeAccepted = "size = L or size = [lx, ly], finite numbers > 0 [m]";

std::optional<GeneratedSurfaceSpec> parse_generated(const Section& g, Problems& problems) {
  const std::size_t before = problems.count();
  g.reject_unknown({"sigma", "hurst", "qr", "qs", "size", "grid", "seed", "refine", "anisotropy"});
  GeneratedSurfaceSpec spec;
  const auto sigma = g.number("sigma", true, positive("[m]"));
  const auto hurst = g.number("hurst", true, {[](Real v) { return v > 0 && v <= 1; }, "a number in (0, 1]"});
  const auto qr = g.number("qr", true, positive("[1/m]"));
  const auto size = g.number("size", true, positive("[m]"));
  const auto grid = g.integer("grid", true, int_range(2, kMaxPointsASide));
  const auto seed = g.integer("seed", true, int_range(0, std::numeric_limits<std::int64_t>::max()));
  const auto anisotropy = g.number("anisotropy", false, positive("(m2x/m2y)"));
  const auto refine = g.integer("refine", false, int_range(grid.value_or(2), kMaxPointsASide));
  std::optional<Real> qs;
  if (g.has("qs")) {
    // qs <= qr would leave no self-affine range (docs/theory.md section 2); the upper limit is the grid's.
    const Rule<Real> rule = qr ? Rule<Real>{[q = *qr](Real v) { return std::isfinite(v) && v > q; },
                                            "a finite number > qr = " + exact_number(*qr) + " [1/m]"}
                               : positive("[1/m]");
    qs = g.number("qs", false, rule);
  }
  if (problems.count() != before) return std::nullopt;
  spec.sigma = *sigma;
  spec.hurst = *hurst;
  spec.qr = *qr;
  spec.size = *size;
  spec.grid = static_cast<Index>(*grid);
  spec.seed = static_cast<std::uint64_t>(*seed);
  spec.anisotropy = anisotropy.value_or(1.0);
  spec.refine = static_cast<Index>(refine.value_or(0));
  const Grid lattice{spec.grid, spec.grid, spec.size, spec.size, true};
  spec.qs = qs.value_or(lattice.nyquist());  // the default, filled in so that reports show it
  SelfAffinePsd psd{spec.sigma, spec.hurst, spec.qr, spec.qs, spec.anisotropy};
  library_check(problems, before, g.line(), g.path(), [&] { validate(psd, lattice); });
  if (problems.count() != before) return std::nullopt;
  return spec;
}

std::optional<FileSurfaceSpec> parse_file(const Section& s, const fs::path& folder, Problems& problems) {
  const std::size_t before = problems.count();
  FileSurfaceSpec spec;
  const auto file = s.string("file", true, "a path to a topography file, relative to the scene's folder");
  if (const toml::node* node = s.find("size")) {
    if (const auto value = Section::as_real(*node)) {
      if (positive("").ok(*value))
        spec.size_x = *value;
      else
        s.problem("size", "out of range: got " + exact_number(*value), kSizeAccepted);
    } else if (const auto* array = node->as_array()) {
      bool good = array->size() == 2;
      std::vector<Real> sizes;
      for (const auto& element : *array) {
        const auto value = Section::as_real(element);
        good = good && value && positive("").ok(*value);
        if (value) sizes.push_back(*value);
      }
      if (good) {
        spec.size_x = sizes[0];
        spec.size_y = sizes[1];
      } else {
        s.problem("size", "expected two finite numbers > 0", kSizeAccepted);
      }
    } else {
      s.wrong_type("size", "a number or an array of two numbers", kSizeAccepted);
    }
  }
  spec.periodic = s.boolean("periodic");
  // channel = "Height" or channel = 1; fill and level as docs/formats.md describes.
  if (const toml::node* node = s.find("channel")) {
    if (const auto* name = node->as_string()) {
      spec.channel = name->get();
    } else if (const auto* index = node->as_integer(); index && index->get() >= 0) {
      spec.channel = std::to_string(index->get());
    } else {
      s.wrong_type("channel", "a channel name or an index >= 0", "a string or an integer >= 0");
    }
  }
  if (const auto fill = s.choice("fill", fill_method_names())) spec.fill = *parse_fill_method(*fill);
  if (const auto level = s.choice("level", levelling_names())) spec.level = *parse_levelling(*level);
  if (const auto align = s.choice("align_rows", row_alignment_names()))
    spec.align_rows = *parse_row_alignment(*align);
  if (s.has("crop")) {
    if (const auto text = s.string("crop", false, kCropAccepted)) {
      // "none", as a resolved scene writes it back: the whole grid.
      spec.crop = parse_crop(*text);
      if (!spec.crop && *text != "none")
        s.problem("crop", "not a region: \"" + *text + "\"", std::string(kCropAccepted) + ", or none");
    }
  }
  if (const auto unit = s.choice("unit", {"m", "mm", "um", "nm", "pm"})) spec.unit = *unit;
  if (file) {
    spec.path = fs::absolute(folder / *file).lexically_normal();
    std::error_code ec;
    if (file->empty() || !fs::exists(spec.path, ec)) {
      s.problem("file", "no such file: " + spec.path.string(), "an existing topography file");
    } else if (!fs::is_regular_file(spec.path, ec)) {
      s.problem("file", "not a regular file: " + spec.path.string(), "an existing topography file");
    } else {
      try {
        const TopographyFormat format = detect_topography_format(spec.path);
        if (!format_carries_sizes(format) && !s.has("size"))
          s.missing("size", std::string(kSizeAccepted) + " (required: " + spec.path.filename().string() +
                                " is a " +
                                (format == TopographyFormat::npy ? "NumPy array" : "plain matrix") +
                                ", which carries no lateral size)");
        if (spec.unit && format_carries_unit(format))
          s.problem("unit",
                    spec.path.filename().string() + " is a " + std::string(to_string(format)) +
                        " file, which states its own unit",
                    "no unit key (it is only for files that state none: npy, plain or CSV matrices, x y z "
                    "point lists)");
      } catch (const Error& error) {
        s.problem("file", error.what(), "a topography file contactbench reads");
      }
    }
  }
  if (problems.count() != before) return std::nullopt;
  return spec;
}

}  // namespace

std::optional<SurfaceSpec> read_surface_keys(const Section& root, const fs::path& folder) {
  Problems& problems = root.problems();
  const toml::table* table = root.subtable("surface", true, "a table [surface] with generate or file");
  if (!table) return std::nullopt;
  const Section s(*table, "surface", problems);
  s.reject_unknown(
      {"generate", "file", "size", "periodic", "channel", "fill", "level", "unit", "crop", "align_rows"});
  const bool generated = s.has("generate"), from_file = s.has("file");
  if (generated && from_file) {
    s.problem("file", "generate and file are mutually exclusive", "generate = { ... } or file = \"...\"");
    return std::nullopt;
  }
  if (!generated && !from_file) {
    problems.add(s.line(), "surface", "missing generate or file (one is required)",
                 "generate = { ... } or file = \"...\"");
    return std::nullopt;
  }
  if (generated) {
    for (std::string_view key :
         {"size", "periodic", "channel", "fill", "level", "unit", "crop", "align_rows"})
      if (s.has(key))
        s.problem(
            key,
            "only applies to file = \"...\" (a generated surface is periodic, its size is generate.size)",
            "generate = { ... } alone");
    const toml::table* g = s.subtable("generate", true, "generate = { sigma, hurst, qr, size, grid, seed }");
    if (!g) return std::nullopt;
    auto spec = parse_generated(Section(*g, "surface.generate", problems), problems);
    if (!spec) return std::nullopt;
    return SurfaceSpec{*spec};
  }
  auto spec = parse_file(s, folder, problems);
  if (!spec) return std::nullopt;
  return SurfaceSpec{*spec};
}

std::optional<Index> points_a_side(const SurfaceSpec& surface) {
  if (const auto* g = std::get_if<GeneratedSurfaceSpec>(&surface.source))
    return g->refine > 0 ? g->refine : g->grid;
  return std::nullopt;
}

void write_surface_keys(const SurfaceSpec& surface, SceneKeys& root) {
  SceneKeys& table = root.table("surface");
  if (const auto* g = std::get_if<GeneratedSurfaceSpec>(&surface.source)) {
    if (g->seed > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
      throw Error("surface.generate.seed = " + std::to_string(g->seed) +
                  " does not fit a TOML integer (< 2^63)");
    SceneKeys& generate = table.table("generate");
    generate.put("sigma", g->sigma);
    generate.put("hurst", g->hurst);
    generate.put("qr", g->qr);
    if (g->qs) generate.put("qs", *g->qs);
    generate.put("size", g->size);
    generate.put("grid", std::int64_t{g->grid});
    generate.put("seed", static_cast<std::int64_t>(g->seed));
    if (g->refine > 0) generate.put("refine", std::int64_t{g->refine});
    generate.put("anisotropy", g->anisotropy);
  } else {
    const auto& f = std::get<FileSurfaceSpec>(surface.source);
    table.put("file", f.path.string());
    if (f.size_x && f.size_y)
      table.put("size", std::vector<Real>{*f.size_x, *f.size_y});
    else if (f.size_x)
      table.put("size", *f.size_x);
    if (f.periodic) table.put("periodic", *f.periodic);
    if (f.channel) table.put("channel", *f.channel);
    // Always written, defaults included, so that a report records how the measured heights were treated.
    table.put("fill", std::string(to_string(f.fill)));
    table.put("level", std::string(to_string(f.level)));
    if (f.unit) table.put("unit", *f.unit);
    table.put("crop", f.crop ? to_string(*f.crop) : std::string("none"));
    table.put("align_rows", std::string(to_string(f.align_rows)));
  }
}

TopographyReadOptions read_options(const FileSurfaceSpec& file, int threads) {
  TopographyReadOptions options;
  options.lx = file.size_x;
  options.ly = file.size_y;
  options.periodic = file.periodic;
  options.channel = file.channel;
  options.fill = file.fill;
  options.level = file.level;
  options.unit = file.unit;
  options.crop = file.crop;
  options.align_rows = file.align_rows;
  options.threads = threads;
  return options;
}

Surface make_surface(const SurfaceSpec& spec, int threads) {
  if (const auto* g = std::get_if<GeneratedSurfaceSpec>(&spec.source)) {
    const Grid grid{.nx = g->grid, .ny = g->grid, .lx = g->size, .ly = g->size, .periodic = true};
    const SelfAffinePsd psd{
        .sigma = g->sigma, .hurst = g->hurst, .qr = g->qr, .qs = g->qs, .anisotropy = g->anisotropy};
    validate(psd, grid);
    // The generator sets the q = 0 coefficient to zero: its surfaces are centred already (to round-off).
    if (g->refine > 0)
      return synthesize(grid, generate_coefficients(grid, psd, g->seed), g->refine, g->refine, threads)
          .centred();
    return generate_surface(grid, psd, g->seed, threads).centred();
  }
  const auto& file = std::get<FileSurfaceSpec>(spec.source);
  const TopographyReadOptions options = read_options(file, threads);
  // Levelling "plane" removes the tilt as well; the mean is removed in any case.
  Surface surface = read_topography(file.path, options).centred();
  // The moments stage and every method would refuse heights beyond what sums hold; that is the file's fault,
  // so the refusal names it.
  try {
    check_summable_heights(surface);
  } catch (const InputError&) {
    throw;
  } catch (const Error& error) {
    throw InputError(file.path, 0, error.what());
  }
  return surface;
}

}  // namespace contactbench

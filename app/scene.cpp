#include "contactbench/app/scene.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <system_error>
#include <type_traits>

#include <toml++/toml.h>

#include "contactbench/core/generation.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/material.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

namespace fs = std::filesystem;

// Points a side of any grid a scene may ask for: 65536^2 doubles are already 32 GiB.
constexpr Index kMaxPointsASide = 65536;
constexpr std::string_view kAnisotropyAccepted =
    "\"refuse\" (the default: an anisotropic surface is an error) or \"average\" (its equivalent isotropic "
    "surface)";
constexpr std::string_view kLevelsAccepted = "\"exact\", \"paper\" or an integer count >= 1";
constexpr std::string_view kSizeAccepted = "size = L or size = [lx, ly], finite numbers > 0 [m]";

// Shortest decimal that reads back to the same double (messages must not round a value into the range).
std::string str(Real value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items)
    text.append(text.empty() ? "" : ", ").append(item);
  return text;
}

std::string method_names() {
  std::vector<std::string> names;
  for (auto name : kMethodNames)
    names.emplace_back(name);
  return join(names);
}

std::optional<MethodKind> method_kind(std::string_view name) {
  for (std::size_t i = 0; i < std::size(kMethodNames); ++i)
    if (kMethodNames[i] == name) return static_cast<MethodKind>(i);
  return std::nullopt;
}

// Names become folder names (results/<name>/) and labels become column and file names: keep them portable.
bool portable_name(std::string_view name, bool allow_dot) {
  if (name.empty() || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [allow_dot](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || (allow_dot && c == '.');
  });
}

std::string_view type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

long line_of(const toml::node& node) {
  return static_cast<long>(node.source().begin.line);
}

// Every problem found, each already formatted as "<origin>[:line]: <key path>: <reason>[; accepted: ...]".
class Problems {
 public:
  explicit Problems(std::string origin) : origin_(std::move(origin)) {}

  void add(long line, std::string_view path, std::string_view reason, std::string_view accepted = {}) {
    std::string text = origin_;
    if (line > 0) text.append(":").append(std::to_string(line));
    text.append(": ").append(path).append(": ").append(reason);
    if (!accepted.empty()) text.append("; accepted: ").append(accepted);
    lines_.push_back(std::move(text));
  }
  // A problem whose location is not a key (a TOML syntax error, at "<origin>:line:column").
  void add_syntax_error(long line, long column, std::string_view reason) {
    lines_.push_back(origin_ + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": TOML syntax error: " + std::string(reason));
  }
  std::size_t count() const { return lines_.size(); }

  void throw_if_any() const {
    if (lines_.empty()) return;
    std::string message = "invalid scene " + origin_ + " (" + std::to_string(lines_.size()) +
                          (lines_.size() == 1 ? " problem):" : " problems):");
    for (const auto& line : lines_)
      message.append("\n").append(line);
    throw SceneError(message, lines_);
  }

 private:
  std::string origin_;
  std::vector<std::string> lines_;
};

// An accepted range: the test and its description for messages.
template <typename T>
struct Rule {
  std::function<bool(T)> ok;
  std::string accepted;
};

Rule<Real> positive(std::string_view unit) {
  return {[](Real v) { return std::isfinite(v) && v > 0; }, "a finite number > 0 " + std::string(unit)};
}
Rule<Real> open_interval(Real low, Real high, std::string_view text) {
  return {[low, high](Real v) { return v > low && v < high; }, std::string(text)};
}
Rule<std::int64_t> int_range(std::int64_t low, std::int64_t high) {
  return {[low, high](std::int64_t v) { return v >= low && v <= high; },
          "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]"};
}

// One table of the file and its key path; reads typed values and reports what is wrong with them.
class Section {
 public:
  Section(const toml::table& table, std::string path, Problems& problems, bool root = false)
      : table_(table), path_(std::move(path)), problems_(problems), root_(root) {}

  const toml::table& table() const { return table_; }
  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }
  bool has(std::string_view key) const { return table_.contains(key); }
  const toml::node* find(std::string_view key) const { return table_.get(key); }
  // The table's own line (0 for the whole file, whose "line" would point at its first key).
  long line() const { return root_ ? 0 : line_of(table_); }

  // A problem with `key`: at the key's line when present, else at the table's.
  void problem(std::string_view key, std::string_view reason, std::string_view accepted = {}) const {
    const toml::node* node = find(key);
    problems_.add(node ? line_of(*node) : line(), key_path(key), reason, accepted);
  }
  void missing(std::string_view key, std::string_view accepted) const {
    problem(key, "missing required key", accepted);
  }
  void wrong_type(std::string_view key, std::string_view expected, std::string_view accepted) const {
    problem(key,
            "wrong type: expected " + std::string(expected) + ", got " + std::string(type_name(*find(key))),
            accepted);
  }

  // Reports every key not in `accepted`, listing those accepted here.
  void reject_unknown(std::initializer_list<std::string_view> accepted) const {
    std::vector<std::string> names(accepted.begin(), accepted.end());
    for (auto&& [key, node] : table_)
      if (std::find(accepted.begin(), accepted.end(), key.str()) == accepted.end())
        problems_.add(line_of(node), key_path(key.str()), "unknown key", join(names));
  }

  // A number (integers are accepted where a float is expected).
  std::optional<Real> number(std::string_view key, bool required, const Rule<Real>& rule) const {
    const toml::node* node = find(key);
    if (!node) {
      if (required) missing(key, rule.accepted);
      return std::nullopt;
    }
    const auto value = as_real(*node);
    if (!value) {
      wrong_type(key, "a number", rule.accepted);
      return std::nullopt;
    }
    if (!rule.ok(*value)) {
      problem(key, "out of range: got " + str(*value), rule.accepted);
      return std::nullopt;
    }
    return value;
  }

  std::optional<std::int64_t> integer(std::string_view key, bool required,
                                      const Rule<std::int64_t>& rule) const {
    const toml::node* node = find(key);
    if (!node) {
      if (required) missing(key, rule.accepted);
      return std::nullopt;
    }
    const auto* value = node->as_integer();
    if (!value) {
      wrong_type(key, "an integer", rule.accepted);
      return std::nullopt;
    }
    if (!rule.ok(value->get())) {
      problem(key, "out of range: got " + std::to_string(value->get()), rule.accepted);
      return std::nullopt;
    }
    return value->get();
  }

  std::optional<std::string> string(std::string_view key, bool required, std::string_view accepted) const {
    const toml::node* node = find(key);
    if (!node) {
      if (required) missing(key, accepted);
      return std::nullopt;
    }
    const auto* value = node->as_string();
    if (!value) {
      wrong_type(key, "a string", accepted);
      return std::nullopt;
    }
    return value->get();
  }

  std::optional<bool> boolean(std::string_view key) const {
    const toml::node* node = find(key);
    if (!node) return std::nullopt;
    const auto* value = node->as_boolean();
    if (!value) {
      wrong_type(key, "a boolean", "true, false");
      return std::nullopt;
    }
    return value->get();
  }

  // A sub-table ([path.key] or key = { ... }).
  const toml::table* subtable(std::string_view key, bool required, std::string_view accepted) const {
    const toml::node* node = find(key);
    if (!node) {
      if (required) missing(key, accepted);
      return nullptr;
    }
    const auto* value = node->as_table();
    if (!value) wrong_type(key, "a table", accepted);
    return value;
  }

  static std::optional<Real> as_real(const toml::node& node) {
    if (const auto* value = node.as_floating_point()) return value->get();
    if (const auto* value = node.as_integer()) return static_cast<Real>(value->get());
    return std::nullopt;
  }

 private:
  const toml::table& table_;
  std::string path_;
  Problems& problems_;
  bool root_;
};

// Validates a group of keys and, when all of them are valid, runs the stricter check of a core function
// that throws Error: its message becomes one problem at `path`.
template <typename Check>
void core_check(Problems& problems, std::size_t count_before, long line, std::string_view path, Check check) {
  if (problems.count() != count_before) return;  // its message would repeat one already given
  try {
    check();
  } catch (const Error& error) {
    problems.add(line, path, error.what());
  }
}

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
                                            "a finite number > qr = " + str(*qr) + " [1/m]"}
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
  core_check(problems, before, g.line(), g.path(), [&] { validate(psd, lattice); });
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
        s.problem("size", "out of range: got " + str(*value), kSizeAccepted);
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
  spec.periodic = s.boolean("periodic").value_or(false);
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
        if (format == TopographyFormat::plain_matrix && !s.has("size"))
          s.missing("size", std::string(kSizeAccepted) + " (required: " + spec.path.filename().string() +
                                " is a plain matrix, which carries no lateral size)");
      } catch (const Error& error) {
        s.problem("file", error.what(), "a topography file contactbench reads");
      }
    }
  }
  if (problems.count() != before) return std::nullopt;
  return spec;
}

std::optional<SurfaceSpec> parse_surface(const Section& root, const fs::path& folder, Problems& problems) {
  const toml::table* table = root.subtable("surface", true, "a table [surface] with generate or file");
  if (!table) return std::nullopt;
  const Section s(*table, "surface", problems);
  s.reject_unknown({"generate", "file", "size", "periodic"});
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
    for (std::string_view key : {"size", "periodic"})
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

std::optional<MaterialSpec> parse_material(const Section& root, Problems& problems) {
  constexpr std::string_view forms = "E with nu (optionally E2 with nu2), or estar alone";
  const toml::table* table = root.subtable("material", true, forms);
  if (!table) return std::nullopt;
  const std::size_t before = problems.count();
  const Section m(*table, "material", problems);
  m.reject_unknown({"E", "nu", "estar", "E2", "nu2"});
  const auto poisson = open_interval(-1, 0.5, "a number in (-1, 0.5)");
  const auto e1 = m.number("E", false, positive("[Pa]"));
  const auto nu1 = m.number("nu", false, poisson);
  const auto estar = m.number("estar", false, positive("[Pa]"));
  const auto e2 = m.number("E2", false, positive("[Pa]"));
  const auto nu2 = m.number("nu2", false, poisson);
  const bool has_e = m.has("E"), has_nu = m.has("nu"), has_estar = m.has("estar");
  const bool has_e2 = m.has("E2"), has_nu2 = m.has("nu2");
  if (has_e && has_estar) m.problem("estar", "E and estar both given", forms);
  if (!has_e && !has_estar) m.missing("E", forms);
  if (has_e && !has_nu) m.missing("nu", "a number in (-1, 0.5), required with E");
  if (has_nu && !has_e) m.problem("nu", "given without E", forms);
  if (has_e2 && !has_nu2) m.missing("nu2", "a number in (-1, 0.5), required with E2");
  if (has_nu2 && !has_e2) m.problem("nu2", "given without E2", forms);
  if ((has_e2 || has_nu2) && !has_e)
    m.problem(has_e2 ? "E2" : "nu2", "a second body needs E and nu of the first (not estar)", forms);
  if (problems.count() != before) return std::nullopt;
  MaterialSpec spec;
  if (estar) {
    spec.estar = *estar;
  } else {
    spec.youngs_modulus = e1;
    spec.poisson_ratio = nu1;
    spec.youngs_modulus_2 = e2;
    spec.poisson_ratio_2 = nu2;
    spec.estar = e2 ? composite_modulus(*e1, *nu1, *e2, *nu2) : contact_modulus(*e1, *nu1);
  }
  return spec;
}

std::optional<std::vector<Real>> parse_loads(const Section& root, Problems& problems) {
  constexpr std::string_view forms = "values = [ ... ] or range = { from, to, count, spacing }";
  const toml::table* table = root.subtable("loads", true, forms);
  if (!table) return std::nullopt;
  const std::size_t before = problems.count();
  const Section l(*table, "loads", problems);
  l.reject_unknown({"values", "range"});
  const auto load = positive("(P/(E* A0))");
  std::vector<Real> loads;
  if (l.has("values") && l.has("range")) l.problem("range", "values and range both given", forms);
  if (!l.has("values") && !l.has("range")) l.missing("values", forms);
  if (const toml::node* node = l.find("values")) {
    if (const auto* array = node->as_array()) {
      if (array->empty()) l.problem("values", "empty array", "at least one " + load.accepted);
      for (std::size_t i = 0; i < array->size(); ++i) {
        const toml::node& element = *array->get(i);
        const std::string path = "loads.values[" + std::to_string(i) + "]";
        const auto value = Section::as_real(element);
        if (!value)
          problems.add(line_of(element), path,
                       "wrong type: expected a number, got " + std::string(type_name(element)),
                       load.accepted);
        else if (!load.ok(*value))
          problems.add(line_of(element), path, "out of range: got " + str(*value), load.accepted);
        else
          loads.push_back(*value);
      }
    } else {
      l.wrong_type("values", "an array of numbers", forms);
    }
  }
  if (l.has("range") && !l.has("values")) {
    if (const toml::table* range_table = l.subtable("range", true, forms)) {
      const Section r(*range_table, "loads.range", problems);
      r.reject_unknown({"from", "to", "count", "spacing"});
      const auto from = r.number("from", true, load);
      const auto to = r.number("to", true, load);
      const auto count = r.integer("count", true, int_range(1, 1000000));
      const auto spacing = r.string("spacing", false, "\"log\", \"linear\"");
      if (spacing && *spacing != "log" && *spacing != "linear")
        r.problem("spacing", "unknown spacing \"" + *spacing + "\"", "\"log\", \"linear\"");
      if (from && to && !(*from < *to))
        r.problem("to", "must exceed from = " + str(*from) + ": got " + str(*to), "a number > from");
      if (problems.count() == before) {
        const bool linear = spacing && *spacing == "linear";
        for (std::int64_t i = 0; i < *count; ++i) {
          const Real t = *count == 1 ? 0.0 : static_cast<Real>(i) / static_cast<Real>(*count - 1);
          loads.push_back(linear ? *from + t * (*to - *from) : *from * std::pow(*to / *from, t));
        }
        if (*count > 1) loads.back() = *to;  // the end point exactly, without the round-off of pow
      }
    }
  }
  if (problems.count() != before) return std::nullopt;
  std::sort(loads.begin(), loads.end());
  loads.erase(std::unique(loads.begin(), loads.end()), loads.end());
  return loads;
}

std::optional<int> parse_connectivity(const Section& s) {
  const auto value =
      s.integer("connectivity", false, {[](std::int64_t v) { return v == 4 || v == 8; }, "4, 8"});
  return value ? std::optional<int>(static_cast<int>(*value)) : std::nullopt;
}

// Points a side of the surface as the scene defines it, when known without reading a file.
std::optional<Index> surface_points(const std::optional<SurfaceSpec>& surface) {
  if (!surface) return std::nullopt;
  if (const auto* g = std::get_if<GeneratedSurfaceSpec>(&surface->source))
    return g->refine > 0 ? g->refine : g->grid;
  return std::nullopt;
}

BemMethodSpec parse_bem(const Section& s, std::optional<Index> points) {
  s.reject_unknown(
      {"method", "refine", "tolerance", "max_iterations", "periodic", "hardness", "connectivity", "solver"});
  BemMethodSpec spec;
  const std::int64_t low = points.value_or(2);
  const auto refine =
      s.integer("refine", false,
                {[low](std::int64_t v) { return v == 0 || (v >= low && v <= kMaxPointsASide); },
                 "0 (the surface as is) or an integer in [" + std::to_string(low) + ", " +
                     std::to_string(kMaxPointsASide) + "]" +
                     (points ? " (the surface has " + std::to_string(*points) + " points a side)" : "")});
  spec.refine = static_cast<Index>(refine.value_or(spec.refine));
  spec.tolerance =
      s.number("tolerance", false, open_interval(0, 1, "a number in (0, 1)")).value_or(spec.tolerance);
  spec.max_iterations = static_cast<Index>(
      s.integer("max_iterations", false, int_range(1, std::numeric_limits<std::int32_t>::max()))
          .value_or(spec.max_iterations));
  spec.periodic = s.boolean("periodic");
  spec.hardness = s.number("hardness", false, positive("[Pa]"));
  spec.connectivity = parse_connectivity(s).value_or(spec.connectivity);
  std::string known;
  for (const std::string& name : solver_names())
    known += (known.empty() ? "\"" : ", \"") + name + "\"";
  if (const auto name = s.string("solver", false, "one of " + known)) {
    const auto& names = solver_names();
    if (std::find(names.begin(), names.end(), *name) != names.end())
      spec.solver = solver_kind(*name);
    else
      s.problem("solver", "unknown BEM solver \"" + *name + "\"", "one of " + known);
  }
  return spec;
}

PlateauMethodSpec parse_plateau(const Section& s) {
  s.reject_unknown({"method", "connectivity", "levels", "periodic"});
  PlateauMethodSpec spec;
  spec.connectivity = parse_connectivity(s).value_or(spec.connectivity);
  spec.periodic = s.boolean("periodic");
  if (const toml::node* node = s.find("levels")) {
    if (const auto* text = node->as_string()) {
      if (text->get() == "exact")
        spec.levels = SweepLevels::exact();
      else if (text->get() == "paper")
        spec.levels = SweepLevels::paper();
      else
        s.problem("levels", "unknown levels \"" + text->get() + "\"", kLevelsAccepted);
    } else if (const auto* count = node->as_integer()) {
      if (count->get() >= 1)
        spec.levels = SweepLevels::uniform(static_cast<Index>(count->get()));
      else
        s.problem("levels", "out of range: got " + std::to_string(count->get()), kLevelsAccepted);
    } else {
      s.wrong_type("levels", "a string or an integer", kLevelsAccepted);
    }
  }
  return spec;
}

TheoryMethodSpec parse_theory(const Section& s) {
  s.reject_unknown({"method", "anisotropy"});
  TheoryMethodSpec spec;
  const auto anisotropy = s.string("anisotropy", false, kAnisotropyAccepted);
  if (anisotropy && *anisotropy != "refuse" && *anisotropy != "average")
    s.problem("anisotropy", "unknown choice \"" + *anisotropy + "\"", kAnisotropyAccepted);
  spec.average_anisotropy = anisotropy && *anisotropy == "average";
  return spec;
}

// The methods in the order the file lists them (toml++ keeps a table's keys sorted, not in file order).
std::vector<MethodSpec> parse_methods(const Section& root, const std::optional<SurfaceSpec>& surface,
                                      std::vector<std::string>& labels, Problems& problems) {
  const std::string accepted = "tables [methods.<label>] with method = one of " + method_names();
  const toml::table* table = root.subtable("methods", true, accepted);
  if (!table) return {};
  const Section methods(*table, "methods", problems);
  if (table->empty())
    problems.add(methods.line(), "methods", "no methods: at least one is required", accepted);
  std::vector<std::pair<const toml::key*, const toml::node*>> entries;
  for (auto&& [key, node] : *table)
    entries.emplace_back(&key, &node);
  std::stable_sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) {
    const auto &pa = a.first->source().begin, &pb = b.first->source().begin;
    return std::pair(pa.line, pa.column) < std::pair(pb.line, pb.column);
  });
  std::vector<MethodSpec> result;
  for (const auto& [key, node] : entries) {
    const std::string label(key->str());
    labels.push_back(label);
    if (!portable_name(label, false))
      methods.problem(label, "invalid label", "letters, digits, '_' and '-' (the label names outputs)");
    const auto* method_table = node->as_table();
    if (!method_table) {
      methods.wrong_type(label, "a table", accepted);
      continue;
    }
    const Section s(*method_table, "methods." + label, problems);
    std::optional<MethodKind> kind = method_kind(label);
    if (const auto name = s.string("method", false, method_names())) {
      const auto named = method_kind(*name);
      if (!named)
        s.problem("method", "unknown method \"" + *name + "\"", method_names());
      else if (kind && *kind != *named)
        s.problem("method", "the label names the method " + label + ", not " + *name,
                  "method = \"" + label + "\", or another label");
      kind = named;
    } else if (!s.has("method") && !kind) {
      s.missing("method", method_names() + " (required when the label is not a method name)");
    }
    if (!kind) continue;
    MethodSpec spec{label, *kind, TheoryMethodSpec{}};
    if (*kind == MethodKind::bem)
      spec.options = parse_bem(s, surface_points(surface));
    else if (*kind == MethodKind::plateau)
      spec.options = parse_plateau(s);
    else
      spec.options = parse_theory(s);
    result.push_back(std::move(spec));
  }
  return result;
}

std::string origin_name(const fs::path& origin) {
  return origin.empty() ? "<scene>" : origin.string();
}

// ---- writing ----
// The scene is written from a small ordered tree (a toml::table would sort the keys, and the methods'
// order matters), rendered either as TOML or as JSON, numbers in their shortest exact decimal form.

struct Value;
using Entries = std::vector<std::pair<std::string, Value>>;
struct Table {
  Entries entries;
  bool inline_table = false;  // TOML: key = { ... } rather than a [section]
};
struct Value {
  std::variant<Real, std::int64_t, bool, std::string, std::vector<Real>, Table> v;
};

void put(Table& table, std::string key, Value value) {
  table.entries.emplace_back(std::move(key), std::move(value));
}

// Both TOML basic strings and JSON strings take these escapes.
std::string escaped(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out.append(buffer);
    } else {
      out.push_back(c);
    }
  }
  return out + "\"";
}

// A TOML key: bare when it can be, else a quoted string.
std::string toml_key(const std::string& key) {
  return portable_name(key, false) ? key : escaped(key);
}

std::string toml_number(Real value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::string text = str(value);
  // TOML reads "31400" as an integer: a float needs a point or an exponent.
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::string json_number(Real value) {
  return std::isfinite(value) ? str(value) : "null";
}

std::string render_toml_value(const Value& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Real>) {
          return toml_number(v);
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          return std::to_string(v);
        } else if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          return escaped(v);
        } else if constexpr (std::is_same_v<T, std::vector<Real>>) {
          std::string out = "[";
          for (std::size_t i = 0; i < v.size(); ++i)
            out.append(i ? ", " : "").append(toml_number(v[i]));
          return out + "]";
        } else {
          std::string out = "{ ";
          for (std::size_t i = 0; i < v.entries.size(); ++i)
            out.append(i ? ", " : "")
                .append(toml_key(v.entries[i].first))
                .append(" = ")
                .append(render_toml_value(v.entries[i].second));
          return out + " }";
        }
      },
      value.v);
}

// Plain keys first, then each sub-table that is not inline as its own [section].
void render_toml_table(std::string& out, const Table& table, const std::string& path) {
  for (const auto& [key, value] : table.entries) {
    const auto* sub = std::get_if<Table>(&value.v);
    if (!sub || sub->inline_table)
      out.append(toml_key(key)).append(" = ").append(render_toml_value(value)) += '\n';
  }
  for (const auto& [key, value] : table.entries) {
    const auto* sub = std::get_if<Table>(&value.v);
    if (!sub || sub->inline_table) continue;
    const std::string sub_path = path.empty() ? toml_key(key) : path + "." + toml_key(key);
    const bool has_keys = std::any_of(sub->entries.begin(), sub->entries.end(), [](const auto& entry) {
      const auto* t = std::get_if<Table>(&entry.second.v);
      return !t || t->inline_table;
    });
    // A table holding only tables ([methods]) needs no header of its own.
    if (has_keys || sub->entries.empty()) out.append("\n[").append(sub_path).append("]\n");
    render_toml_table(out, *sub, sub_path);
  }
}

void render_json(std::string& out, const Value& value, int level) {
  const std::string indent(2 * static_cast<std::size_t>(level + 1), ' ');
  const std::string close_indent(2 * static_cast<std::size_t>(level), ' ');
  std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Real>) {
          out += json_number(v);
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          out += std::to_string(v);
        } else if constexpr (std::is_same_v<T, bool>) {
          out += v ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::string>) {
          out += escaped(v);
        } else if constexpr (std::is_same_v<T, std::vector<Real>>) {
          out += "[";
          for (std::size_t i = 0; i < v.size(); ++i)
            out.append(i ? ", " : "").append(json_number(v[i]));
          out += "]";
        } else {
          if (v.entries.empty()) {
            out += "{}";
            return;
          }
          out += "{\n";
          for (std::size_t i = 0; i < v.entries.size(); ++i) {
            out.append(indent).append(escaped(v.entries[i].first)).append(": ");
            render_json(out, v.entries[i].second, level + 1);
            out.append(i + 1 < v.entries.size() ? ",\n" : "\n");
          }
          out.append(close_indent).append("}");
        }
      },
      value.v);
}

std::int64_t toml_integer(std::uint64_t value, std::string_view what) {
  if (value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
    throw Error(std::string(what) + " = " + std::to_string(value) + " does not fit a TOML integer (< 2^63)");
  return static_cast<std::int64_t>(value);
}

std::int64_t integer(Index value) {
  return static_cast<std::int64_t>(value);
}

Table surface_table(const SurfaceSpec& surface) {
  Table table;
  if (const auto* g = std::get_if<GeneratedSurfaceSpec>(&surface.source)) {
    Table generate{{}, true};
    put(generate, "sigma", {g->sigma});
    put(generate, "hurst", {g->hurst});
    put(generate, "qr", {g->qr});
    if (g->qs) put(generate, "qs", {*g->qs});
    put(generate, "size", {g->size});
    put(generate, "grid", {integer(g->grid)});
    put(generate, "seed", {toml_integer(g->seed, "surface.generate.seed")});
    if (g->refine > 0) put(generate, "refine", {integer(g->refine)});
    put(generate, "anisotropy", {g->anisotropy});
    put(table, "generate", {std::move(generate)});
  } else {
    const auto& f = std::get<FileSurfaceSpec>(surface.source);
    put(table, "file", {f.path.string()});
    if (f.size_x && f.size_y)
      put(table, "size", {std::vector<Real>{*f.size_x, *f.size_y}});
    else if (f.size_x)
      put(table, "size", {*f.size_x});
    put(table, "periodic", {f.periodic});
  }
  return table;
}

Table material_table(const MaterialSpec& material, bool with_estar) {
  Table table;
  if (material.youngs_modulus) {
    put(table, "E", {*material.youngs_modulus});
    if (material.poisson_ratio) put(table, "nu", {*material.poisson_ratio});
    if (material.youngs_modulus_2) put(table, "E2", {*material.youngs_modulus_2});
    if (material.poisson_ratio_2) put(table, "nu2", {*material.poisson_ratio_2});
    if (with_estar) put(table, "estar", {material.estar});
  } else {
    put(table, "estar", {material.estar});
  }
  return table;
}

Table method_table(const MethodSpec& method) {
  Table table;
  put(table, "method", {std::string(to_string(method.kind))});
  if (const auto* bem = std::get_if<BemMethodSpec>(&method.options)) {
    put(table, "refine", {integer(bem->refine)});
    put(table, "tolerance", {bem->tolerance});
    put(table, "max_iterations", {integer(bem->max_iterations)});
    if (bem->periodic) put(table, "periodic", {*bem->periodic});
    if (bem->hardness) put(table, "hardness", {*bem->hardness});
    put(table, "connectivity", {std::int64_t{bem->connectivity}});
    put(table, "solver", {std::string(solver_name(bem->solver))});
  } else if (const auto* plateau = std::get_if<PlateauMethodSpec>(&method.options)) {
    put(table, "connectivity", {std::int64_t{plateau->connectivity}});
    switch (plateau->levels.kind) {
      case SweepLevels::Kind::exact:
        put(table, "levels", {std::string("exact")});
        break;
      case SweepLevels::Kind::paper:
        if (plateau->levels.count != SweepLevels::paper().count)
          throw Error("methods." + method.label + ".levels: paper levels with a count other than " +
                      std::to_string(SweepLevels::paper().count) + " have no scene form");
        put(table, "levels", {std::string("paper")});
        break;
      case SweepLevels::Kind::uniform:
        put(table, "levels", {integer(plateau->levels.count)});
        break;
    }
    if (plateau->periodic) put(table, "periodic", {*plateau->periodic});
  } else if (const auto* theory = std::get_if<TheoryMethodSpec>(&method.options)) {
    put(table, "anisotropy", {std::string(theory->average_anisotropy ? "average" : "refuse")});
  }
  return table;
}

Table scene_table(const Scene& scene, bool with_estar) {
  Table table;
  put(table, "name", {scene.name});
  put(table, "description", {scene.description});
  put(table, "reference", {scene.reference});
  put(table, "surface", {surface_table(scene.surface)});
  put(table, "material", {material_table(scene.material, with_estar)});
  Table loads;
  put(loads, "values", {scene.loads});
  put(table, "loads", {std::move(loads)});
  Table methods;
  for (const auto& method : scene.methods)
    put(methods, method.label, {method_table(method)});
  put(table, "methods", {std::move(methods)});
  return table;
}

}  // namespace

std::string_view to_string(MethodKind kind) {
  const auto index = static_cast<std::size_t>(kind);
  return index < std::size(kMethodNames) ? kMethodNames[index] : std::string_view("unknown");
}

const MethodSpec& Scene::method(std::string_view label) const {
  for (const auto& m : methods)
    if (m.label == label) return m;
  std::vector<std::string> labels;
  for (const auto& m : methods)
    labels.push_back(m.label);
  throw Error("scene " + name + " has no method labelled \"" + std::string(label) +
              "\"; labels: " + join(labels));
}

Scene parse_scene(std::string_view toml_text, const std::filesystem::path& origin) {
  const std::string origin_text = origin_name(origin);
  Problems problems(origin_text);
  toml::table document;
  try {
    document = toml::parse(toml_text, origin.string());
  } catch (const toml::parse_error& error) {
    const auto& at = error.source().begin;
    problems.add_syntax_error(static_cast<long>(at.line), static_cast<long>(at.column), error.description());
    problems.throw_if_any();
  }
  const Section root(document, "", problems, true);
  root.reject_unknown({"name", "description", "reference", "surface", "material", "loads", "methods"});

  Scene scene;
  const auto name =
      root.string("name", true, "letters, digits, '_', '-' and '.' (it names the output folder)");
  if (name && !portable_name(*name, true))
    root.problem("name", "invalid name \"" + *name + "\"",
                 "letters, digits, '_', '-' and '.' (it names the output folder)");
  scene.name = name.value_or("");
  scene.description = root.string("description", false, "any text").value_or("");
  const fs::path folder = origin.parent_path();
  const auto surface = parse_surface(root, folder, problems);
  const auto material = parse_material(root, problems);
  const auto loads = parse_loads(root, problems);
  std::vector<std::string> labels;  // every label in the file, also those with problems
  scene.methods = parse_methods(root, surface, labels, problems);
  if (const auto reference = root.string("reference", false, "a method label")) {
    if (!reference->empty() && std::find(labels.begin(), labels.end(), *reference) == labels.end())
      root.problem(
          "reference", "no method labelled \"" + *reference + "\"",
          labels.empty() ? std::string("a label of a [methods.<label>] table") : join(labels) + ", \"\"");
    scene.reference = *reference;
  } else if (!root.has("reference")) {
    // Default: the BEM when it is the only one, else no comparison.
    const auto bem = std::count_if(scene.methods.begin(), scene.methods.end(),
                                   [](const MethodSpec& m) { return m.kind == MethodKind::bem; });
    if (bem == 1)
      scene.reference = std::find_if(scene.methods.begin(), scene.methods.end(), [](const MethodSpec& m) {
                          return m.kind == MethodKind::bem;
                        })->label;
  }
  problems.throw_if_any();
  scene.surface = *surface;
  scene.material = *material;
  scene.loads = *loads;
  return scene;
}

Scene read_scene(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    Problems problems(origin_name(path));
    problems.add(0, "file", "cannot open the scene file " + fs::absolute(path).lexically_normal().string());
    problems.throw_if_any();
  }
  std::ostringstream text;
  text << in.rdbuf();
  Scene scene = parse_scene(text.str(), path);
  scene.file = path;
  return scene;
}

std::string to_toml(const Scene& scene) {
  std::string out = "# contactbench scene as understood, defaults filled in (scenes/README.md)\n";
  render_toml_table(out, scene_table(scene, false), "");
  return out;
}

std::string to_json(const Scene& scene) {
  std::string out;
  render_json(out, {scene_table(scene, true)}, 0);
  return out + "\n";
}

}  // namespace contactbench

// The scene's schema: the keys of the top level, [material], [loads] and [methods.<label>] (each method
// reads its own keys, app/methods/), [surface] in app/surface_source.cpp. Docs: scenes/README.md.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "contactbench/app/methods/registry.hpp"
#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_grid_override.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/core/bounded_read.hpp"
#include "contactbench/core/material.hpp"

namespace contactbench {

namespace {

namespace fs = std::filesystem;

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

// The loads every method answers at (ascending, each once) and, with path = "as listed", the listed path.
struct ParsedLoads {
  std::vector<Real> loads;
  std::vector<Real> path;
};

std::optional<ParsedLoads> parse_loads(const Section& root, Problems& problems) {
  constexpr std::string_view forms = "values = [ ... ] or range = { from, to, count, spacing }";
  const toml::table* table = root.subtable("loads", true, forms);
  if (!table) return std::nullopt;
  const std::size_t before = problems.count();
  const Section l(*table, "loads", problems);
  l.reject_unknown({"values", "range", "path"});
  constexpr std::string_view paths = "\"ascending\" (the default), \"as listed\"";
  const auto path = l.string("path", false, paths);
  if (path && *path != "ascending" && *path != "as listed")
    l.problem("path", "unknown load path \"" + *path + "\"", paths);
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
          problems.add(line_of(element), path, "out of range: got " + exact_number(*value), load.accepted);
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
        r.problem("to", "must exceed from = " + exact_number(*from) + ": got " + exact_number(*to),
                  "a number > from");
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
  ParsedLoads parsed;
  if (path && *path == "as listed") parsed.path = loads;
  std::sort(loads.begin(), loads.end());
  loads.erase(std::unique(loads.begin(), loads.end()), loads.end());
  parsed.loads = std::move(loads);
  return parsed;
}

// The methods in the order the file lists them (toml++ keeps a table's keys sorted, not in file order).
// `ignore = ["hardness", ...]`: the effects of the interface a method runs without (app/interface.hpp).
std::vector<Effect> read_ignored_effects(const Section& s) {
  const std::string accepted = "an array of effect names: " + effects_text(known_effects());
  std::vector<Effect> ignored;
  const toml::node* node = s.find("ignore");
  if (!node) return ignored;
  const auto* array = node->as_array();
  if (!array) {
    s.wrong_type("ignore", "an array of strings", accepted);
    return ignored;
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const std::string path = s.key_path("ignore") + "[" + std::to_string(i) + "]";
    const auto* name = element.as_string();
    const auto effect = name ? effect_of(name->get()) : std::nullopt;
    if (!name)
      s.problems().add(line_of(element), path,
                       "wrong type: expected a string, got " + std::string(type_name(element)), accepted);
    else if (!effect)
      s.problems().add(line_of(element), path, "unknown effect \"" + name->get() + "\"", accepted);
    else if (std::find(ignored.begin(), ignored.end(), *effect) == ignored.end())
      ignored.push_back(*effect);
  }
  return ignored;
}

std::vector<MethodSpec> parse_methods(const Section& root, const std::optional<SurfaceSpec>& surface,
                                      const InterfaceSpec& interface, const fs::path& folder,
                                      std::vector<std::string>& labels, Problems& problems) {
  const MethodRegistry& registry = MethodRegistry::global();
  const std::string known = registry.names_text();
  const std::string accepted = "tables [methods.<label>] with method = one of " + known;
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
  SceneContext context{.surface_points = surface ? points_a_side(*surface) : std::nullopt,
                       .surface_periodic = true,  // not known before the file is read; unused here
                       .folder = folder,
                       .interface = interface};
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
    Section s(*method_table, "methods." + label, problems);
    s.accept_common_keys({"ignore"});
    const bool label_is_a_name = registry.make(label) != nullptr;
    std::string name = label_is_a_name ? label : "";
    if (const auto given = s.string("method", false, known)) {
      if (!registry.make(*given)) {
        s.problem("method", "unknown method \"" + *given + "\"", known);
        continue;
      }
      if (label_is_a_name && *given != label) {
        s.problem("method", "the label names the method " + label + ", not " + *given,
                  "method = \"" + label + "\", or another label");
        continue;
      }
      name = *given;
    } else if (!s.has("method") && !label_is_a_name) {
      s.missing("method", known + " (required when the label is not a method name)");
    }
    if (name.empty()) continue;
    std::unique_ptr<Method> method = registry.make(name);
    std::vector<Effect> ignored = read_ignored_effects(s);
    context.interface = interface.without(ignored);
    method->read(s, context);
    result.push_back({label, std::shared_ptr<const Method>(std::move(method)), std::move(ignored)});
  }
  return result;
}

// `compare = ["area", "mean_gap", "stiffness"]`: what the comparison judges besides the area, which it
// always judges (app/compared_quantity.hpp). Absent: the area alone.
std::vector<Quantity> parse_compare(const Section& root) {
  const std::string accepted = "an array of quantity names: " + quantities_text();
  std::vector<Quantity> compare = {Quantity::area};
  const toml::node* node = root.find("compare");
  if (!node) return compare;
  const auto* array = node->as_array();
  if (!array) {
    root.wrong_type("compare", "an array of strings", accepted);
    return compare;
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const toml::node& element = *array->get(i);
    const std::string path = "compare[" + std::to_string(i) + "]";
    const auto* name = element.as_string();
    const auto quantity = name ? quantity_of(name->get()) : std::nullopt;
    if (!name)
      root.problems().add(line_of(element), path,
                          "wrong type: expected a string, got " + std::string(type_name(element)), accepted);
    else if (!quantity)
      root.problems().add(line_of(element), path, "unknown quantity \"" + name->get() + "\"", accepted);
    else if (std::find(compare.begin(), compare.end(), *quantity) == compare.end())
      compare.push_back(*quantity);
  }
  // In the one order the outputs use, whatever the file's.
  std::sort(compare.begin(), compare.end());
  return compare;
}

// `distributions = { load = <P/(E* A0)>, bins = <count> }`: the reference load of the distributions
// (app/distributions_csv.hpp), one of the scene's loads, and a BEM to measure them. Absent: none.
std::optional<DistributionsSpec> parse_distributions(const Section& root, const std::vector<Real>* loads,
                                                     const std::vector<MethodSpec>& methods) {
  const toml::table* table = root.subtable(
      "distributions", false, "a table { load = <one of the scene's loads>, bins = <2..10000> }");
  if (!table) return std::nullopt;
  const Section d(*table, "distributions", root.problems());
  d.reject_unknown({"load", "bins"});
  const auto load = d.number("load", true, positive("P/(E* A0), one of the scene's loads"));
  const auto bins = d.integer("bins", false, int_range(2, 10000));
  if (!load) return std::nullopt;
  if (loads) {
    // The same number as written among the loads: equal to the last bits, or a relative 1e-12 for a
    // value computed differently (a range's).
    const bool listed = std::any_of(loads->begin(), loads->end(),
                                    [&](Real l) { return std::abs(l - *load) <= 1e-12 * std::abs(l); });
    if (!listed) {
      std::vector<std::string> values;
      for (const Real l : *loads)
        values.push_back(exact_number(l));
      d.problem("load", "the load " + exact_number(*load) + " is not one of the scene's loads",
                "one of " + join(values));
    }
  }
  const bool bem = std::any_of(methods.begin(), methods.end(),
                               [](const MethodSpec& m) { return m.method->name() == "bem"; });
  if (!bem)
    root.problem("distributions", "the distributions are the BEM's, and this scene has no bem method",
                 "a [methods.bem] table, or no distributions key");
  return DistributionsSpec{.load = *load, .bins = bins.value_or(60)};
}

// `approach_retract = { from = <m>, to = <m>, steps = <count> }`: the closed separation-controlled path
// each adhesive BEM runs after its loads (bem/adhesive_path.hpp): down from `from` to `to`, and back, in
// `steps` equal steps a leg. Needs the interface's adhesion and a BEM that models it. Absent: none.
std::optional<AdhesivePathOptions> parse_approach_retract(const Section& root, const InterfaceSpec& interface,
                                                          const std::vector<MethodSpec>& methods) {
  const char* accepted_table =
      "a table { from = <separation [m]>, to = <a smaller separation [m]>, steps = <2..100000> }";
  const toml::table* table = root.subtable("approach_retract", false, accepted_table);
  if (!table) return std::nullopt;
  const Section p(*table, "approach_retract", root.problems());
  p.reject_unknown({"from", "to", "steps"});
  const Rule<Real> separation{[](Real v) { return std::isfinite(v); },
                              "a finite separation [m] of the flat from the heights' mean plane"};
  const auto from = p.number("from", true, separation);
  const auto to = p.number("to", true, separation);
  const auto steps = p.integer("steps", true, int_range(2, 100000));
  if (from && to && !(*to < *from))
    p.problem(
        "to",
        "the path turns at " + exact_number(*to) + " m, not below its start " + exact_number(*from) + " m",
        "a separation below `from` (the flat comes down, then goes back up)");
  // The adhesive BEM's: the scene's adhesion and at least one BEM that does not ignore it.
  const bool adhesive_bem =
      interface.adhesion && std::any_of(methods.begin(), methods.end(), [](const MethodSpec& m) {
        return m.method->name() == "bem" &&
               std::find(m.ignored.begin(), m.ignored.end(), Effect::adhesion) == m.ignored.end();
      });
  if (!adhesive_bem)
    root.problem(
        "approach_retract",
        interface.adhesion ? "the path is the adhesive BEM's, and every bem method of this scene ignores "
                             "the adhesion"
                           : "the path's jumps come from the attraction, and this scene has no "
                             "interface.adhesion",
        "interface.adhesion and a [methods.<label>] table with method = \"bem\" that does not ignore it, "
        "or no approach_retract key");
  if (!from || !to || !steps) return std::nullopt;
  return AdhesivePathOptions{.start = *from, .turn = *to, .steps = static_cast<Index>(*steps)};
}

std::string origin_name(const fs::path& origin) {
  return origin.empty() ? "<scene>" : origin.string();
}

toml::table parse_toml(std::string_view toml_text, const fs::path& origin) {
  try {
    return toml::parse(toml_text, origin.string());
  } catch (const toml::parse_error& error) {
    Problems problems(origin_name(origin));
    const auto& at = error.source().begin;
    problems.add_syntax_error(static_cast<long>(at.line), static_cast<long>(at.column), error.description());
    problems.throw_if_any();
  }
  return {};  // not reached: throw_if_any threw
}

}  // namespace

std::string_view MethodSpec::name() const {
  return method->name();
}

bool Scene::compares(Quantity quantity) const {
  return std::find(compare.begin(), compare.end(), quantity) != compare.end();
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
  return parse_scene_table(parse_toml(toml_text, origin), origin);
}

Scene parse_scene_table(const toml::table& document, const std::filesystem::path& origin) {
  Problems problems(origin_name(origin));
  const Section root(document, "", problems, true);
  root.reject_unknown({"name", "description", "reference", "compare", "distributions", "approach_retract",
                       "surface", "material", "interface", "loads", "methods"});

  Scene scene;
  const auto name =
      root.string("name", true, "letters, digits, '_', '-' and '.' (it names the output folder)");
  if (name && !portable_name(*name, true))
    root.problem("name", "invalid name \"" + *name + "\"",
                 "letters, digits, '_', '-' and '.' (it names the output folder)");
  scene.name = name.value_or("");
  scene.description = root.string("description", false, "any text").value_or("");
  scene.compare = parse_compare(root);
  const fs::path folder = origin.parent_path();
  const auto surface = read_surface_keys(root, folder);
  const auto material = parse_material(root, problems);
  scene.interface = read_interface(root);
  const auto loads = parse_loads(root, problems);
  std::vector<std::string> labels;  // every label in the file, also those with problems
  scene.methods = parse_methods(root, surface, scene.interface, folder, labels, problems);
  scene.distributions = parse_distributions(root, loads ? &loads->loads : nullptr, scene.methods);
  scene.approach_retract = parse_approach_retract(root, scene.interface, scene.methods);
  if (const auto reference = root.string("reference", false, "a method label")) {
    if (!reference->empty() && std::find(labels.begin(), labels.end(), *reference) == labels.end())
      root.problem(
          "reference", "no method labelled \"" + *reference + "\"",
          labels.empty() ? std::string("a label of a [methods.<label>] table") : join(labels) + ", \"\"");
    scene.reference = *reference;
  } else if (!root.has("reference")) {
    // Default: the ground truth (the BEM) when only one method is, else no comparison.
    const auto truth = [](const MethodSpec& m) { return m.method->is_ground_truth(); };
    if (std::count_if(scene.methods.begin(), scene.methods.end(), truth) == 1)
      scene.reference = std::find_if(scene.methods.begin(), scene.methods.end(), truth)->label;
  }
  problems.throw_if_any();
  scene.surface = *surface;
  scene.material = *material;
  scene.loads = loads->loads;
  scene.load_path = loads->path;
  return scene;
}

namespace {

// The scene file's text as a TOML document.
toml::table read_scene_document(const fs::path& path) {
  // A scene is a few kilobytes of TOML: 16 MiB is far beyond any real one and bounds a wrong argument
  // (a device such as /dev/zero is refused by name, never read without end).
  constexpr std::uintmax_t max_scene_bytes = std::uintmax_t{16} << 20;
  std::string text;
  try {
    text = read_file_bounded(path, max_scene_bytes, "scene files");
  } catch (const InputError& e) {
    Problems problems(origin_name(path));
    problems.add(0, "file", "cannot open the scene file " + std::string(e.what()));
    problems.throw_if_any();
  }
  return parse_toml(text, path);
}

}  // namespace

Scene read_scene(const std::filesystem::path& path) {
  Scene scene = parse_scene_table(read_scene_document(path), path);
  scene.file = path;
  return scene;
}

Scene read_scene_on_grid(const std::filesystem::path& path, Index points) {
  const toml::table document = read_scene_document(path);
  // The scene as written is checked first, so that its own problems are reported at their lines; then the
  // override (app/scene_grid_override.hpp), and the overridden scene is checked again.
  const Scene as_written = parse_scene_table(document, path);
  Scene scene = parse_scene_table(with_grid_override(document, as_written, points, path), path);
  scene.file = path;
  return scene;
}

}  // namespace contactbench

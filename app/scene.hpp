// A scene: what a user asks contactbench to compare (a surface, a material, loads, methods, a reference),
// read from a TOML file (app/scene_schema.cpp) and checked completely before any stage runs: its keys when
// read, each method against the surface, material and loads before the first stage (app/scene_run.hpp).
// Docs: scenes/README.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "contactbench/app/compared_quantity.hpp"
#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/interface.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/surface_source.hpp"
#include "contactbench/bem/adhesive_path.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

class Method;  // app/methods/method.hpp

// [material]: E* is what every method uses (docs/theory.md section 0); the elastic constants are kept as
// given so that the report can show them. Either E and nu (then optionally E2 and nu2: a second elastic
// body), or estar alone.
struct MaterialSpec {
  Real estar = 0;                        // the contact modulus E* [Pa], always set
  std::optional<Real> youngs_modulus;    // E [Pa]
  std::optional<Real> poisson_ratio;     // nu
  std::optional<Real> youngs_modulus_2;  // E2 [Pa] of an elastic counter-body
  std::optional<Real> poisson_ratio_2;   // nu2
  bool two_bodies() const { return youngs_modulus_2.has_value(); }
};

// [methods.<label>]: the label names the method's outputs; the method object holds its own options
// (app/methods/method.hpp). Shared, never changed after reading: copies of a scene share their methods.
struct MethodSpec {
  std::string label;
  std::shared_ptr<const Method> method;
  // `ignore = [...]`: effects of the scene's interface this method runs without, said explicitly (it is
  // refused otherwise when it does not model them); every output marks its row (app/interface.hpp).
  std::vector<Effect> ignored;
  std::string_view name() const;  // the registry name, e.g. "bem"
};

struct Scene {
  std::string name;            // also the default output folder runs/<name>/
  std::string description;     // optional free text
  std::filesystem::path file;  // the scene file itself ("" when parsed from a string)
  SurfaceSpec surface;
  MaterialSpec material;
  InterfaceSpec interface;  // [interface]: the effects the scene calls for (none: elastic)
  std::vector<Real> loads;  // P/(E* A0), ascending, > 0: the one list every method answers at
  // loads.path = "as listed": the listed loads in the file's order, up and down and repeated (a load path:
  // the plastic BEM keeps its deformation along it, docs/solvers.md "Hardness"); empty: path = "ascending".
  std::vector<Real> load_path;
  std::vector<MethodSpec> methods;  // in the order the file lists them
  std::string reference;            // label of the method the others are judged against
  // `compare = [...]`: the quantities compared, the area always first (app/compared_quantity.hpp).
  std::vector<Quantity> compare = {Quantity::area};
  bool compares(Quantity quantity) const;
  // `distributions = { load, bins }`: the BEM's pressure, gap and patch-size distributions at one of the
  // loads (app/distributions_csv.hpp); absent: none measured.
  std::optional<DistributionsSpec> distributions;
  // `approach_retract = { from, to, steps }`: after its loads, each adhesive BEM also runs the closed
  // approach-retract path under separation control (bem/adhesive_path.hpp; start = from, turn = to [m]);
  // absent: none.
  std::optional<AdhesivePathOptions> approach_retract;
  const MethodSpec& method(std::string_view label) const;  // throws Error if absent
};

// Parses and validates a scene. Every problem found (unknown key, wrong type, value out of range, unknown
// method, missing file, unknown reference) is collected, and one SceneError lists them all, each with its
// key path (e.g. "material.nu") and the accepted values. `origin` names the text in messages and is the
// folder against which relative file paths resolve (its parent directory).
Scene parse_scene(std::string_view toml_text, const std::filesystem::path& origin);
Scene read_scene(const std::filesystem::path& path);
// `contactbench run SCENE --grid N`: the scene with its generated surface on `points` a side and its refine
// keys scaled alike (app/scene_grid_override.hpp); a SceneError names the key when that cannot apply.
Scene read_scene_on_grid(const std::filesystem::path& path, Index points);

// The scene as understood, defaults filled in, as TOML that parse_scene accepts again (for users to copy).
// Methods keep their order. Throws Error for what a file cannot say (a seed above 2^63 - 1).
std::string to_toml(const Scene& scene);

// The same scene as one JSON object with the keys of the TOML file (material.estar always present), for
// summary.json. JSON objects have no order: the methods' order is Scene::methods'.
std::string to_json(const Scene& scene);

}  // namespace contactbench

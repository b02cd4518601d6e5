// A scene: what a user asks contactbench to compare (a surface, a material, loads, methods, a reference),
// read from a TOML file and validated completely before anything runs (docs: scenes/README.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

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
  std::filesystem::path path;  // resolved against the scene file's folder when relative
  std::optional<Real> size_x;  // [m], required when the file does not state its size
  std::optional<Real> size_y;  // [m]
  bool periodic = false;
};

struct SurfaceSpec {
  std::variant<GeneratedSurfaceSpec, FileSurfaceSpec> source;
};

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

enum class MethodKind { bem, plateau, gw_mccool, bgt, bgt_linear, persson };

// Every accepted method name, in the order the documentation lists them.
inline constexpr std::string_view kMethodNames[] = {"bem", "plateau",    "gw_mccool",
                                                    "bgt", "bgt_linear", "persson"};
std::string_view to_string(MethodKind kind);

// [methods.<label>] with method = "bem" (or the label "bem" itself).
struct BemMethodSpec {
  Index refine = 0;       // points a side of the surface the BEM solves on (Fourier refinement); 0 = as given
  Real tolerance = 1e-8;  // relative change of the pressure (bem/polonsky_keer.hpp)
  Index max_iterations = 20000;
  std::optional<bool> periodic;        // default: the surface's own periodicity
  std::optional<Real> hardness;        // [Pa]: perfectly plastic pressure cap; absent = purely elastic
  int connectivity = 4;                // for counting contact spots
  SolverKind solver = kDefaultSolver;  // solver = "polonsky_keer" | "preconditioned_cg" (docs/solvers.md)
};

// [methods.<label>] with method = "plateau" (docs/theory.md section 4).
struct PlateauMethodSpec {
  int connectivity = 4;
  SweepLevels levels = SweepLevels::exact();  // levels = "exact" | "paper" | an integer count (uniform)
  std::optional<bool> periodic;               // default: the surface's own periodicity
};

// [methods.<label>] of an analytic theory (gw_mccool, bgt, bgt_linear, persson). The theories are for
// isotropic surfaces and refuse one whose x and y profile moments differ by more than 5 %
// (theories/load_solver.hpp), unless anisotropy = "average": then they see the surface's equivalent isotropic
// surface, the means of its x and y profile moments, which keeps the areal gbar^2 = m2x + m2y (exact for
// Persson's theory and the BGT linear law, which depend on gbar alone; an approximation for GW-McCool and the
// full BGT).
struct TheoryMethodSpec {
  bool average_anisotropy = false;  // anisotropy = "refuse" (default) | "average"
};

struct MethodSpec {
  std::string label;  // the table's name: the key of [methods.<label>]
  MethodKind kind = MethodKind::bem;
  std::variant<TheoryMethodSpec, BemMethodSpec, PlateauMethodSpec> options;
};

struct Scene {
  std::string name;            // also the default output folder results/<name>/
  std::string description;     // optional free text
  std::filesystem::path file;  // the scene file itself ("" when parsed from a string)
  SurfaceSpec surface;
  MaterialSpec material;
  std::vector<Real> loads;          // P/(E* A0), ascending, > 0
  std::vector<MethodSpec> methods;  // in the order the file lists them
  std::string reference;            // label of the method the others are judged against
  const MethodSpec& method(std::string_view label) const;  // throws Error if absent
};

// Every problem a scene has, one per line of the message ("<origin>: <key path>: <reason>; accepted: ...").
class SceneError : public Error {
 public:
  SceneError(const std::string& message, std::vector<std::string> problems)
      : Error(message), problems_(std::move(problems)) {}
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// Parses and validates a scene. Every problem found (unknown key, wrong type, value out of range, unknown
// method, missing file, unknown reference) is collected, and one SceneError lists them all, each with its
// key path (e.g. "material.nu") and the accepted values. `origin` names the text in messages and is the
// folder against which relative file paths resolve (its parent directory).
Scene parse_scene(std::string_view toml_text, const std::filesystem::path& origin);
Scene read_scene(const std::filesystem::path& path);

// The scene as understood, defaults filled in, as TOML that parse_scene accepts again (for summary.json's
// record and for users to copy). Methods keep their order. Throws Error for what a file cannot say (a seed
// above 2^63 - 1, paper levels with a count other than 500).
std::string to_toml(const Scene& scene);

// The same scene as one JSON object with the keys of the TOML file (material.estar always present), for
// summary.json. JSON objects have no order: the methods' order is Scene::methods'.
std::string to_json(const Scene& scene);

}  // namespace contactbench

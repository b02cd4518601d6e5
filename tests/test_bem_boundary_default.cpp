// The BEM's `boundary` left unset (app/methods/bem_settings.hpp, resolve_boundary; docs/solvers.md "Mirrored
// boundary"): "mirrored" on a non-periodic problem where the mirror is available, else "as_is" with the
// reason in the run's parameters; a declared value is kept, and a declared "mirrored" where it is unavailable
// is refused, not quietly solved as is.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "contactbench/app/methods/bem_settings.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/scene_plan.hpp"
#include "contactbench/app/scene_run.hpp"
#include "run_scene_text.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

BemSettings unset_boundary() {
  BemSettings settings = default_settings(bem_settings());
  EXPECT_FALSE(settings.mirrored.has_value()) << "boundary has no default value: resolve_boundary gives it";
  return settings;
}

TEST(BemBoundaryDefault, UnsetResolvesMirroredOnlyForANonPeriodicProblemWithoutWhatTheMirrorLacks) {
  const BemSettings plain = unset_boundary();
  // Periodic: no edges, nothing to choose, nothing to explain.
  const ResolvedBoundary periodic = resolve_boundary(plain, true, false);
  EXPECT_FALSE(periodic.mirrored);
  EXPECT_TRUE(periodic.as_is_because.empty()) << periodic.as_is_because;
  const ResolvedBoundary record = resolve_boundary(plain, false, false);
  EXPECT_TRUE(record.mirrored);
  EXPECT_TRUE(record.as_is_because.empty()) << record.as_is_because;

  // Each thing the mirror lacks, alone: as is, and the reason names it.
  BemSettings residual = plain;
  residual.residual_topography = "after.txt";
  BemSettings extrapolated = plain;
  extrapolated.extrapolate = true;
  struct Case {
    const char* what;
    ResolvedBoundary resolved;
    const char* named;
  };
  const std::vector<Case> cases = {
      {"adhesion", resolve_boundary(plain, false, true), "adhesion"},
      {"residual_topography", resolve_boundary(residual, false, false), "residual_topography"},
      {"extrapolate", resolve_boundary(extrapolated, false, false), "extrapolate = true"},
  };
  for (const Case& c : cases) {
    EXPECT_FALSE(c.resolved.mirrored) << c.what;
    EXPECT_TRUE(contains(c.resolved.as_is_because, c.named)) << c.what << ": " << c.resolved.as_is_because;
    EXPECT_TRUE(contains(c.resolved.as_is_because, "boundary unset")) << c.resolved.as_is_because;
  }
  // The same on a periodic problem: still nothing to choose or explain.
  EXPECT_TRUE(resolve_boundary(extrapolated, true, true).as_is_because.empty());
}

TEST(BemBoundaryDefault, ADeclaredBoundaryIsKeptAsDeclared) {
  BemSettings as_is = unset_boundary();
  as_is.mirrored = false;
  for (const bool periodic : {true, false}) {
    const ResolvedBoundary kept = resolve_boundary(as_is, periodic, false);
    EXPECT_FALSE(kept.mirrored);
    EXPECT_TRUE(kept.as_is_because.empty()) << "declared, not a fallback: " << kept.as_is_because;
  }
  // Declared "mirrored" stays "mirrored" even where it is unavailable: the preflight refuses it there
  // (below), the resolution never turns it into "as_is".
  BemSettings mirrored = unset_boundary();
  mirrored.mirrored = true;
  mirrored.extrapolate = true;
  EXPECT_TRUE(resolve_boundary(mirrored, false, true).mirrored);
  EXPECT_TRUE(resolve_boundary(mirrored, true, false).mirrored);
}

// The ranks mirror on their slabs (mpi/distributed_mirror.hpp): no boundary is refused under mpiexec.
TEST(BemBoundaryDefault, TheDistributedSolverTakesEveryBoundary) {
  const BemSettings defaults = default_settings(bem_settings());
  BemSettings settings = unset_boundary();
  EXPECT_TRUE(undistributed_settings(bem_settings(), settings, defaults).empty());
  for (const bool mirrored : {false, true}) {
    settings.mirrored = mirrored;
    EXPECT_TRUE(undistributed_settings(bem_settings(), settings, defaults).empty()) << mirrored;
  }
}

// The small scene's 32 x 32 surface is periodic; `periodic = false` makes the BEM treat it as a finite
// record.
std::string record_scene(const std::string& name, const std::string& methods) {
  return "name = \"" + name + "\"\n" + kSmallSurfaceAndMaterial + "[loads]\nvalues = [1e-3, 5e-3, 2e-2]\n" +
         methods;
}

const std::vector<Real>& column(const MethodCurve& curve, const std::string& name) {
  const auto found = std::find_if(curve.columns.begin(), curve.columns.end(),
                                  [&](const auto& c) { return c.first == name; });
  EXPECT_NE(found, curve.columns.end()) << name;
  static const std::vector<Real> none;
  return found == curve.columns.end() ? none : found->second;
}

std::size_t bem_stages(const SceneReport& report) {
  return static_cast<std::size_t>(std::count_if(report.stages.begin(), report.stages.end(),
                                                [](const auto& s) { return s.name.rfind("bem (", 0) == 0; }));
}

// End to end: an unset boundary on a non-periodic problem is the declared mirror's solve, bit for bit (the
// same stage: same solver, grid and iteration; compared with ==, no tolerance), and its parameters say so.
TEST(BemBoundaryDefault, UnsetOnARecordIsTheMirroredSolveBitForBitAndSaysSo) {
  const SceneReport unset = run_scene_text(record_scene("unset", "[methods.bem]\nperiodic = false\n"));
  const SceneReport mirrored =
      run_scene_text(record_scene("mirrored", "[methods.bem]\nperiodic = false\nboundary = \"mirrored\"\n"));
  const SceneReport as_is =
      run_scene_text(record_scene("as_is", "[methods.bem]\nperiodic = false\nboundary = \"as_is\"\n"));
  const MethodCurve& u = unset.methods[0].curve;
  const MethodCurve& m = mirrored.methods[0].curve;
  EXPECT_EQ(u.area_fraction, m.area_fraction);
  EXPECT_EQ(u.area_fraction_nodes, m.area_fraction_nodes);
  EXPECT_EQ(u.separation, m.separation);
  EXPECT_EQ(column(u, "max_pressure"), column(m, "max_pressure"));
  EXPECT_EQ(column(u, "edge_load_share"), column(m, "edge_load_share"));
  // And not the as-is solve: the punch at the record's edges changes the contact (else this test could not
  // tell the two boundaries apart).
  EXPECT_NE(u.area_fraction_nodes, as_is.methods[0].curve.area_fraction_nodes);
  EXPECT_TRUE(contains(u.parameters, "non-periodic mirrored")) << u.parameters;
  EXPECT_FALSE(contains(u.parameters, "as is")) << u.parameters;
  EXPECT_TRUE(contains(as_is.methods[0].curve.parameters, "non-periodic,"))
      << as_is.methods[0].curve.parameters;
  EXPECT_FALSE(contains(as_is.methods[0].curve.parameters, "boundary unset"));

  // In one scene, unset and declared "mirrored" share one solve.
  const SceneReport both =
      run_scene_text(record_scene("both",
                                  "[methods.bem]\nperiodic = false\n[methods.bem_m]\nmethod = \"bem\"\n"
                                  "periodic = false\nboundary = \"mirrored\"\nconnectivity = 8\n"));
  EXPECT_EQ(bem_stages(both), 1u);
  EXPECT_EQ(both.methods[0].curve.area_fraction, m.area_fraction);
}

// A fallback says why, in the parameters of the method that left the boundary unset only: here extrapolate
// (its finer grids are Fourier refinements of a periodic surface). A declared "as_is" beside it shares the
// solve and reads as declared.
TEST(BemBoundaryDefault, AFallbackToAsIsSaysWhyInTheUnsetMethodsParameters) {
  const SceneReport report = run_scene_text(
      record_scene("fallback",
                   "[methods.bem]\nperiodic = false\nextrapolate = true\nerror_estimate = \"gci2\"\n"
                   "[methods.bem_declared]\nmethod = \"bem\"\nperiodic = false\nextrapolate = true\n"
                   "error_estimate = \"gci2\"\nboundary = \"as_is\"\nconnectivity = 8\n"));
  EXPECT_EQ(bem_stages(report), 1u);
  const std::string& unset = report.methods[0].curve.parameters;
  const std::string& declared = report.methods[1].curve.parameters;
  EXPECT_TRUE(contains(unset, "non-periodic as is (boundary unset")) << unset;
  EXPECT_TRUE(contains(unset, "extrapolate = true")) << unset;
  EXPECT_FALSE(contains(declared, "boundary unset")) << declared;
  EXPECT_FALSE(contains(declared, "mirrored")) << declared;
}

// Adhesion, planned only (the planner runs nothing): as is, the reason named; without it, mirrored.
TEST(BemBoundaryDefault, ThePlanFallsBackWithAdhesion) {
  const Grid grid{.nx = 32, .ny = 32, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  const Scene adhesive =
      parse_scene(record_scene("adhesive",
                               "[interface]\nadhesion = { model = \"dugdale\", work = 0.05, stress = 1e5 }\n"
                               "[methods.bem]\nperiodic = false\n"),
                  "test.toml");
  const ScenePlan with_adhesion = plan_scene(adhesive, grid);
  ASSERT_EQ(with_adhesion.bems.size(), 1u);
  EXPECT_FALSE(with_adhesion.bems[0].stage.settings.mirrored.value_or(true));
  EXPECT_TRUE(contains(with_adhesion.bems[0].stage.name(), "as is (boundary unset"));
  EXPECT_TRUE(contains(with_adhesion.bems[0].stage.as_is_because, "adhesion"));

  const Scene record = parse_scene(record_scene("record", "[methods.bem]\nperiodic = false\n"), "test.toml");
  const ScenePlan plan = plan_scene(record, grid);
  EXPECT_TRUE(plan.bems[0].stage.settings.mirrored.value_or(false));
  EXPECT_TRUE(plan.bems[0].stage.as_is_because.empty()) << plan.bems[0].stage.as_is_because;
}

// Declared "mirrored" where the mirror is unavailable: refused naming the key, before any solve.
TEST(BemBoundaryDefault, ADeclaredMirrorWhereUnavailableIsRefusedNamingTheKey) {
  const auto refusal = [](const std::string& text) -> std::string {
    try {
      run_scene_text(text);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "";
  };
  const std::string adhesion =
      refusal(record_scene("a",
                           "[interface]\nadhesion = { model = \"dugdale\", work = 0.05, stress = 1e5 }\n"
                           "[methods.bem]\nperiodic = false\nboundary = \"mirrored\"\n"));
  EXPECT_TRUE(contains(adhesion, "boundary")) << adhesion;
  EXPECT_TRUE(contains(adhesion, "adhesion")) << adhesion;
  const std::string extrapolate = refusal(
      record_scene("e", "[methods.bem]\nperiodic = false\nboundary = \"mirrored\"\nextrapolate = true\n"));
  EXPECT_TRUE(contains(extrapolate, "boundary")) << extrapolate;
  EXPECT_TRUE(contains(extrapolate, "extrapolate")) << extrapolate;
  const std::string periodic = refusal(record_scene("p", "[methods.bem]\nboundary = \"mirrored\"\n"));
  EXPECT_TRUE(contains(periodic, "periodic = false")) << periodic;
}

}  // namespace
}  // namespace contactbench

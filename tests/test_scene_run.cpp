// Scenes end to end (app/scene_plan.hpp, app/scene_run.hpp, app/report_writers.hpp): the planner runs exactly
// the stages the methods need, each once; the shipped scenes run on a small grid; the files are complete.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/app/comparison.hpp"
#include "contactbench/app/load_area_plots.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_plan.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/app/surface_source.hpp"
#include "contactbench/app/unconverged.hpp"
#include "contactbench/bem/grid_convergence.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"
#include "run_scene_text.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

const std::filesystem::path kSource = CB_SOURCE_DIR;

std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Replaces every `from` in `text` by `to`; fails the test if there is none (the scene changed shape).
std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "no '" << from << "' to replace";
  for (; at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// A 32 x 32 version of a paper scene: grid 256 -> 32 and the BEM's refinement 512 -> 64 (same ratio).
std::string small_paper_scene(const std::string& file) {
  std::string text = slurp(kSource / "scenes" / "paper" / file);
  text = replace_all(text, "grid = 256", "grid = 32");
  return replace_all(text, "refine = 512", "refine = 64");
}

bool ran(const SceneReport& report, const std::string& prefix) {
  return std::any_of(report.stages.begin(), report.stages.end(),
                     [&](const StageRecord& s) { return s.name.rfind(prefix, 0) == 0; });
}

const std::string kSmallSurface = kSmallSurfaceAndMaterial + "[loads]\nvalues = [1e-3, 1e-2]\n";

TEST(ScenePlan, TheoriesAloneNeverSweepNorSolve) {
  const SceneReport report =
      run_scene_text("name = \"theories\"\n" + kSmallSurface +
                     "[methods.gw_mccool]\n[methods.bgt]\n[methods.bgt_linear]\n[methods.persson]\n");
  EXPECT_FALSE(ran(report, "sweep"));
  EXPECT_FALSE(ran(report, "bem"));
  EXPECT_FALSE(ran(report, "refine"));
  EXPECT_TRUE(ran(report, "moments"));
  ASSERT_EQ(report.methods.size(), 4u);
  for (const MethodResult& m : report.methods) {
    ASSERT_EQ(m.curve.area_fraction.size(), 2u) << m.label;
    EXPECT_GT(m.curve.area_fraction[0], 0) << m.label;
    EXPECT_LT(m.curve.area_fraction[0], m.curve.area_fraction[1]) << m.label;
  }
}

TEST(ScenePlan, PlateauAloneNeverSolvesAndSharesEqualSweeps) {
  const SceneReport report = run_scene_text("name = \"plateaus\"\n" + kSmallSurface + R"(
[methods.plateau_4]
method = "plateau"
[methods.plateau_4_again]
method = "plateau"
connectivity = 4
levels = "exact"
[methods.plateau_8]
method = "plateau"
connectivity = 8
)");
  EXPECT_FALSE(ran(report, "bem"));
  EXPECT_EQ(std::count_if(report.stages.begin(), report.stages.end(),
                          [](const StageRecord& s) { return s.name.rfind("sweep", 0) == 0; }),
            2);  // one sweep per topology: the two 4-connectivity methods share theirs
  EXPECT_EQ(report.methods[0].curve.area_fraction, report.methods[1].curve.area_fraction);
}

TEST(ScenePlan, BemsThatDifferOnlyInSpotCountingShareOneSolve) {
  const Scene scene = parse_scene("name = \"bems\"\n" + kSmallSurface + R"(
[methods.bem_4]
method = "bem"
connectivity = 4
[methods.bem_8]
method = "bem"
connectivity = 8
[methods.bem_loose]
method = "bem"
tolerance = 1e-4
[methods.bem_periodic]
method = "bem"
periodic = true
)",
                                  "test.toml");
  const ScenePlan plan = plan_scene(scene, Grid{.nx = 32, .ny = 32, .lx = 1, .ly = 1, .periodic = true});
  ASSERT_EQ(plan.bems.size(), 2u);
  std::vector<int> bem_of_method;
  for (const ScenePlan::Stages& stages : plan.of_method)
    bem_of_method.push_back(stages.bem);
  // periodic = true on a periodic surface is the default spelled out: the same solve.
  EXPECT_EQ(bem_of_method, (std::vector<int>{0, 0, 1, 0}));
  EXPECT_EQ(plan.bems[0].connectivities, (std::set<int>{4, 8})) << "one solve, labelled for both counts";
  EXPECT_EQ(plan.bems[1].connectivities, (std::set<int>{4}));
  EXPECT_TRUE(plan.sweeps.empty());
}

// An effect runs only where a method names it: the pressure cap shows in its stage and its own column, and
// the elastic method beside it has neither (and caps nothing: more area under the cap at the same load).
TEST(ScenePlan, AHardnessRunsOnlyForTheMethodThatRunsWithIt) {
  const SceneReport report = run_scene_text("name = \"cap\"\nreference = \"\"\n" + kSmallSurface + R"(
[interface]
hardness = 2e9
[methods.elastic]
method = "bem"
ignore = ["hardness"]
[methods.capped]
method = "bem"
)");
  std::vector<std::string> solves;
  for (const StageRecord& stage : report.stages)
    if (stage.name.rfind("bem", 0) == 0) solves.push_back(stage.name);
  ASSERT_EQ(solves.size(), 2u);  // two BEM solves
  EXPECT_EQ(solves[0].find("hardness"), std::string::npos) << solves[0];
  EXPECT_NE(solves[1].find("hardness"), std::string::npos) << solves[1];
  const auto has_plastic = [](const MethodResult& m) {
    return std::any_of(m.curve.columns.begin(), m.curve.columns.end(),
                       [](const auto& c) { return c.first == "plastic_area_fraction"; });
  };
  EXPECT_FALSE(has_plastic(report.methods[0]));
  EXPECT_TRUE(has_plastic(report.methods[1]));
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_GT(report.methods[1].curve.area_fraction[k], report.methods[0].curve.area_fraction[k]);
}

TEST(ScenePlan, RefusesToRefineANonPeriodicSurface) {
  const Scene scene = parse_scene(R"(name = "measured"
[surface]
file = ")" + (std::filesystem::path(CB_DATA_DIR "/measured") / "matrix-3.txt").string() +
                                      R"("
[material]
estar = 1e11
[loads]
values = [1e-3]
[methods.bem]
refine = 512
)",
                                  "test.toml");
  try {
    run_scene(scene, {.threads = 1, .observer = nullptr});
    ADD_FAILURE() << "refined a non-periodic surface";
  } catch (const SceneError& error) {
    ASSERT_EQ(error.problems().size(), 1u) << error.what();
    EXPECT_NE(error.problems()[0].find("methods.bem.refine"), std::string::npos) << error.what();
  }
}

TEST(ScenePlan, PlateauRefinesLikeTheBemAndRefusesTheSameWay) {
  // refine sweeps the surface Fourier-refined: the same as sweeping the surface generated on the finer grid
  // from the same coefficients (both are the same trigonometric interpolation; equal to rounding, 1e-12,
  // far below the area of one node, 1/64^2 = 2.4e-4, so the node counts agree exactly but for a tie).
  const SceneReport refined = run_scene_text("name = \"refined\"\n" + kSmallSurface + R"(
[methods.plateau_64]
method = "plateau"
refine = 64
[methods.hertz_64]
method = "plateau_hertz"
refine = 64
)");
  const SceneReport generated = run_scene_text(
      "name = \"generated\"\n" + replace_all(kSmallSurface, "seed = 2 }", "seed = 2, refine = 64 }") + R"(
[methods.plateau]
)");
  ASSERT_TRUE(ran(refined, "sweep (refined to 64 x 64"));
  for (std::size_t k = 0; k < refined.loads().size(); ++k)
    EXPECT_NEAR(refined.methods[0].curve.area_fraction[k], generated.methods[0].curve.area_fraction[k],
                1e-9 * generated.methods[0].curve.area_fraction[k]);
  // The refined and unrefined sweeps are different stages, never shared.
  const SceneReport both = run_scene_text("name = \"both\"\n" + kSmallSurface + R"(
[methods.plateau]
[methods.plateau_64]
method = "plateau"
refine = 64
)");
  EXPECT_EQ(std::count_if(both.stages.begin(), both.stages.end(),
                          [](const StageRecord& s) { return s.name.rfind("sweep", 0) == 0; }),
            2);
  // Same key, same refusals as the BEM's.
  for (const std::string method : {"plateau", "plateau_hertz"}) {
    try {
      run_scene_text("name = \"bad\"\n" + kSmallSurface + "[methods.p]\nmethod = \"" + method +
                     "\"\nrefine = 16\n");
      ADD_FAILURE() << method << " refined to fewer points";
    } catch (const SceneError& error) {
      EXPECT_NE(std::string(error.what()).find("methods.p.refine: out of range: got 16"), std::string::npos)
          << error.what();
    }
  }
}

TEST(ScenePlan, PlateauHertzIsThePlateauSweepReadAsParaboloids) {
  // docs/theory.md section 8.3: A_H(P) = A_c(z) / 2 where the paper's model carries sqrt(2) P at z, on the
  // same sweep (shared). Exact relation between the two methods' answers, to rounding (1e-12).
  const std::string loads =
      "[loads]\nvalues = [1e-3, 1.41421356237309515e-3, 1e-2, 1.41421356237309515e-2]\n";
  const SceneReport report = run_scene_text("name = \"hertz\"\n" + kSmallSurfaceAndMaterial + loads + R"(
[methods.plateau]
[methods.hertz]
method = "plateau_hertz"
)");
  EXPECT_EQ(std::count_if(report.stages.begin(), report.stages.end(),
                          [](const StageRecord& s) { return s.name.rfind("sweep", 0) == 0; }),
            1);
  const auto& paper = report.methods[0].curve.area_fraction;
  const auto& hertz = report.methods[1].curve.area_fraction;
  EXPECT_NEAR(hertz[0], paper[1] / 2, 1e-12);
  EXPECT_NEAR(hertz[2], paper[3] / 2, 1e-12);
  // Named apart from the paper's model wherever it is reported.
  EXPECT_NE(report.methods[1].curve.parameters.find("not the paper's model"), std::string::npos);
  EXPECT_NE(report.methods[1].compared_area.find("Hertz-consistent"), std::string::npos);
}

// The tables, the legend and the unconverged-load marking read a method's typed fields and its note, never
// its name or a column's: a note set on any row (as an effect's mark would be) shows after its label, and a
// load marked unconverged is marked whichever method it belongs to.
TEST(SceneRun, WritersShowEveryNoteAndReadTypedFields) {
  SceneReport report = run_scene_text("name = \"typed\"\n" + kSmallSurface + R"(
[methods.bem]
[methods.hertz]
method = "plateau_hertz"
[methods.gw]
method = "gw_mccool"
)");
  ASSERT_EQ(report.methods.size(), 3u);
  const MethodResult& bem = report.methods[0];
  EXPECT_EQ(bem.note, "");
  EXPECT_EQ(bem.curve.converged, (std::vector<bool>{true, true}));
  EXPECT_EQ(bem.curve.area_fraction_nodes.size(), 2u);
  // No extrapolation: the compared perimeter-corrected area carries its one-grid calibrated bar K' |N -
  // A_corrected| (docs/theory.md section 9.2; the surface is periodic, no hardness or adhesion). Tolerance
  // 1e-15: the same product of the same numbers.
  ASSERT_EQ(bem.curve.area_fraction_error.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_NEAR(bem.curve.area_fraction_error[k],
                corrected_area_error(bem.curve.area_fraction_nodes[k], bem.curve.area_fraction[k]), 1e-15);
  EXPECT_EQ(report.methods[1].note, "Hertz-consistent plateaus, this project");
  EXPECT_TRUE(report.methods[2].curve.converged.empty());  // a theory does not iterate
  EXPECT_TRUE(describe_unconverged(report).empty());

  report.methods[2].note = "elastic: ignores hardness";
  report.methods[2].curve.converged = {true, false};
  const Comparison comparison = compare(report);
  std::ostringstream table, plot;
  write_table_md(table, report, comparison, current_provenance(1, "test"));
  write_gnuplot_script(plot, report, "a.png", "a.svg");
  for (const std::string& row : {std::string("| hertz (Hertz-consistent plateaus, this project) |"),
                                 std::string("| gw (elastic: ignores hardness) |")})
    EXPECT_NE(table.str().find(row), std::string::npos) << row << " in\n" << table.str();
  EXPECT_NE(plot.str().find("title \"gw (elastic: ignores hardness)\""), std::string::npos) << plot.str();
  EXPECT_NE(table.str().find("(not converged)"), std::string::npos) << table.str();
  EXPECT_EQ(unconverged_loads(report.methods[2].curve), (std::vector<std::size_t>{1}));
}

// The numbers after "key": in text, from position `from` on: one scalar or the elements of an array (null:
// NaN).
std::vector<Real> json_numbers_after(const std::string& text, std::size_t from, const std::string& key) {
  std::size_t at = text.find("\"" + key + "\": ", from);
  if (at == std::string::npos) return {};
  at += key.size() + 4;
  std::vector<Real> numbers;
  const bool array = text[at] == '[';
  if (array) ++at;
  while (true) {
    while (text[at] == ' ')
      ++at;
    if (text.compare(at, 4, "null") == 0) {
      numbers.push_back(std::nan(""));
      at += 4;
    } else {
      std::size_t used = 0;
      numbers.push_back(std::stod(text.substr(at, 40), &used));
      at += used;
    }
    if (!array || text[at] != ',') break;
    ++at;
  }
  return numbers;
}

// The headline comparison against a hand computation: two synthetic curves with known errors, through
// compare() and the writers of table.md and summary.json, every printed column checked against numbers
// worked out by hand below (not by the formulas of app/comparison.cpp). Reference A/A0 = 0.010, 0.020, 0.040
// and the model's 0.011, 0.019, 0.036 at P/(E* A0) = 1e-3, 2e-3, 4e-3: relative errors +10 %, -5 %, -10 %;
// max |e| = 10 %; rms = sqrt((0.01 + 0.0025 + 0.01)/3) = sqrt(0.0075) = 8.660 %. gbar = sqrt(m2x + m2y) =
// sqrt(0.0009 + 0.0016) = 0.05, so kappa = (A/A0) gbar / (P/(E* A0)) at 1e-3 is 0.500 for the reference,
// 0.550 for the model and 0.600 for its node count 0.012. The reference's own error 2e-4 is 2 %, 1 %, 0.5 %
// of its areas (at most 2 %). Tolerance for the JSON's numbers: 1e-12 relative (a few divisions in double);
// the table prints them rounded (%.3f, %.1f %%, %.4g), so its text is compared exactly. Rejects an error
// taken the other way round (reference over model: -9.1 %, +5.3 %, +11.1 %), a mean |e| in place of the rms
// (8.3 %), kappa with the profile gbar sqrt(m2x) (0.300) or at the largest load (0.450 for the model), or a
// column shifted by one load.
TEST(SceneRun, TheComparisonEqualsAHandComputation) {
  SceneReport report = run_scene_text("name = \"hand\"\nreference = \"\"\n" + kSmallSurfaceAndMaterial +
                                      "[loads]\nvalues = [1e-3, 2e-3, 4e-3]\n[methods.persson]\n");
  ASSERT_EQ(report.loads(), (std::vector<Real>{1e-3, 2e-3, 4e-3}));
  const Real nan = std::nan("");
  const std::vector<Real> none{nan, nan, nan};
  MethodResult reference;
  reference.label = "ref";
  reference.method = "bem";
  reference.compared_area = "area_fraction_corrected";
  reference.curve.area_fraction = {0.010, 0.020, 0.040};
  reference.curve.area_fraction_error = {2e-4, 2e-4, 2e-4};
  reference.curve.separation = reference.curve.spots = none;
  reference.curve.parameters = "synthetic reference";
  reference.seconds = 2.5;
  MethodResult model;
  model.label = "model";
  model.method = "plateau_hertz";
  model.compared_area = "area_fraction_nodes";
  model.curve.area_fraction = {0.011, 0.019, 0.036};
  model.curve.area_fraction_nodes = {0.012, 0.019, 0.036};
  model.curve.separation = model.curve.spots = none;
  model.curve.parameters = "synthetic model";
  model.seconds = 0.125;
  report.methods = {reference, model};
  report.scene.reference = "ref";
  report.moments.m2x = 0.0009;
  report.moments.m2y = 0.0016;

  const Comparison comparison = compare(report);
  std::ostringstream table_text, summary_text;
  write_table_md(table_text, report, comparison, current_provenance(1, "test"));
  write_summary_json(summary_text, report, comparison, current_provenance(1, "test"));
  const std::string table = table_text.str(), summary = summary_text.str();

  // table.md: the method table (time, kappa, max abs error, rms error) and A/A0 with each load's error.
  for (const std::string& row :
       {std::string("| ref | 2.5 | 0.500 | reference (its own error up to ± 2.0 %) |  |"),
        std::string("| model | 0.125 | 0.550 (nodes 0.600) | 10.0 % | 8.7 % |"), std::string("gbar = 0.05."),
        std::string("at the smallest load, 0.001 "),
        std::string("| 0.001 | 0.01 (± 2.0 %) | 0.011 (+10.0 %) |"),
        std::string("| 0.002 | 0.02 (± 1.0 %) | 0.019 (-5.0 %) |"),
        std::string("| 0.004 | 0.04 (± 0.5 %) | 0.036 (-10.0 %) |")})
    EXPECT_NE(table.find(row), std::string::npos) << row << " in\n" << table;

  // summary.json: the same numbers unrounded.
  const auto near = [](const std::vector<Real>& got, const std::vector<Real>& expected,
                       const std::string& what) {
    ASSERT_EQ(got.size(), expected.size()) << what;
    for (std::size_t k = 0; k < expected.size(); ++k)
      EXPECT_NEAR(got[k], expected[k], 1e-12 * std::abs(expected[k])) << what << " [" << k << "]";
  };
  near(json_numbers_after(summary, 0, "rms_gradient"), {0.05}, "rms_gradient");
  near(json_numbers_after(summary, 0, "kappa_load"), {1e-3}, "kappa_load");
  near(json_numbers_after(summary, 0, "reference_relative_uncertainty"), {0.02, 0.01, 0.005}, "uncertainty");
  const std::size_t ref_at = summary.find("\"label\": \"ref\""),
                    model_at = summary.find("\"label\": \"model\"");
  ASSERT_NE(ref_at, std::string::npos) << summary;
  ASSERT_NE(model_at, std::string::npos) << summary;
  ASSERT_LT(ref_at, model_at);
  near(json_numbers_after(summary, ref_at, "kappa"), {0.5}, "ref kappa");
  near(json_numbers_after(summary, ref_at, "relative_error"), {0, 0, 0}, "ref relative_error");
  near(json_numbers_after(summary, ref_at, "max_abs_relative_error"), {0}, "ref max");
  near(json_numbers_after(summary, model_at, "kappa"), {0.55}, "model kappa");
  near(json_numbers_after(summary, model_at, "kappa_nodes"), {0.6}, "model kappa_nodes");
  near(json_numbers_after(summary, model_at, "area_fraction"), {0.011, 0.019, 0.036}, "model area_fraction");
  near(json_numbers_after(summary, model_at, "relative_error"), {0.1, -0.05, -0.1}, "model relative_error");
  near(json_numbers_after(summary, model_at, "max_abs_relative_error"), {0.1}, "model max");
  near(json_numbers_after(summary, model_at, "rms_relative_error"), {0.08660254037844386}, "model rms");
}

// A scene with a hardness and a method that ignores it (app/interface.hpp): the method runs elastic, and
// table.md, summary.json and the plot legend mark its row; the BEM, which models the cap, is unmarked and
// solves capped.
TEST(SceneRun, AMethodThatIgnoresAnEffectIsMarkedInEveryOutput) {
  const SceneReport report = run_scene_text("name = \"plastic\"\n" + kSmallSurface + R"(
[interface]
hardness = 2e9
[methods.bem]
[methods.persson]
ignore = ["hardness"]
)");
  ASSERT_EQ(report.methods.size(), 2u);
  EXPECT_EQ(report.methods[0].note, "");
  EXPECT_NE(report.methods[0].curve.parameters.find("hardness 2e+09 Pa"), std::string::npos);
  EXPECT_EQ(report.methods[1].note, "elastic: ignores hardness");
  const Comparison comparison = compare(report);
  std::ostringstream table, summary, plot;
  write_table_md(table, report, comparison, current_provenance(1, "test"));
  write_summary_json(summary, report, comparison, current_provenance(1, "test"));
  write_gnuplot_script(plot, report, "a.png", "a.svg");
  EXPECT_NE(table.str().find("| persson (elastic: ignores hardness) |"), std::string::npos) << table.str();
  EXPECT_NE(table.str().find("| bem |"), std::string::npos) << table.str();
  EXPECT_NE(summary.str().find("\"note\": \"elastic: ignores hardness\""), std::string::npos)
      << summary.str();
  EXPECT_NE(summary.str().find("\"ignored_effects\": [\"hardness\"]"), std::string::npos) << summary.str();
  EXPECT_NE(summary.str().find("\"interface\": {"), std::string::npos) << "the scene as understood";
  EXPECT_NE(plot.str().find("title \"persson (elastic: ignores hardness)\""), std::string::npos)
      << plot.str();
}

// Adhesion on the scene: the BEM solves it and says what it adds per load; a BEM that ignores it runs without
// and is marked. At the same net load the attraction pulls more of the surface into contact (the repulsive
// load is the load plus the pull), so the adhesive area must exceed the non-adhesive one at every load: with
// the pull's sign reversed it would fall short, and with the attraction dropped it would equal it.
TEST(SceneRun, AdhesionAddsItsPullAndGrowsTheArea) {
  const SceneReport report = run_scene_text("name = \"sticky\"\n" + kSmallSurface + R"(
[interface]
adhesion = { model = "dugdale", work = 1.0, stress = 1e8 }
[methods.bem]
[methods.bem_plain]
method = "bem"
ignore = ["adhesion"]
)");
  ASSERT_EQ(report.methods.size(), 2u);
  EXPECT_EQ(report.methods[0].note, "");
  EXPECT_EQ(report.methods[1].note, "non-adhesive: ignores adhesion");
  const MethodCurve& sticky = report.methods[0].curve;
  const MethodCurve& plain = report.methods[1].curve;
  EXPECT_NE(sticky.parameters.find("adhesion dugdale w 1 J/m^2 sigma0 1e+08 Pa"), std::string::npos)
      << sticky.parameters;
  const auto column = [&](const std::string& name) {
    for (const auto& [key, values] : sticky.columns)
      if (key == name) return values;
    ADD_FAILURE() << "no column " << name;
    return std::vector<Real>{};
  };
  const std::vector<Real> pull = column("adhesive_load"), zone = column("attractive_fraction");
  ASSERT_EQ(pull.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_GT(sticky.area_fraction[k], plain.area_fraction[k]) << "load " << k;
    // The pull is σ0 over the contact and the zone at most: (A/A0 + zone) σ0 / E*, up to the node count.
    EXPECT_GT(pull[k], 0);
    EXPECT_LE(pull[k], (sticky.area_fraction_nodes[k] + zone[k]) * 1e8 / (100e9 / (1 - 0.09)) * (1 + 1e-12));
    EXPECT_TRUE(sticky.converged[k]);
  }
}

// A plateau method keeps its sweep level by level only when asked (write_levels = true: with exact levels
// it is a row per distinct height), and the scene as understood says so only then, so that every scene
// without the key reads and writes as before.
TEST(SceneRun, APlateauKeepsItsLevelsOnlyWhenAsked) {
  const std::string methods = R"(
[methods.quiet]
method = "plateau"
[methods.kept]
method = "plateau_hertz"
levels = 10
write_levels = true
)";
  const Scene scene = parse_scene("name = \"levels\"\n" + kSmallSurface + methods, "test.toml");
  const std::string written = to_toml(scene);
  EXPECT_EQ(written.find("write_levels"), written.rfind("write_levels")) << written;  // once: kept's
  EXPECT_NE(written.find("write_levels = true"), std::string::npos) << written;
  const SceneReport report =
      run_scene(parse_scene(written, "test.toml"), {.threads = 1, .observer = nullptr});
  EXPECT_FALSE(report.methods[0].curve.levels.has_value());
  ASSERT_TRUE(report.methods[1].curve.levels.has_value());
  EXPECT_EQ(report.methods[1].curve.levels->z.size(), 11u);  // 10 equal steps, both ends
}

// With extrapolate = true a load is converged only when both of its solves are: a finer solve that did not
// converge marks the load in the typed field and in the BEM's own column alike. The stage's products are
// made by hand, as no small grid makes one solve converge and the other not.
TEST(SceneRun, ABemLoadConvergedOnlyWhenBothOfItsSolvesDid) {
  const Scene scene = parse_scene(
      "name = \"fine\"\n" + kSmallSurface + "[methods.bem]\nextrapolate = true\nerror_estimate = \"gci2\"\n",
      "test.toml");
  const Surface surface = make_surface(scene.surface, 1);
  BemProducts products;
  products.points = 32 * 32;
  products.fine_points = 64 * 64;
  for (const bool fine_converged : {true, false}) {
    ContactSolution coarse, fine;
    coarse.converged = true;
    fine.converged = fine_converged;
    products.solutions.push_back(coarse);
    products.fine_solutions.push_back(fine);
    products.statistics[4].push_back({.area_fraction = 0.02, .area_fraction_corrected = 0.015});
    products.fine_statistics[4].push_back({.area_fraction = 0.018, .area_fraction_corrected = 0.015});
  }
  const SpectralMoments moments{};  // the BEM reads none
  const MethodCurve curve = scene.methods[0].method->evaluate({.scene = scene,
                                                               .surface = SceneSurface(surface),
                                                               .moments = moments,
                                                               .sweep = nullptr,
                                                               .bem = &products});
  EXPECT_EQ(curve.converged, (std::vector<bool>{true, false}));
  EXPECT_EQ(unconverged_loads(curve), (std::vector<std::size_t>{1}));
  for (const auto& [name, values] : curve.columns)
    if (name == "converged") {
      EXPECT_EQ(values, (std::vector<Real>{1, 0}));
    }
  // Its own error bar, the two-grid GCI (bem/grid_convergence.hpp): 3 |0.018 - 0.02|, to rounding.
  EXPECT_NEAR(curve.area_fraction_error[0], 0.006, 1e-15);
}

// The shipped paper scenes at 32 x 32 (BEM at 64 x 64): every method answers at every load (the
// Hertz-consistent variant up to the load it names), the reference's
// error is zero, and the three files hold what they promise. Tolerances: none needed, these are structural.
void expect_complete_run(const std::string& text, const std::filesystem::path& folder) {
  const Scene scene = parse_scene(text, kSource / "scenes" / "paper" / "scene.toml");
  const SceneReport report = run_scene(scene, {.threads = 2, .observer = nullptr});
  EXPECT_TRUE(ran(report, "bem"));
  EXPECT_TRUE(ran(report, "sweep"));
  const Comparison comparison = compare(report);
  ASSERT_EQ(comparison.methods.size(), scene.methods.size());
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& r = report.methods[m];
    ASSERT_EQ(r.curve.area_fraction.size(), scene.loads.size()) << r.label;
    // The Hertz-consistent variant has no answer above sqrt(2) x the paper model's full-contact load
    // (docs/theory.md section 8.3), reached on a 32 x 32 grid at the largest loads; it names that load.
    const bool may_stop_early =
        r.curve.parameters.find("no answer (NaN) for loads above") != std::string::npos;
    EXPECT_TRUE(std::isfinite(r.curve.area_fraction.front())) << r.label << " at the smallest load";
    for (std::size_t k = 0; k < scene.loads.size(); ++k) {
      if (may_stop_early && !std::isfinite(r.curve.area_fraction[k])) continue;
      EXPECT_TRUE(std::isfinite(r.curve.area_fraction[k])) << r.label << " at load " << k;
      EXPECT_TRUE(std::isfinite(comparison.methods[m].relative_error[k])) << r.label << " at load " << k;
    }
    if (r.label == scene.reference) {
      EXPECT_EQ(comparison.methods[m].max_abs_relative_error, 0);
    }
    EXPECT_GT(comparison.methods[m].kappa, 0) << r.label;
  }
  const Provenance provenance = current_provenance(2, "test");
  write_report(folder, report, comparison, provenance);
  const std::string csv = slurp(folder / "curves.csv");
  EXPECT_NE(csv.find("method,separation,load,area_fraction,spots"), std::string::npos);
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')),
            3 + scene.methods.size() * (1 + scene.loads.size()));  // two comments, one per method, the header
  const std::string json = slurp(folder / "summary.json");
  for (const char* key : {"\"stages\"", "\"provenance\"", "\"commit\"", "\"kappa\"", "\"relative_error\"",
                          "\"scene_as_understood\"", "\"machine\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  const std::string table = slurp(folder / "table.md");
  for (const MethodSpec& method : scene.methods)
    EXPECT_NE(table.find("| " + method.label + " |"), std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST(ShippedScenes, SurfaceARunsEndToEndOnASmallGrid) {
  expect_complete_run(small_paper_scene("surface_A.toml"),
                      std::filesystem::temp_directory_path() / "contactbench_scene_surface_A");
}

TEST(ShippedScenes, SurfaceBRunsEndToEndOnASmallGrid) {
  expect_complete_run(small_paper_scene("surface_B.toml"),
                      std::filesystem::temp_directory_path() / "contactbench_scene_surface_B");
}

// The measured scene on a 48 x 48 corner of its file (written in the project's format), so that its
// non-periodic BEM stays fast; everything else as shipped.
TEST(ShippedScenes, MeasuredRunsEndToEndOnACorner) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "contactbench_scene_measured";
  std::filesystem::create_directories(folder);
  const Surface full = read_topography(std::filesystem::path(CB_DATA_DIR "/measured") / "matrix-2.txt");
  const Index n = 48;
  const Grid corner{
      .nx = n, .ny = n, .lx = full.grid().dx() * n, .ly = full.grid().dy() * n, .periodic = false};
  write_surface(folder / "corner.txt", Surface(corner, full.heights().topLeftCorner(n, n)));
  const std::string text = replace_all(slurp(kSource / "scenes" / "paper" / "measured.toml"),
                                       "../../data/measured/matrix-2.txt", (folder / "corner.txt").string());
  expect_complete_run(text, folder / "out");
  std::filesystem::remove_all(folder);
}

// Heights from the mean plane (docs/theory.md section 0): a file's heights carry an arbitrary offset (an
// instrument's zero), which the scene removes, so every method's separation is measured from the same plane.
// The same surface written with and without an offset of 1 mm (5000 times its height range) must give the
// same separations; without the centring the plateau model's would differ by the offset. Tolerance 1e-6 of
// the height range: the two problems differ by the offset's round-off (2e-19 m against heights of 1e-7 m),
// and two BEM solves stopped at a relative change of 1e-10 agree far better than that; the offset is 5e9
// times larger.
TEST(SceneRun, FileSurfacesAreMeasuredFromTheirMeanPlane) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "contactbench_scene_offset";
  std::filesystem::create_directories(folder);
  const Grid grid{.nx = 16, .ny = 16, .lx = 16e-6, .ly = 16e-6, .periodic = false};
  HeightMap h(16, 16);
  for (Index iy = 0; iy < 16; ++iy)
    for (Index ix = 0; ix < 16; ++ix)
      h(iy, ix) = 1e-7 * std::sin(0.7 * ix + 1.3 * iy) * std::cos(0.4 * ix - 0.9 * iy);
  const Real range = h.maxCoeff() - h.minCoeff();
  write_surface(folder / "plain.txt", Surface(grid, h));
  write_surface(folder / "offset.txt", Surface(grid, h + 1e-3));
  auto run_file = [&](const std::string& name) {
    return run_scene_text(R"(name = "offset"
[surface]
file = ")" + (folder / name).string() +
                          R"("
[material]
estar = 1e11
[loads]
values = [1e-3, 1e-2]
[methods.bem]
tolerance = 1e-10
[methods.plateau]
method = "plateau"
)");
  };
  const SceneReport plain = run_file("plain.txt"), offset = run_file("offset.txt");
  ASSERT_EQ(plain.methods.size(), 2u);
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t k = 0; k < 2; ++k) {
      const Real z = plain.methods[m].curve.separation[k];
      ASSERT_TRUE(std::isfinite(z)) << plain.methods[m].label;
      EXPECT_NEAR(offset.methods[m].curve.separation[k], z, 1e-6 * range) << plain.methods[m].label;
    }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace contactbench

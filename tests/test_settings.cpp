// Each setting declared once (app/settings.hpp): the BEM method's keys (app/methods/bem_settings.cpp) are
// what the scene reads and writes, what `contactbench bem` flags, what the MPI broadcast carries and refuses,
// and what scenes/README.md documents. Structural checks: no tolerance is involved.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/app/methods/bem_settings.hpp"
#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/setting_flags.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

std::string slurp_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The rows of the table that follows `heading` in the file, up to the first line that is not a row.
std::vector<std::string> table_after(const std::string& text, const std::string& heading) {
  std::vector<std::string> rows;
  const auto at = text.find(heading);
  if (at == std::string::npos) return rows;
  std::istringstream lines(text.substr(at));
  std::string line;
  bool in_table = false;
  while (std::getline(lines, line)) {
    const bool row = line.rfind("| `", 0) == 0;
    if (row) rows.push_back(line);
    if (in_table && !row && line.rfind("|", 0) != 0) break;
    in_table = in_table || line.rfind("|", 0) == 0;
  }
  return rows;
}

// The docs' key table is the declaration's, row for row: a key added, removed or changed in one and not the
// other fails here, with the rows the declaration makes.
TEST(Settings, TheScenesKeyTableOfTheBemIsTheDeclarations) {
  const std::vector<std::string> documented =
      table_after(slurp_file(CB_SOURCE_DIR "/scenes/README.md"), "`bem` (Polonsky");
  std::vector<std::string> declared;
  for (const Setting<BemSettings>& row : bem_settings())
    declared.push_back(markdown_row(row));
  std::string expected;
  for (const std::string& row : declared)
    expected += row + "\n";
  EXPECT_EQ(documented, declared) << "scenes/README.md's table of the bem keys should read:\n" << expected;
}

TEST(Settings, DefaultsAreTheRowsDefaultsAndScopeDecidesWhatASolveShares) {
  const BemSettings defaults = default_settings(bem_settings());
  EXPECT_EQ(defaults.solver.tolerance, kDefaultTolerance);
  EXPECT_EQ(defaults.solver.max_iterations, 20000);
  EXPECT_EQ(defaults.solver.solver, kDefaultSolver);
  EXPECT_EQ(defaults.connectivity, 4);
  EXPECT_FALSE(defaults.periodic.has_value());
  BemSettings spots = defaults;
  spots.connectivity = 8;  // read from the same solve's contact maps
  EXPECT_TRUE(same_settings(bem_settings(), SettingScope::solve, defaults, spots));
  EXPECT_FALSE(same_settings(bem_settings(), SettingScope::method, defaults, spots));
  BemSettings tighter = defaults;
  tighter.solver.tolerance = 1e-10;
  EXPECT_FALSE(same_settings(bem_settings(), SettingScope::solve, defaults, tighter));
}

TEST(Settings, TheDistributedPackingCarriesEverySolveSettingItTakesAndRefusesTheRest) {
  BemSettings settings = default_settings(bem_settings());
  settings.solver.tolerance = 3e-9;
  settings.solver.max_iterations = 77;
  settings.solver.solver = SolverKind::preconditioned_cg;
  settings.extrapolate = true;
  std::vector<double> packed;
  pack_settings(bem_settings(), settings, packed);
  BemSettings unpacked;  // as another rank starts: nothing but the struct's own initialisers
  std::size_t next = 0;
  unpack_settings(bem_settings(), packed, next, unpacked);
  EXPECT_EQ(next, packed.size());
  EXPECT_EQ(unpacked.solver.tolerance, 3e-9);
  EXPECT_EQ(unpacked.solver.max_iterations, 77);
  EXPECT_EQ(unpacked.solver.solver, SolverKind::preconditioned_cg);
  EXPECT_TRUE(undistributed_settings(bem_settings(), settings, default_settings(bem_settings())).empty());
  settings.solver.solver = SolverKind::active_set;  // the default solver: distributed too
  EXPECT_TRUE(undistributed_settings(bem_settings(), settings, default_settings(bem_settings())).empty());
  settings.solver.single_precision = true;
  settings.solver.load_path = LoadPathStart::extrapolated;
  EXPECT_EQ(undistributed_settings(bem_settings(), settings, default_settings(bem_settings())),
            (std::vector<std::string>{"precision = \"single\"", "load_path = \"extrapolated\""}));
}

// The command's flags become the scene's keys: the given ones only, typed as their rows say.
TEST(Settings, FlagsBecomeTheSceneKeysTheyName) {
  std::vector<SettingSpec> specs;
  for (const Setting<BemSettings>& row : bem_settings())
    specs.push_back(spec_of(row));
  SettingFlags flags(specs);
  CLI::App app;
  flags.add_to(app);
  app.parse("--solver polonsky_keer --float --max-iterations 9 --tolerance 1e-5", false);
  toml::table table;
  flags.insert_into(table);
  EXPECT_EQ(table["tolerance"].value<double>(), 1e-5);
  EXPECT_EQ(table["max_iterations"].value<std::int64_t>(), 9);
  EXPECT_EQ(table["precision"].value<std::string>(), "single");
  EXPECT_EQ(table["solver"].value<std::string>(), "polonsky_keer");
  EXPECT_FALSE(table.contains("periodic")) << "a switch not given sets nothing";
  EXPECT_EQ(flags.command_text(), " --tolerance 1e-5 --max-iterations 9 --float --solver polonsky_keer");
  FlagNames names;
  flags.name_flags("methods.bem.", names);
  EXPECT_EQ(names.at("methods.bem.precision"), "--float");
}

// A scene's keys read and written back through the declaration: the same values, and a value out of a row's
// range is a problem naming the key and the range.
TEST(Settings, ASceneReadsAndWritesEveryKeyThroughTheDeclaration) {
  const Scene scene = parse_scene("name = \"s\"\n" + kSmallSurfaceAndMaterial +
                                      "[loads]\nvalues = [1e-3]\n[methods.bem]\ntolerance = 1e-9\n"
                                      "max_iterations = 50\nsolver = \"polonsky_keer\"\nconnectivity = 8\n",
                                  "s.toml");
  const std::string toml = to_toml(scene);
  for (const char* line : {"tolerance = 1e-09", "max_iterations = 50", "solver = \"polonsky_keer\"",
                           "connectivity = 8", "precision = \"double\"", "area = \"corrected\""})
    EXPECT_NE(toml.find(line), std::string::npos) << line << " in\n" << toml;
  EXPECT_EQ(to_toml(parse_scene(toml, "again.toml")), toml);
  // A key added by one row (load_path) reaches the solver's options.
  const Scene extrapolated =
      parse_scene("name = \"s\"\n" + kSmallSurfaceAndMaterial +
                      "[loads]\nvalues = [1e-3]\n[methods.bem]\nload_path = \"extrapolated\"\n",
                  "s.toml");
  const MethodNeeds needs = extrapolated.methods[0].method->needs({});
  ASSERT_TRUE(needs.bem.has_value());
  EXPECT_EQ(needs.bem->settings.solver.load_path, LoadPathStart::extrapolated);
}

}  // namespace
}  // namespace contactbench

// Scene files: a full scene round-trips through to_toml, defaults are filled in, relative paths resolve
// against the scene's folder, and every kind of invalid input is reported with its key path and reason,
// all problems of a scene in one error.
#include "contactbench/app/scene.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/methods/registry.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/core/material.hpp"
#include "test_folder.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

const fs::path measured_folder{CB_DATA_DIR "/measured"};

// A valid scene in blocks; each test replaces the block it is about.
struct Blocks {
  std::string head = "name = \"test\"\n";
  std::string surface =
      "[surface]\ngenerate = { sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, size = 200e-6, grid = 64, seed = 1 "
      "}\n";
  std::string material = "[material]\nE = 100e9\nnu = 0.3\n";
  std::string loads = "[loads]\nvalues = [1e-3, 1e-4]\n";
  std::string methods = "[methods.bem]\n[methods.persson]\n";
  std::string text() const { return head + surface + material + loads + methods; }
};

// A full scene: every section, most options given.
const std::string full_scene = R"(name = "surface_A.v2"
description = "The paper's surface A: all methods against the BEM"
reference = "bem_fine"

[surface]
generate = { sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, qs = 3e6, size = 200e-6, grid = 256, seed = 7, refine = 512, anisotropy = 2 }

[material]
E = 100e9
nu = 0.3
E2 = 200e9
nu2 = 0.25

[interface]
hardness = 5e9

[loads]
range = { from = 1e-4, to = 1e-2, count = 5, spacing = "log" }

[methods.bem_fine]
method = "bem"
refine = 1024
tolerance = 1e-9
max_iterations = 5000
periodic = true
connectivity = 8
solver = "polonsky_keer"

[methods.plateau_4]
method = "plateau"
connectivity = 4
levels = "paper"
periodic = false

[methods.plateau]
levels = 100

[methods.gw_mccool]
[methods.bgt]
[methods.bgt_linear]
[methods.persson]
)";

// A method's keys as it writes them back (its options, defaults filled in).
SceneKeys keys_of(const MethodSpec& method) {
  SceneKeys keys;
  method.method->write(keys);
  return keys;
}

// The value of one written key; a test failure when absent.
SceneKeys::Value key(const MethodSpec& method, const std::string& name) {
  for (const auto& [k, value] : keys_of(method).values)
    if (k == name) return value;
  ADD_FAILURE() << method.label << " wrote no key " << name;
  return SceneKeys::Value{std::string("<absent>")};
}

bool has_key(const MethodSpec& method, const std::string& name) {
  for (const auto& entry : keys_of(method).values)
    if (entry.first == name) return true;
  return false;
}

using Value = SceneKeys::Value;

void expect_same(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.reference, b.reference);
  ASSERT_EQ(a.surface.source.index(), b.surface.source.index());
  if (const auto* ga = std::get_if<GeneratedSurfaceSpec>(&a.surface.source)) {
    const auto& gb = std::get<GeneratedSurfaceSpec>(b.surface.source);
    EXPECT_EQ(ga->sigma, gb.sigma);
    EXPECT_EQ(ga->hurst, gb.hurst);
    EXPECT_EQ(ga->qr, gb.qr);
    EXPECT_EQ(ga->qs, gb.qs);
    EXPECT_EQ(ga->size, gb.size);
    EXPECT_EQ(ga->grid, gb.grid);
    EXPECT_EQ(ga->seed, gb.seed);
    EXPECT_EQ(ga->refine, gb.refine);
    EXPECT_EQ(ga->anisotropy, gb.anisotropy);
  } else {
    const auto& fa = std::get<FileSurfaceSpec>(a.surface.source);
    const auto& fb = std::get<FileSurfaceSpec>(b.surface.source);
    EXPECT_EQ(fa.path, fb.path);
    EXPECT_EQ(fa.size_x, fb.size_x);
    EXPECT_EQ(fa.size_y, fb.size_y);
    EXPECT_EQ(fa.periodic, fb.periodic);
  }
  EXPECT_EQ(a.material.estar, b.material.estar);
  EXPECT_EQ(a.material.youngs_modulus, b.material.youngs_modulus);
  EXPECT_EQ(a.material.poisson_ratio, b.material.poisson_ratio);
  EXPECT_EQ(a.material.youngs_modulus_2, b.material.youngs_modulus_2);
  EXPECT_EQ(a.material.poisson_ratio_2, b.material.poisson_ratio_2);
  EXPECT_EQ(a.loads, b.loads);
  ASSERT_EQ(a.methods.size(), b.methods.size());
  for (std::size_t i = 0; i < a.methods.size(); ++i) {
    const auto &ma = a.methods[i], &mb = b.methods[i];
    EXPECT_EQ(ma.label, mb.label);
    EXPECT_EQ(ma.name(), mb.name());
    EXPECT_EQ(keys_of(ma).values, keys_of(mb).values) << ma.label;
  }
}

// The problems parse_scene reports for `text` (empty when it accepts the scene).
std::vector<std::string> problems_of(const std::string& text, const fs::path& origin = "scene.toml") {
  try {
    parse_scene(text, origin);
  } catch (const SceneError& error) {
    const std::string message = error.what();
    for (const auto& problem : error.problems())
      EXPECT_NE(message.find(problem), std::string::npos) << "the message must list every problem";
    return error.problems();
  }
  return {};
}

// One of the problems reads "<origin>[:line]: <path>: ...<reason>..." (and `accepted` after "accepted: ").
void expect_problem(const std::string& text, std::string_view path, std::string_view reason,
                    std::string_view accepted = {}, const fs::path& origin = "scene.toml") {
  const auto problems = problems_of(text, origin);
  ASSERT_FALSE(problems.empty()) << "accepted without error:\n" << text;
  for (const auto& problem : problems) {
    const auto at = problem.find(": " + std::string(path) + ": ");
    if (!problem.starts_with(origin.string()) || at == std::string::npos) continue;
    if (problem.find(reason, at) == std::string::npos) continue;
    if (!accepted.empty()) {
      const auto list = problem.find("; accepted: ", at);
      ASSERT_NE(list, std::string::npos) << problem;
      EXPECT_NE(problem.find(accepted, list), std::string::npos)
          << "expected '" << accepted << "' in: " << problem;
    }
    return;
  }
  std::string all;
  for (const auto& problem : problems)
    all += problem + "\n";
  ADD_FAILURE() << "no problem '" << path << ": ... " << reason << "' among:\n" << all;
}

std::string with_generate(std::string_view extra_or_changed) {
  return "[surface]\ngenerate = { " + std::string(extra_or_changed) + " }\n";
}
const std::string generate_fields =
    "sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, size = 200e-6, grid = 64, seed = 1";

// A minimal JSON checker (RFC 8259 grammar, without the finer points of number and escape syntax).
class JsonChecker {
 public:
  explicit JsonChecker(std::string_view text) : text_(text) {}
  bool valid() {
    skip();
    if (!value()) return false;
    skip();
    return pos_ == text_.size();
  }

 private:
  void skip() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool eat(char c) {
    skip();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  bool literal(std::string_view word) {
    if (text_.substr(pos_, word.size()) != word) return false;
    pos_ += word.size();
    return true;
  }
  bool string() {
    if (!eat('"')) return false;
    while (pos_ < text_.size() && text_[pos_] != '"')
      pos_ += text_[pos_] == '\\' ? 2 : 1;
    return eat('"');
  }
  bool number() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           std::string_view("+-0123456789.eE").find(text_[pos_]) != std::string_view::npos)
      ++pos_;
    return pos_ > start;
  }
  bool value() {
    skip();
    if (pos_ >= text_.size()) return false;
    const char c = text_[pos_];
    if (c == '{') return sequence('{', '}', true);
    if (c == '[') return sequence('[', ']', false);
    if (c == '"') return string();
    if (c == 't') return literal("true");
    if (c == 'f') return literal("false");
    if (c == 'n') return literal("null");
    return number();
  }
  bool sequence(char open, char close, bool object) {
    eat(open);
    if (eat(close)) return true;
    do {
      if (object && !(string() && eat(':'))) return false;
      if (!value()) return false;
    } while (eat(','));
    return eat(close);
  }
  std::string_view text_;
  std::size_t pos_ = 0;
};

// Each test that writes files gets a fresh folder of its own.
class SceneFiles : public testing::FolderTest {
 protected:
  SceneFiles() : FolderTest("contactbench_test_scene_") {}
};

TEST(Scene, FullSceneRoundTrips) {
  const Scene first = parse_scene(full_scene, "scene.toml");
  const std::string written = to_toml(first);
  const Scene second = parse_scene(written, "elsewhere/again.toml");
  expect_same(first, second);
  EXPECT_EQ(to_toml(second), written) << "to_toml must be a fixed point";

  // What was read, field by field.
  EXPECT_EQ(first.name, "surface_A.v2");
  EXPECT_EQ(first.reference, "bem_fine");
  const auto& g = std::get<GeneratedSurfaceSpec>(first.surface.source);
  EXPECT_EQ(g.qs, 3e6);
  EXPECT_EQ(g.grid, 256);
  EXPECT_EQ(g.seed, 7u);
  EXPECT_EQ(g.refine, 512);
  EXPECT_EQ(g.anisotropy, 2.0);
  EXPECT_TRUE(first.material.two_bodies());
  EXPECT_EQ(first.material.estar, composite_modulus(100e9, 0.3, 200e9, 0.25));
  ASSERT_EQ(first.loads.size(), 5u);
  EXPECT_EQ(first.loads.front(), 1e-4);
  EXPECT_EQ(first.loads.back(), 1e-2);
  EXPECT_NEAR(first.loads[2], 1e-3, 1e-15);  // log spacing: the geometric mean in the middle
  // Methods keep the file's order, not the alphabetical order of a TOML table.
  std::vector<std::string> labels;
  for (const auto& m : first.methods)
    labels.push_back(m.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"bem_fine", "plateau_4", "plateau", "gw_mccool", "bgt",
                                              "bgt_linear", "persson"}));
  const MethodSpec& bem = first.method("bem_fine");
  EXPECT_EQ(key(bem, "refine"), Value{std::int64_t{1024}});
  EXPECT_EQ(key(bem, "tolerance"), Value{1e-9});
  EXPECT_EQ(key(bem, "max_iterations"), Value{std::int64_t{5000}});
  EXPECT_EQ(key(bem, "periodic"), Value{true});
  EXPECT_EQ(first.interface.hardness, 5e9);
  EXPECT_FALSE(has_key(bem, "hardness")) << "an effect of the interface, not a key of the method";
  EXPECT_EQ(key(bem, "connectivity"), Value{std::int64_t{8}});
  EXPECT_EQ(key(bem, "solver"), Value{std::string("polonsky_keer")});
  const MethodSpec& paper = first.method("plateau_4");
  EXPECT_EQ(key(paper, "levels"), Value{std::string("paper")});
  EXPECT_EQ(paper.method->needs({}).sweep->levels.count, 500);
  EXPECT_EQ(key(paper, "periodic"), Value{false});
  const MethodSpec& uniform = first.method("plateau");
  EXPECT_EQ(key(uniform, "levels"), Value{std::int64_t{100}});
  EXPECT_EQ(uniform.method->needs({}).sweep->levels.kind, SweepLevels::Kind::uniform);
  EXPECT_EQ(first.method("bgt_linear").name(), "bgt_linear");
  EXPECT_EQ(key(first.method("persson"), "anisotropy"), Value{std::string("refuse")});
}

TEST(Scene, DefaultsAreFilledIn) {
  Blocks b;
  b.loads = "[loads]\nvalues = [1e-3, 1e-4, 1e-3, 2e-3]\n";
  b.methods = "[methods.bem]\n[methods.sweep]\nmethod = \"plateau\"\n";
  const Scene scene = parse_scene(b.text(), "scene.toml");
  EXPECT_EQ(scene.description, "");
  EXPECT_EQ(scene.file, fs::path());
  EXPECT_EQ(scene.reference, "bem") << "the only BEM is the default reference";
  const auto& g = std::get<GeneratedSurfaceSpec>(scene.surface.source);
  EXPECT_EQ(g.qs, std::numbers::pi / (200e-6 / 64)) << "qs defaults to the grid's Nyquist wavevector";
  EXPECT_EQ(g.refine, 0);
  EXPECT_EQ(g.anisotropy, 1.0);
  EXPECT_EQ(scene.material.estar, contact_modulus(100e9, 0.3));
  EXPECT_FALSE(scene.material.two_bodies());
  EXPECT_EQ(scene.loads, (std::vector<Real>{1e-4, 1e-3, 2e-3})) << "sorted ascending, duplicates removed";
  const MethodSpec& bem = scene.method("bem");
  EXPECT_EQ(key(bem, "refine"), Value{std::int64_t{0}});
  EXPECT_EQ(key(bem, "tolerance"), Value{1e-8});
  EXPECT_EQ(key(bem, "max_iterations"), Value{std::int64_t{20000}});
  EXPECT_FALSE(has_key(bem, "periodic")) << "default: the surface's own periodicity";
  EXPECT_FALSE(has_key(bem, "hardness"));
  EXPECT_EQ(key(bem, "precision"), Value{std::string("double")});
  EXPECT_EQ(key(bem, "connectivity"), Value{std::int64_t{4}});
  EXPECT_EQ(key(bem, "solver"), Value{std::string(solver_name(kDefaultSolver))});
  const MethodSpec& plateau = scene.method("sweep");
  EXPECT_EQ(plateau.name(), "plateau");
  EXPECT_EQ(key(plateau, "connectivity"), Value{std::int64_t{4}});
  EXPECT_EQ(key(plateau, "levels"), Value{std::string("exact")});
  EXPECT_FALSE(has_key(plateau, "periodic"));
}

TEST(Scene, ReferenceDefaultsToNoneUnlessExactlyOneBem) {
  Blocks b;
  b.methods = "[methods.persson]\n[methods.bgt]\n";
  EXPECT_EQ(parse_scene(b.text(), "s.toml").reference, "");
  b.methods = "[methods.bem]\n[methods.bem_fine]\nmethod = \"bem\"\nrefine = 128\n";
  EXPECT_EQ(parse_scene(b.text(), "s.toml").reference, "");
  b.head += "reference = \"bem_fine\"\n";
  EXPECT_EQ(parse_scene(b.text(), "s.toml").reference, "bem_fine");
}

TEST(Scene, ElasticModulusAloneAndIntegersWhereFloatsAreExpected) {
  Blocks b;
  b.material = "[material]\nestar = 110000000000\n";
  b.surface = with_generate("sigma = 0.5e-6, hurst = 1, qr = 31400, size = 200e-6, grid = 64, seed = 0");
  const Scene scene = parse_scene(b.text(), "s.toml");
  EXPECT_EQ(scene.material.estar, 1.1e11);
  EXPECT_FALSE(scene.material.youngs_modulus.has_value());
  const auto& g = std::get<GeneratedSurfaceSpec>(scene.surface.source);
  EXPECT_EQ(g.qr, 31400.0);
  EXPECT_EQ(g.hurst, 1.0) << "H = 1 is inside (0, 1]";
  expect_same(scene, parse_scene(to_toml(scene), "s.toml"));
}

TEST(Scene, LinearRangeOfLoads) {
  Blocks b;
  b.loads = "[loads]\nrange = { from = 1, to = 3, count = 5, spacing = \"linear\" }\n";
  EXPECT_EQ(parse_scene(b.text(), "s.toml").loads, (std::vector<Real>{1, 1.5, 2, 2.5, 3}));
  b.loads = "[loads]\nrange = { from = 1e-3, to = 1e-2, count = 1 }\n";
  EXPECT_EQ(parse_scene(b.text(), "s.toml").loads, (std::vector<Real>{1e-3}));
}

TEST(Scene, RelativeFilePathResolvesAgainstTheScenesFolder) {
  Blocks b;
  b.surface = "[surface]\nfile = \"matrix-2.txt\"\n";
  const Scene scene = parse_scene(b.text(), measured_folder / "scene.toml");
  const auto& f = std::get<FileSurfaceSpec>(scene.surface.source);
  EXPECT_EQ(f.path, fs::absolute(measured_folder / "matrix-2.txt").lexically_normal());
  EXPECT_TRUE(f.path.is_absolute());
  EXPECT_FALSE(f.size_x.has_value()) << "the interferometer export carries its size";
  EXPECT_FALSE(f.periodic.has_value()) << "absent: the file's own periodicity";
  EXPECT_EQ(scene.reference, "bem");

  // The written scene names the resolved path, so it reads back the same from any folder.
  expect_same(scene, parse_scene(to_toml(scene), "/somewhere/else/scene.toml"));
}

TEST_F(SceneFiles, ReadSceneResolvesAgainstTheFilesFolder) {
  const fs::path relative = fs::relative(measured_folder / "matrix-3.txt", folder_);
  Blocks b;
  b.surface =
      "[surface]\nfile = \"" + relative.generic_string() + "\"\nsize = [10e-6, 10e-6]\nperiodic = true\n";
  const fs::path path = write("scene.toml", b.text());
  const Scene scene = read_scene(path);
  EXPECT_EQ(scene.file, path);
  const auto& f = std::get<FileSurfaceSpec>(scene.surface.source);
  EXPECT_EQ(fs::canonical(f.path), fs::canonical(measured_folder / "matrix-3.txt"));
  EXPECT_EQ(f.size_x, 10e-6);
  EXPECT_EQ(f.size_y, 10e-6);
  EXPECT_EQ(f.periodic, true);
  expect_same(scene, parse_scene(to_toml(scene), "x.toml"));
}

TEST_F(SceneFiles, ReadSceneOfAMissingFile) {
  try {
    read_scene(folder_ / "absent.toml");
    ADD_FAILURE() << "read without error";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("cannot open the scene file"), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find((folder_ / "absent.toml").string()), std::string::npos);
  }
}

TEST_F(SceneFiles, PlainMatrixNeedsASize) {
  write("heights.txt", "0 1e-6 2e-6\n1e-6 0 -1e-6\n-2e-6 1e-6 0\n");
  Blocks b;
  b.surface = "[surface]\nfile = \"heights.txt\"\n";
  const fs::path origin = folder_ / "scene.toml";
  expect_problem(b.text(), "surface.size", "missing required key", "plain matrix", origin);
  b.surface += "size = 3e-6\n";
  const Scene scene = parse_scene(b.text(), origin);
  EXPECT_EQ(std::get<FileSurfaceSpec>(scene.surface.source).size_x, 3e-6);
  EXPECT_FALSE(std::get<FileSurfaceSpec>(scene.surface.source).size_y.has_value()) << "square pixels";
}

TEST_F(SceneFiles, MissingSurfaceFileNamesTheResolvedPath) {
  Blocks b;
  b.surface = "[surface]\nfile = \"data/absent.txt\"\n";
  const fs::path origin = folder_ / "scene.toml";
  expect_problem(b.text(), "surface.file", "no such file: " + (folder_ / "data/absent.txt").string(), {},
                 origin);
}

TEST_F(SceneFiles, UnreadableTopographyIsReported) {
  write("empty.txt", "");
  Blocks b;
  b.surface = "[surface]\nfile = \"empty.txt\"\nsize = 1e-6\n";
  const auto problems = problems_of(b.text(), folder_ / "scene.toml");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("surface.file: "), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("empty.txt"), std::string::npos) << problems[0];
}

TEST(Scene, SyntaxErrorNamesLineAndColumn) {
  const auto problems = problems_of("name = \"x\"\n[surface\n");
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_TRUE(problems[0].starts_with("scene.toml:2:")) << problems[0];
  EXPECT_NE(problems[0].find("TOML syntax error"), std::string::npos) << problems[0];
}

TEST(Scene, ProblemsCarryTheLineOfTheKey) {
  Blocks b;
  b.methods = "[methods.bem]\nconnectivity = 4\ntolerance = 2\n";
  const auto problems = problems_of(b.text());
  ASSERT_EQ(problems.size(), 1u);
  // Lines: name 1, [surface] 2-3, [material] 4-6, [loads] 7-8, [methods.bem] 9, connectivity 10,
  // tolerance 11.
  EXPECT_TRUE(
      problems[0].starts_with("scene.toml:11: methods.bem.tolerance: out of range: got 2; accepted: "))
      << problems[0];
}

TEST(Scene, SeveralProblemsAreReportedTogether) {
  Blocks b;
  b.head = "name = \"bad name\"\ncolour = \"red\"\nreference = \"fem\"\n";
  b.surface = with_generate("sigma = -1, hurst = 2, qr = 3.14e4, size = 200e-6, grid = 64, seed = 1");
  b.material = "[material]\nE = 100e9\n";
  b.loads = "[loads]\nvalues = [0, 1e-3]\n";
  b.methods = "[methods.fast]\nmethod = \"fem\"\n";
  const auto problems = problems_of(b.text());
  const std::vector<std::string> expected = {
      "scene.toml:1: name: invalid name",     "scene.toml:2: colour: unknown key",
      "surface.generate.sigma: out of range", "surface.generate.hurst: out of range",
      "material.nu: missing required key",    "loads.values[0]: out of range",
      "methods.fast.method: unknown method",  "reference: no method labelled \"fem\""};
  EXPECT_EQ(problems.size(), expected.size());
  for (const auto& part : expected) {
    bool found = false;
    for (const auto& problem : problems)
      found = found || problem.find(part) != std::string::npos;
    EXPECT_TRUE(found) << "missing: " << part;
  }
}

TEST(Scene, ToJsonIsValidJsonWithTheDefaults) {
  const Scene scene = parse_scene(Blocks().text(), "scene.toml");
  const std::string json = to_json(scene);
  EXPECT_TRUE(JsonChecker(json).valid()) << json;
  EXPECT_FALSE(JsonChecker(json + "}").valid()) << "the checker must be able to fail";
  for (std::string_view part :
       {"\"name\": \"test\"", "\"reference\": \"bem\"", "\"tolerance\": 1e-08", "\"max_iterations\": 20000",
        "\"anisotropy\": 1\n", "\"estar\": 109890109890.1", "\"method\": \"persson\"", "\"qs\": 1005309.649",
        "\"values\": [1e-04, 0.001]"})
    EXPECT_NE(json.find(part), std::string::npos) << "expected '" << part << "' in:\n" << json;
}

TEST(Scene, MethodLookupAndNames) {
  const Scene scene = parse_scene(Blocks().text(), "scene.toml");
  EXPECT_EQ(scene.method("persson").name(), "persson");
  try {
    scene.method("fem");
    ADD_FAILURE() << "found a method that is not there";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("bem, persson"), std::string::npos) << error.what();
  }
  for (const std::string& name : MethodRegistry::global().names()) {
    Blocks b;
    b.methods = "[methods.m]\nmethod = \"" + name + "\"\n";
    EXPECT_EQ(parse_scene(b.text(), "s.toml").method("m").name(), name);
  }
}

// One invalid scene per kind of problem: the text differs from the valid Blocks() in one place.
struct InvalidCase {
  const char* test_name;
  std::string text;
  std::string path;      // the key path the problem names
  std::string reason;    // a part of its reason
  std::string accepted;  // a part of its accepted values ("" = not checked)
};

Blocks changed(std::string Blocks::*block, std::string text) {
  Blocks b;
  b.*block = std::move(text);
  return b;
}

// The generate fields with the one starting "<key> = " replaced by `with` (an empty `with` removes it).
std::string generate(const std::string& key, const std::string& with) {
  std::string fields = generate_fields;
  const auto at = fields.find(key + " = ");
  const auto end = fields.find(", ", at);
  fields.replace(at, end == std::string::npos ? std::string::npos : end - at + (with.empty() ? 2 : 0), with);
  return changed(&Blocks::surface, with_generate(fields)).text();
}
std::string generate_plus(const std::string& extra) {
  return changed(&Blocks::surface, with_generate(generate_fields + ", " + extra)).text();
}
std::string material(const std::string& text) {
  return changed(&Blocks::material, "[material]\n" + text).text();
}
std::string loads(const std::string& text) {
  return changed(&Blocks::loads, "[loads]\n" + text).text();
}
std::string methods(const std::string& text) {
  return changed(&Blocks::methods, text).text();
}
std::string bem(const std::string& option) {
  return methods("[methods.bem]\n" + option + "\n");
}
std::string plateau(const std::string& option) {
  return methods("[methods.p]\nmethod = \"plateau\"\n" + option + "\n");
}

const std::string kGenerate = "surface.generate.";

std::vector<InvalidCase> invalid_cases() {
  return {
      {"UnknownKeyAtTop", "colour = 1\n" + Blocks().text(), "colour", "unknown key",
       "name, description, reference"},
      {"UnknownKeyInGenerate", generate_plus("colour = 1"), kGenerate + "colour", "unknown key",
       "sigma, hurst"},
      {"UnknownKeyInBem", bem("colour = 1"), "methods.bem.colour", "unknown key", "tolerance"},
      {"OptionOfAnAnalyticTheory", methods("[methods.persson]\nrefine = 2\n"), "methods.persson.refine",
       "unknown key", "method"},
      {"UnknownAnisotropyChoice", methods("[methods.persson]\nanisotropy = \"ignore\"\n"),
       "methods.persson.anisotropy", "unknown choice \"ignore\"", "\"average\""},
      {"StringForANumber", generate("sigma", "sigma = \"big\""), kGenerate + "sigma",
       "wrong type: expected a number, got a string", "> 0"},
      {"FloatForAnInteger", generate("grid", "grid = 64.0"), kGenerate + "grid", "expected an integer",
       "[2, 65536]"},
      {"NumberForATable",
       [] {
         Blocks b;
         b.head += "material = 3\n";
         b.material = "";
         return b.text();
       }(),
       "material", "expected a table", ""},
      {"MissingName", changed(&Blocks::head, "").text(), "name", "missing required key", ""},
      {"MissingSigma", generate("sigma", ""), kGenerate + "sigma", "missing required key", "> 0"},
      {"MissingSurface", changed(&Blocks::surface, "").text(), "surface", "missing required key", ""},
      {"MissingMaterial", changed(&Blocks::material, "").text(), "material", "missing required key", "estar"},
      {"MissingLoads", changed(&Blocks::loads, "").text(), "loads", "missing required key", ""},
      {"NeitherGenerateNorFile", changed(&Blocks::surface, "[surface]\nperiodic = true\n").text(), "surface",
       "missing generate or file", ""},
      {"GenerateAndFile",
       changed(&Blocks::surface, with_generate(generate_fields) + "file = \"x.txt\"\n").text(),
       "surface.file", "mutually exclusive", ""},
      {"SizeWithGenerate", changed(&Blocks::surface, with_generate(generate_fields) + "size = 1e-3\n").text(),
       "surface.size", "only applies to file", ""},
      {"NegativeSigma", generate("sigma", "sigma = -0.5e-6"), kGenerate + "sigma", "out of range: got -5e-07",
       "> 0"},
      {"ZeroQr", generate("qr", "qr = 0"), kGenerate + "qr", "out of range", "> 0"},
      {"ZeroSize", generate("size", "size = 0"), kGenerate + "size", "out of range", "> 0"},
      {"HurstZero", generate("hurst", "hurst = 0"), kGenerate + "hurst", "out of range", "(0, 1]"},
      {"HurstAboveOne", generate("hurst", "hurst = 1.2"), kGenerate + "hurst", "out of range", "(0, 1]"},
      {"QsBelowQr", generate_plus("qs = 3e4"), kGenerate + "qs", "out of range", "> qr = 31400"},
      {"QsAboveNyquist", generate_plus("qs = 1e8"), "surface.generate", "qs must lie in", ""},
      {"GridOfOne", generate("grid", "grid = 1"), kGenerate + "grid", "out of range: got 1", "[2, 65536]"},
      {"GridTooLarge", generate("grid", "grid = 70000"), kGenerate + "grid", "out of range", "[2, 65536]"},
      {"RefineBelowGrid", generate_plus("refine = 32"), kGenerate + "refine", "out of range", "[64, 65536]"},
      {"NegativeSeed", generate("seed", "seed = -1"), kGenerate + "seed", "out of range", ""},
      {"ZeroAnisotropy", generate_plus("anisotropy = 0"), kGenerate + "anisotropy", "out of range", "> 0"},
      {"ZeroYoungsModulus", material("E = 0\nnu = 0.3\n"), "material.E", "out of range", "> 0"},
      {"PoissonRatioMinusOne", material("E = 1e9\nnu = -1\n"), "material.nu", "out of range", "(-1, 0.5)"},
      {"PoissonRatioHalf", material("E = 1e9\nnu = 0.5\n"), "material.nu", "out of range", "(-1, 0.5)"},
      {"NegativeEstar", material("estar = -1\n"), "material.estar", "out of range", "> 0"},
      {"EAndEstar", material("E = 1e9\nnu = 0.3\nestar = 1e9\n"), "material.estar", "E and estar both given",
       "estar alone"},
      {"EWithoutNu", material("E = 1e9\n"), "material.nu", "missing required key", "required with E"},
      {"NuWithoutE", material("nu = 0.3\nestar = 1e9\n"), "material.nu", "given without E", ""},
      {"NoElasticConstants", material(""), "material.E", "missing required key", "estar alone"},
      {"E2WithoutNu2", material("E = 1e9\nnu = 0.3\nE2 = 2e9\n"), "material.nu2", "missing required key",
       "required with E2"},
      {"SecondBodyWithEstar", material("estar = 1e9\nE2 = 2e9\nnu2 = 0.3\n"), "material.E2",
       "a second body needs E and nu", ""},
      {"NegativeLoad", loads("values = [1e-3, -1e-3]\n"), "loads.values[1]", "out of range: got -0.001",
       "> 0"},
      {"ZeroLoad", loads("values = [0]\n"), "loads.values[0]", "out of range", "> 0"},
      {"NanLoad", loads("values = [nan]\n"), "loads.values[0]", "out of range: got nan", "finite"},
      {"InfiniteLoad", loads("values = [inf]\n"), "loads.values[0]", "out of range: got inf", "finite"},
      {"StringLoad", loads("values = [\"1e-3\"]\n"), "loads.values[0]", "wrong type", ""},
      {"EmptyLoads", loads("values = []\n"), "loads.values", "empty array", ""},
      {"NoLoads", loads(""), "loads.values", "missing required key", "range"},
      {"ValuesAndRange", loads("values = [1e-3]\nrange = { from = 1e-4, to = 1e-2, count = 3 }\n"),
       "loads.range", "values and range both given", ""},
      {"RangeFromNotBelowTo", loads("range = { from = 1e-2, to = 1e-2, count = 3 }\n"), "loads.range.to",
       "must exceed from", ""},
      {"RangeCountZero", loads("range = { from = 1e-4, to = 1e-2, count = 0 }\n"), "loads.range.count",
       "out of range", "[1, "},
      {"RangeUnknownSpacing", loads("range = { from = 1e-4, to = 1e-2, count = 3, spacing = \"cubic\" }\n"),
       "loads.range.spacing", "unknown spacing", "\"log\", \"linear\""},
      {"RangeMissingTo", loads("range = { from = 1e-4, count = 3 }\n"), "loads.range.to",
       "missing required key", ""},
      // Tolerances outside [1e-13, 1e-2] mean nothing (app/methods/bem_method.cpp): 0, the 1e-20 double
      // cannot resolve, and 0.5 or 1, which stop far from the solution.
      {"ToleranceZero", bem("tolerance = 0"), "methods.bem.tolerance", "out of range", "[1e-13, 0.01]"},
      {"ToleranceTiny", bem("tolerance = 1e-20"), "methods.bem.tolerance", "out of range", "[1e-13, 0.01]"},
      {"ToleranceHalf", bem("tolerance = 0.5"), "methods.bem.tolerance", "out of range", "[1e-13, 0.01]"},
      {"ToleranceOne", bem("tolerance = 1"), "methods.bem.tolerance", "out of range", "[1e-13, 0.01]"},
      {"MaxIterationsZero", bem("max_iterations = 0"), "methods.bem.max_iterations", "out of range", "[1, "},
      {"HardnessZero", methods("[interface]\nhardness = 0\n[methods.bem]\n"), "interface.hardness",
       "out of range", "> 0"},
      // The BEM's key of earlier versions names the new place.
      {"HardnessOfTheBem", bem("hardness = 1e9"), "methods.bem.hardness", "a property of the interface",
       "interface.hardness"},
      // interface.adhesion (app/interface.cpp): each number checked and named; the model's own keys only.
      {"AdhesionNegativeWork",
       methods(
           "[interface]\nadhesion = { model = \"dugdale\", work = -0.05, stress = 1e5 }\n[methods.bem]\n"),
       "interface.adhesion.work", "out of range", "> 0"},
      {"AdhesionZeroStress",
       methods("[interface]\nadhesion = { model = \"dugdale\", work = 0.05, stress = 0 }\n[methods.bem]\n"),
       "interface.adhesion.stress", "out of range", "> 0"},
      {"AdhesionMissingRange",
       methods("[interface]\nadhesion = { model = \"exponential\", work = 0.05 }\n[methods.bem]\n"),
       "interface.adhesion.range", "missing required key", ""},
      {"AdhesionRangeOfDugdale",
       methods("[interface]\nadhesion = { model = \"dugdale\", work = 0.05, range = 1e-9 }\n[methods.bem]\n"),
       "interface.adhesion.range", "unknown key", "stress"},
      {"AdhesionUnknownModel",
       methods("[interface]\nadhesion = { model = \"jkr\", work = 0.05 }\n[methods.bem]\n"),
       "interface.adhesion.model", "unknown choice \"jkr\"", "\"dugdale\", \"exponential\""},
      {"AdhesionWithoutModel", methods("[interface]\nadhesion = { work = 0.05 }\n[methods.bem]\n"),
       "interface.adhesion.model", "missing", "model = \"dugdale\""},
      {"UnknownInterfaceKey", methods("[interface]\nfriction = 0.3\n[methods.bem]\n"), "interface.friction",
       "unknown key", "hardness"},
      {"UnknownEffectIgnored", bem("ignore = [\"friction\"]"), "methods.bem.ignore[0]",
       "unknown effect \"friction\"", "hardness"},
      {"IgnoreNotAnArray", bem("ignore = \"hardness\""), "methods.bem.ignore", "wrong type",
       "an array of effect names"},
      {"BemUnknownSolver", bem("solver = \"multigrid\""), "methods.bem.solver",
       "unknown choice \"multigrid\"", "\"polonsky_keer\", \"preconditioned_cg\""},
      {"BemSolverNotAString", bem("solver = 1"), "methods.bem.solver", "wrong type", "\"polonsky_keer\""},
      {"BemConnectivitySix", bem("connectivity = 6"), "methods.bem.connectivity", "out of range: got 6",
       "4, 8"},
      {"BemRefineBelowSurface", bem("refine = 32"), "methods.bem.refine", "out of range", "64 points a side"},
      {"BemPeriodicNotBoolean", bem("periodic = \"yes\""), "methods.bem.periodic", "expected a boolean",
       "true"},
      {"PlateauConnectivitySix", plateau("connectivity = 6"), "methods.p.connectivity", "out of range",
       "4, 8"},
      {"PlateauUnknownLevels", plateau("levels = \"fine\""), "methods.p.levels", "unknown levels",
       "\"exact\""},
      {"PlateauZeroLevels", plateau("levels = 0"), "methods.p.levels", "out of range", "integer count >= 1"},
      {"PlateauFractionalLevels", plateau("levels = 1.5"), "methods.p.levels", "wrong type", "\"paper\""},
      {"UnknownMethod", methods("[methods.x]\nmethod = \"fem\"\n"), "methods.x.method", "unknown method",
       "bem, plateau, plateau_hertz, gw_mccool, bgt, bgt_linear, persson"},
      {"LabelNeedsAMethod", methods("[methods.x]\n"), "methods.x.method", "missing required key",
       "gw_mccool"},
      {"LabelNamesAnotherMethod", methods("[methods.bgt]\nmethod = \"persson\"\n"), "methods.bgt.method",
       "the label names the method bgt", ""},
      {"InvalidLabel", methods("[methods.\"a b\"]\nmethod = \"bgt\"\n"), "methods.a b", "invalid label", ""},
      {"NoMethods", methods("[methods]\n"), "methods", "no methods", "bem, plateau"},
      {"MissingMethods", methods(""), "methods", "missing required key", "bem, plateau"},
      {"UnknownReference", "reference = \"fem\"\n" + Blocks().text(), "reference",
       "no method labelled \"fem\"", "bem, persson"},
      {"InvalidName", changed(&Blocks::head, "name = \"my scene/1\"\n").text(), "name", "invalid name",
       "letters, digits"},
      {"DotDotName", changed(&Blocks::head, "name = \"..\"\n").text(), "name", "invalid name", ""},
      {"MissingSurfaceFile", changed(&Blocks::surface, "[surface]\nfile = \"absent.txt\"\n").text(),
       "surface.file", "no such file: ", ""},
  };
}

// gtest prints the case by its name instead of its bytes.
void PrintTo(const InvalidCase& c, std::ostream* out) {
  *out << c.test_name;
}

class InvalidScene : public ::testing::TestWithParam<InvalidCase> {};

TEST_P(InvalidScene, IsReportedWithKeyPathAndReason) {
  const InvalidCase& c = GetParam();
  expect_problem(c.text, c.path, c.reason, c.accepted);
}

// docs/formats.md: an instrument file under [surface] with channel, fill and level; written back and re-read.
TEST(Scene, InstrumentFileTakesChannelFillAndLevel) {
  const fs::path formats_folder{CB_DATA_DIR "/formats"};
  Blocks b;
  b.surface = "[surface]\nfile = \"di-1.di\"\nchannel = 1\nfill = \"harmonic\"\nlevel = \"plane\"\n";
  const Scene scene = parse_scene(b.text(), formats_folder / "scene.toml");
  const auto& f = std::get<FileSurfaceSpec>(scene.surface.source);
  EXPECT_EQ(f.channel, "1");
  EXPECT_EQ(f.fill, FillMethod::harmonic);
  EXPECT_EQ(f.level, Levelling::plane);
  const Scene again = parse_scene(to_toml(scene), "x.toml");
  const auto& g = std::get<FileSurfaceSpec>(again.surface.source);
  EXPECT_EQ(g.channel, "1");
  EXPECT_EQ(g.fill, FillMethod::harmonic);
  EXPECT_EQ(g.level, Levelling::plane);

  b.surface = "[surface]\nfile = \"di-1.di\"\nfill = \"zero\"\nlevel = \"tilt\"\n";
  expect_problem(b.text(), "surface.fill", "unknown choice \"zero\"", "\"harmonic\"",
                 formats_folder / "s.toml");
  expect_problem(b.text(), "surface.level", "unknown choice \"tilt\"", "\"plane\"",
                 formats_folder / "s.toml");
  b.surface = "[surface]\nfile = \"example-2d.npy\"\n";
  expect_problem(b.text(), "surface.size", "missing required key", "NumPy array", formats_folder / "s.toml");
}

INSTANTIATE_TEST_SUITE_P(Scene, InvalidScene, ::testing::ValuesIn(invalid_cases()),
                         [](const auto& info) { return std::string(info.param.test_name); });

}  // namespace
}  // namespace contactbench

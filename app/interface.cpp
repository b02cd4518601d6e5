#include "contactbench/app/interface.hpp"

#include <algorithm>

#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/section.hpp"

namespace contactbench {

std::string_view effect_name(Effect effect) {
  switch (effect) {
    case Effect::hardness:
      return "hardness";
    case Effect::adhesion:
      return "adhesion";
  }
  return "";
}

const std::vector<Effect>& known_effects() {
  static const std::vector<Effect> effects{Effect::hardness, Effect::adhesion};
  return effects;
}

std::string effects_text(const std::vector<Effect>& effects) {
  std::string text;
  for (const Effect e : effects)
    text += (text.empty() ? "" : ", ") + std::string(effect_name(e));
  return text;
}

std::optional<Effect> effect_of(std::string_view name) {
  for (const Effect e : known_effects())
    if (effect_name(e) == name) return e;
  return std::nullopt;
}

bool InterfaceSpec::has(Effect effect) const {
  switch (effect) {
    case Effect::hardness:
      return hardness.has_value();
    case Effect::adhesion:
      return adhesion.has_value();
  }
  return false;
}

std::vector<Effect> InterfaceSpec::effects() const {
  std::vector<Effect> present;
  for (const Effect e : known_effects())
    if (has(e)) present.push_back(e);
  return present;
}

InterfaceSpec InterfaceSpec::without(const std::vector<Effect>& ignored) const {
  InterfaceSpec applied = *this;
  for (const Effect e : ignored)
    switch (e) {
      case Effect::hardness:
        applied.hardness.reset();
        break;
      case Effect::adhesion:
        applied.adhesion.reset();
        break;
    }
  return applied;
}

namespace {

constexpr std::string_view kAdhesionTables =
    "adhesion = { model = \"dugdale\", work = <w [J/m^2]>, stress = <sigma0 [Pa]> } or { model = "
    "\"exponential\", work = <w [J/m^2]>, range = <rho [m]> }";

// interface.adhesion: the law's model and its two numbers, each checked and named on its own.
std::optional<AdhesionLaw> read_adhesion(const Section& interface) {
  const toml::table* table = interface.subtable("adhesion", false, kAdhesionTables);
  if (!table) return std::nullopt;
  const Section s(*table, "interface.adhesion", interface.problems());
  const std::optional<std::string> model = s.choice("model", {"dugdale", "exponential"});
  if (!model) {
    if (!s.has("model")) s.missing("model", kAdhesionTables);
    return std::nullopt;
  }
  const bool dugdale = *model == "dugdale";
  s.reject_unknown({"model", "work", dugdale ? "stress" : "range"});
  const std::optional<Real> work = s.number("work", true, positive("[J/m^2]"));
  const std::optional<Real> second =
      dugdale ? s.number("stress", true, positive("[Pa]")) : s.number("range", true, positive("[m]"));
  if (!work || !second) return std::nullopt;
  return dugdale ? AdhesionLaw::dugdale(*work, *second) : AdhesionLaw::exponential(*work, *second);
}

}  // namespace

InterfaceSpec read_interface(const Section& root) {
  InterfaceSpec spec;
  const toml::table* table = root.subtable(
      "interface", false, "a table of effects: hardness = <H [Pa]>, " + std::string(kAdhesionTables));
  if (!table) return spec;
  const Section s(*table, "interface", root.problems());
  std::vector<std::string_view> keys;
  for (const Effect e : known_effects())
    keys.push_back(effect_name(e));
  s.reject_unknown(keys);
  spec.hardness = s.number("hardness", false, positive("[Pa]"));
  spec.adhesion = read_adhesion(s);
  return spec;
}

void write_interface(const InterfaceSpec& interface, SceneKeys& root) {
  if (interface.effects().empty()) return;
  SceneKeys& table = root.table("interface");
  if (interface.hardness) table.put("hardness", *interface.hardness);
  if (const std::optional<AdhesionLaw>& law = interface.adhesion) {
    SceneKeys& adhesion = table.table("adhesion");
    adhesion.put("model", std::string(adhesion_model_name(law->model)));
    adhesion.put("work", law->work);
    if (law->model == AdhesionModel::dugdale)
      adhesion.put("stress", law->stress);
    else
      adhesion.put("range", law->range);
  }
}

namespace {

// What a method is without the effect, as a reader of the table says it.
std::string_view without_word(Effect effect) {
  switch (effect) {
    case Effect::hardness:
      return "elastic";
    case Effect::adhesion:
      return "non-adhesive";
  }
  return "";
}

}  // namespace

std::string ignored_effects_note(const std::vector<Effect>& ignored) {
  std::string words;
  for (const Effect e : ignored)
    words += (words.empty() ? "" : ", ") + std::string(without_word(e));
  return ignored.empty() ? "" : words + ": ignores " + effects_text(ignored);
}

}  // namespace contactbench

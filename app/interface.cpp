#include "contactbench/app/interface.hpp"

#include <algorithm>

#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/section.hpp"

namespace contactbench {

std::string_view effect_name(Effect effect) {
  switch (effect) {
    case Effect::hardness:
      return "hardness";
  }
  return "";
}

const std::vector<Effect>& known_effects() {
  static const std::vector<Effect> effects{Effect::hardness};
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
    }
  return applied;
}

InterfaceSpec read_interface(const Section& root) {
  InterfaceSpec spec;
  const toml::table* table = root.subtable("interface", false, "a table of effects: hardness = <H [Pa]>");
  if (!table) return spec;
  const Section s(*table, "interface", root.problems());
  std::vector<std::string_view> keys;
  for (const Effect e : known_effects())
    keys.push_back(effect_name(e));
  s.reject_unknown(keys);
  spec.hardness = s.number("hardness", false, positive("[Pa]"));
  return spec;
}

void write_interface(const InterfaceSpec& interface, SceneKeys& root) {
  if (interface.effects().empty()) return;
  SceneKeys& table = root.table("interface");
  if (interface.hardness) table.put("hardness", *interface.hardness);
}

namespace {

// What a method is without the effect, as a reader of the table says it.
std::string_view without_word(Effect effect) {
  switch (effect) {
    case Effect::hardness:
      return "elastic";
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

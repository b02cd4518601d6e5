// The physics of the interface a scene calls for (scenes/README.md, [interface]): effects beyond frictionless
// elastic contact, declared once for the whole scene rather than as options of one method. Every method says
// which effects it models (Method::models); a method asked to run a scene with an effect it does not model is
// refused before any stage, unless its table says `ignore = ["<effect>"]`, and then every output marks its
// row (app/scene_run.hpp). A scene with no effect runs no effect's code.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/adhesion_law.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

class Section;
class Problems;
struct SceneKeys;

enum class Effect {
  hardness,  // a perfectly plastic pressure cap p <= H (docs/theory.md section 6)
  adhesion,  // an attraction between the surfaces as a function of the gap (core/adhesion_law.hpp)
};

// The scene key of an effect ("hardness"), and every known effect in declaration order.
std::string_view effect_name(Effect effect);
const std::vector<Effect>& known_effects();
// "hardness, ..." for messages.
std::string effects_text(const std::vector<Effect>& effects);
std::optional<Effect> effect_of(std::string_view name);

struct InterfaceSpec {
  std::optional<Real> hardness;  // [Pa]: perfectly plastic pressure cap; absent: purely elastic
  // adhesion = { model = "dugdale", work = w [J/m^2], stress = σ0 [Pa] } or { model = "exponential",
  // work = w, range = ρ [m] }; absent: non-adhesive.
  std::optional<AdhesionLaw> adhesion;

  bool has(Effect effect) const;
  std::vector<Effect> effects() const;  // those the scene calls for, in declaration order
  // The same interface without `ignored`: what a method that ignores them runs with.
  InterfaceSpec without(const std::vector<Effect>& ignored) const;
  bool operator==(const InterfaceSpec&) const = default;
};

// [interface], optional: every problem goes to the section's problems.
InterfaceSpec read_interface(const Section& root);
// Written only when the scene calls for an effect, so that a purely elastic scene reads back unchanged.
void write_interface(const InterfaceSpec& interface, SceneKeys& root);

// "elastic: ignores hardness": what every output shows beside a method that runs without some of the
// scene's effects; empty when it ignores none.
std::string ignored_effects_note(const std::vector<Effect>& ignored);

}  // namespace contactbench

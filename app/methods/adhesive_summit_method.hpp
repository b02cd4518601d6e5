// What the adhesive summit theories share as methods of a scene (theories/adhesive_summits.hpp,
// docs/theory.md section 10.4): Fuller–Tabor (fuller_tabor_method.cpp) and Maugis–GW (maugis_gw_method.cpp).
// They model the interface's adhesion and nothing else: a scene without [interface] adhesion, or with a
// hardness, is refused in preflight naming the key. They need the spectral moments alone, read the law and
// E* from the scene, and answer the repulsive A/A0 at the scene's net loads on the branch the table names
// (branch = "approach", the default, or "retract").
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/core/adhesion_law.hpp"
#include "contactbench/theories/adhesive_summits.hpp"

namespace contactbench {

class AdhesiveSummitMethod : public Method {
 public:
  // curve(moments, E* [Pa], law, loads, branch, nominal area [m^2]): the theory's library function, which
  // throws Error for what it refuses.
  using Curve = std::function<LoadAreaCurve(const SpectralMoments&, Real, const AdhesionLaw&,
                                            std::span<const Real>, AdhesiveBranch, Real)>;
  AdhesiveSummitMethod(std::string name, std::string summit, Curve curve)
      : name_(std::move(name)), summit_(std::move(summit)), curve_(std::move(curve)) {}

  std::string_view name() const override { return name_; }
  std::vector<Effect> models() const override { return {Effect::adhesion}; }
  std::string compared_area() const override {
    return "the theory's repulsive A/A0 at the net load (a continuum: no grid)";
  }
  std::string note() const override { return "GW summits each " + summit_; }
  void read(const Section& keys, const SceneContext& context) override;
  void write(SceneKeys& keys) const override;
  MethodNeeds needs(const SceneContext& context) const override;
  void preflight(const MethodCheck& check) const override;
  MethodCurve evaluate(const MethodInputs& inputs) const override;

 private:
  std::string name_;
  std::string summit_;  // "a JKR sphere", for the note
  Curve curve_;
  AdhesiveBranch branch_ = AdhesiveBranch::approach;
};

}  // namespace contactbench

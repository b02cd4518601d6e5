// What the elastic-plastic analytic theories share as methods of a scene (docs/theory.md section 11): they
// need the spectral moments alone, model the interface's hardness (without one they are their elastic parent
// theory), refuse a hardness at or below the mean pressure of any load (naming the load), and add the
// columns plastic_area_fraction (A_plastic/A0) and plastic_load_fraction (P_plastic/P). One file per theory
// (ceb_method.cpp, ...) says which library curve it is.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/theories/plastic_curve.hpp"

namespace contactbench {

// What a theory reads besides the moments and loads.
struct PlasticTheoryInputs {
  Real hardness_over_estar = kNoHardness;  // H/E*
  Real poisson_ratio = 0.3;                // the scene's material.nu, 0.3 when it gives none
  Real nominal_area = 0;                   // A0 [m^2]
  const SceneSurface* surface = nullptr;   // heights from the mean plane, for theories that fit its spectrum
};

class PlasticTheoryMethod : public Method {
 public:
  // curve(moments, loads, inputs): the theory's library function, which throws Error for what it refuses.
  using Curve =
      std::function<PlasticCurve(const SpectralMoments&, std::span<const Real>, const PlasticTheoryInputs&)>;
  PlasticTheoryMethod(std::string name, std::string note, Curve curve)
      : name_(std::move(name)), note_(std::move(note)), curve_(std::move(curve)) {}

  std::string_view name() const override { return name_; }
  std::vector<Effect> models() const override { return {Effect::hardness}; }
  std::string note() const override { return note_; }
  std::string compared_area() const override {
    return "the theory's A/A0, elastic and plastic (a continuum: no grid)";
  }
  void read(const Section& keys, const SceneContext& context) override;
  void write(SceneKeys& keys) const override;
  MethodNeeds needs(const SceneContext& context) const override;
  void preflight(const MethodCheck& check) const override;
  MethodCurve evaluate(const MethodInputs& inputs) const override;

 private:
  PlasticTheoryInputs inputs(const Scene& scene, const SceneSurface& surface) const;

  std::string name_, note_;
  Curve curve_;
  std::optional<Real> hardness_;  // [Pa], the interface's as this method runs it
};

// The capped load check shared with the plateau methods: one problem naming every load at or above the
// hardness, at interface.hardness.
void check_hardness_against_loads(const MethodCheck& check);

}  // namespace contactbench

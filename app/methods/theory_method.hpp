// What the analytic theories share as methods of a scene (docs/theory.md section 5): they need the spectral
// moments alone; they are for isotropic surfaces, and refuse an anisotropic one unless anisotropy =
// "average" gives them its equivalent isotropic surface; and each refuses the loads it cannot reach. One
// file per theory (gw_mccool_method.cpp, ...) says which library curve it is.
#pragma once

#include <functional>
#include <span>
#include <string>

#include "contactbench/app/methods/method.hpp"

namespace contactbench {

class AnalyticTheoryMethod : public Method {
 public:
  // curve(moments, loads, nominal area [m^2]): the theory's library function, which throws Error for what
  // it refuses. uses_m4: whether the theory reads m4 (then both m2 and m4 must be isotropic).
  using Curve = std::function<LoadAreaCurve(const SpectralMoments&, std::span<const Real>, Real)>;
  // beyond(moments seen, inputs, curve): fills curve.mean_gap and curve.stiffness [Pa/m] at the scene's
  // loads for a theory that gives them (docs/theory.md section 12), called only when the scene compares
  // either; none: the theory gives neither (the tables say n/a).
  using Beyond = std::function<void(const SpectralMoments&, const MethodInputs&, MethodCurve&)>;
  // beyond_reads_heights: whether `beyond` reads the surface's heights (its spectrum), which a line scan
  // does not give over an area.
  AnalyticTheoryMethod(std::string name, Curve curve, bool uses_m4, Beyond beyond = nullptr,
                       bool beyond_reads_heights = false)
      : name_(std::move(name)),
        curve_(std::move(curve)),
        uses_m4_(uses_m4),
        beyond_(std::move(beyond)),
        beyond_reads_heights_(beyond_reads_heights) {}

  std::string_view name() const override { return name_; }
  std::string compared_area() const override { return "the theory's A/A0 (a continuum: no grid)"; }
  void read(const Section& keys, const SceneContext& context) override;
  void write(SceneKeys& keys) const override;
  MethodNeeds needs(const SceneContext& context) const override;
  void preflight(const MethodCheck& check) const override;
  MethodCurve evaluate(const MethodInputs& inputs) const override;

 private:
  // The moments the theory sees: the surface's own, or with anisotropy = "average" the means of x and y
  // (the equivalent isotropic surface, which keeps the areal gbar^2 = m2x + m2y: exact for Persson and the
  // BGT linear law, which depend on gbar alone; an approximation for GW-McCool and the full BGT).
  SpectralMoments seen(const SpectralMoments& surface) const;

  std::string name_;
  Curve curve_;
  bool uses_m4_ = true;
  Beyond beyond_;
  bool beyond_reads_heights_ = false;
  bool average_anisotropy_ = false;  // anisotropy = "refuse" (default) | "average"
};

}  // namespace contactbench

#include "contactbench/app/methods/theory_method.hpp"

#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/theories/isotropic_moments.hpp"

namespace contactbench {

void AnalyticTheoryMethod::read(const Section& s, const SceneContext&) {
  s.reject_unknown({"method", "anisotropy"});
  average_anisotropy_ = s.choice("anisotropy", {"refuse", "average"}) == "average";
}

void AnalyticTheoryMethod::write(SceneKeys& keys) const {
  keys.put("anisotropy", average_anisotropy_ ? "average" : "refuse");
}

MethodNeeds AnalyticTheoryMethod::needs(const SceneContext&) const {
  return {.moments = true,
          .sweep = std::nullopt,
          .bem = std::nullopt,
          .bem_connectivity = 4,
          .heights_over_an_area = false};
}

SpectralMoments AnalyticTheoryMethod::seen(const SpectralMoments& m) const {
  if (!average_anisotropy_) return m;
  const Real m2 = 0.5 * (m.m2x + m.m2y), m4 = 0.5 * (m.m4x + m.m4y);
  return {.m0 = m.m0, .m2x = m2, .m4x = m4, .m2y = m2, .m4y = m4};
}

void AnalyticTheoryMethod::preflight(const MethodCheck& check) const {
  if (check.line_scan) {
    if (beyond_reads_heights_ &&
        (check.scene.compares(Quantity::mean_gap) || check.scene.compares(Quantity::stiffness))) {
      check.problem("",
                    name_ +
                        "'s mean gap and stiffness integrate the surface's spectrum over the plane, "
                        "which a line scan (one profile) does not give",
                    "compare = [\"area\"] for a line scan, or a 2-D file of the surface");
      return;
    }
    if (uses_m4_ && !check.line_scan->rms_curvature) {
      check.problem("",
                    name_ +
                        " reads m4 (the profile's curvature), which a line scan sampled at uneven x "
                        "does not give (docs/formats.md \"line scans\")",
                    "a uniformly sampled scan, or a theory that reads m2 alone (persson, bgt_linear)");
      return;
    }
  }
  const SpectralMoments moments = seen(check.moments);
  try {
    if (uses_m4_)
      isotropic_moments(moments, name_);
    else
      isotropic_m2(moments, name_);
  } catch (const Error& error) {
    check.problem("anisotropy", error.what(),
                  "anisotropy = \"average\" (the theory sees the surface's equivalent isotropic surface), or "
                  "leave this method out");
    return;
  }
  const Real area = check.surface.grid().nominal_area();
  report_loads_the_theory_refuses(check,
                                  [&](Real load) { curve_(moments, std::span<const Real>(&load, 1), area); });
}

MethodCurve AnalyticTheoryMethod::evaluate(const MethodInputs& in) const {
  const SpectralMoments moments = seen(in.moments);
  MethodCurve curve =
      MethodCurve::from(curve_(moments, in.scene.loads, in.surface.grid().nominal_area()), in.scene.loads);
  const bool gap = in.scene.compares(Quantity::mean_gap), stiffness = in.scene.compares(Quantity::stiffness);
  if (beyond_ && (gap || stiffness)) {
    beyond_(moments, in, curve);
    if (!gap) curve.mean_gap.clear();
    if (!stiffness) curve.stiffness.clear();
  }
  if (average_anisotropy_)
    curve.parameters += "; anisotropy averaged: the equivalent isotropic surface of m2x/m2y = " +
                        std::to_string(in.moments.m2x / in.moments.m2y) +
                        ", m4x/m4y = " + std::to_string(in.moments.m4x / in.moments.m4y);
  return curve;
}

}  // namespace contactbench

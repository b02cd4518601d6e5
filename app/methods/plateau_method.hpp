// The multi-plateaus model's keys and sweep, shared by the paper's model (plateau_method.cpp) and the
// project's Hertz-consistent variant (plateau_hertz_method.cpp): the same cut of the same (optionally
// Fourier-refined) surface, two readings of it.
#pragma once

#include <optional>
#include <string_view>

#include "contactbench/app/methods/method.hpp"

namespace contactbench {

class PlateauMethod : public Method {
 public:
  std::string_view name() const override { return "plateau"; }
  std::string compared_area() const override;
  void read(const Section& keys, const SceneContext& context) override;
  void write(SceneKeys& keys) const override;
  MethodNeeds needs(const SceneContext& context) const override;
  // Refinement is checked against the surface (periodic, enough points); the model answers every positive
  // load (full contact beyond the lowest height; NaN beyond the paper's last level, said in its parameters).
  void preflight(const MethodCheck& check) const override;
  MethodCurve evaluate(const MethodInputs& inputs) const override;

 protected:
  // What both readings add to their curve: " on the surface Fourier-refined to n x n" to the parameters when
  // refined, and the sweep level by level when write_levels = true.
  void complete(MethodCurve& curve, const MethodInputs& inputs) const;

 private:
  int connectivity_ = 4;
  SweepLevels levels_ = SweepLevels::exact();  // levels = "exact" | "paper" | an integer count (uniform)
  std::optional<bool> periodic_;               // default: the surface's own periodicity
  Index refine_ = 0;                           // points a side swept; 0 = the surface as it is
  // write_levels = true: the report keeps the sweep (MethodCurve::levels), written as <label>_levels.csv. Off
  // by default: with exact levels it is a row per distinct height (4 million on a 2048^2 refinement).
  bool write_levels_ = false;
};

}  // namespace contactbench

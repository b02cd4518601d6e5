// The adhesive boundary-element ground truth: a rough rigid surface pressed against (or pulled off) an
// elastic half-space whose surface is also attracted by the law of core/adhesion_law.hpp (docs/theory.md
// section 10, docs/solvers.md "Adhesion"). The traction is t = p - a(g): p >= 0 the repulsive contact
// pressure (nonzero only where the gap g is 0), a(g) >= 0 the attraction at the gap.
//
// Method: a fixed point on the attraction around any non-adhesive solver of the registry. With a(x) frozen,
// the gap g = d - h + G(p - a) = d - (h + G a) + G p is that of a non-adhesive contact with the heights
// h + G a (the attraction lifts the elastic surface towards the rigid one) and a repulsive load of P +
// mean(a); so each outer iteration solves that contact with the chosen solver (warm-started from the last)
// and sets a from its gap. Maugis–Dugdale: a = σ0 where g < δc, converged when no point changes side (the
// cohesive zone is the outer iteration's unknown, as in the Dugdale iterations of the literature, e.g.
// Bazrafshan, de Rooij and Schipper 2017); exponential: converged when the attraction changes by less than
// the tolerance of its peak, with under-relaxation where the plain fixed point overshoots.
//
// Separation control follows a path: approach (falling separations) and retract (rising ones), each solve
// starting from the last state, so the jumps into and out of contact happen where they happen physically.
// Load control may ask for a tensile (negative) load; when no state in contact carries it the solution says
// the surfaces separate.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/adhesion_law.hpp"

namespace contactbench {

class ContactSolver;
class ExponentialLbfgs;
class HalfSpace;

// What an adhesive solve adds to the contact solution of the same load (the scene's columns).
struct AdhesiveLoad {
  Real adhesive_pressure = 0;  // mean(a) [Pa]
  Index attractive_points = 0;
  Real zone_pixels = 0;
  Index outer_iterations = 0;
};

struct AdhesiveSolution {
  HeightMap traction;           // t = p - a [Pa], compressive positive
  HeightMap pressure;           // p [Pa]: the repulsive part alone
  HeightMap gap;                // [m], 0 on the repulsive contact set
  Real mean_pressure = 0;       // P/A0 = mean(t) [Pa]: the net load, negative when tensile
  Real repulsive_pressure = 0;  // mean(p) [Pa]
  Real adhesive_pressure = 0;   // mean(a) [Pa], >= 0: the pull of the attraction
  Real mean_gap = 0;            // [m]
  Real separation = 0;          // d: the flat's height above the mean plane of the heights [m]
  Index contact_points = 0;     // g = 0 (the repulsive contact area)
  // Points outside contact inside the attractive zone: pulled (Dugdale: the zone's rule, adhesive_solver.cpp)
  // or at g < ρ (exponential).
  Index attractive_points = 0;
  // Points on the edge of the contact set (a contact point with a neighbour out of contact), and the width
  // of the attractive zone there in pixels: attractive_points / edge_points. The zone must be resolved
  // (several pixels) for the answer to mean what the law says (docs/solvers.md "Adhesion").
  Index edge_points = 0;
  Real zone_pixels = 0;
  Index iterations = 0;        // of the contact solves, summed over the outer iterations
  Index outer_iterations = 0;  // contact solves made
  // constrained_cg: the steps of the whole-surface CG before them; projected_lbfgs: its quasi-Newton steps
  // (its energy evaluations, one FFT pair each, are in `iterations`, with the start's contact solve).
  Index cg_iterations = 0;
  Real residual = 0;           // of the last contact solve (BemSolver::solution().residual)
  Real attraction_change = 0;  // the last outer change: points that changed side (Dugdale), max |Δa|/peak
  bool converged = false;
  // Load control only: no state in contact carries the load (below the pull-off force); the fields are those
  // of the last attempt.
  bool separated = false;
  double seconds = 0;

  // The contact solution of the same state: the repulsive pressure as its pressure (the contact set is
  // where it is > 0), the net load as its mean pressure; and what the attraction adds.
  ContactSolution contact() const;
  AdhesiveLoad adhesive() const {
    return {adhesive_pressure, attractive_points, zone_pixels, outer_iterations};
  }
};

// How the adhesive problem is solved (docs/solvers.md "Adhesion"): the fixed point on the attraction around
// the contact solver alone, or (Dugdale only) first one constrained CG on the whole surface with the zone
// decided inside it (bem/adhesive_constrained_cg.hpp), whose state the fixed point then checks and settles,
// or (exponential law, periodic only) the total energy minimised over the gap by a projected L-BFGS
// (bem/adhesive_lbfgs.hpp, docs/theory.md section 10.11).
enum class AdhesiveMethod { fixed_point, constrained_cg, projected_lbfgs };

inline std::string_view adhesive_method_name(AdhesiveMethod method) {
  switch (method) {
    case AdhesiveMethod::fixed_point:
      return "fixed_point";
    case AdhesiveMethod::constrained_cg:
      return "constrained_cg";
    case AdhesiveMethod::projected_lbfgs:
      return "projected_lbfgs";
  }
  return "fixed_point";
}

// Why `method` cannot solve this law on this grid (an empty reason: it can), and what is accepted instead:
// the projected L-BFGS needs a smooth potential (the exponential law) and the periodic stiffness operator,
// the constrained CG the Dugdale law's two-state zone.
// The words preflight (app/methods/bem_method.cpp) and the solver both use.
struct AdhesiveMethodRefusal {
  std::string reason, accepted;
};
AdhesiveMethodRefusal adhesive_method_refusal(AdhesiveMethod method, AdhesionModel model, bool periodic);

struct AdhesiveSolverOptions {
  BemSolverOptions contact;  // of each contact solve (the solver, tolerance, precision)
  AdhesiveMethod method = AdhesiveMethod::fixed_point;
  // Outer iterations before the solve is marked not converged.
  Index max_outer_iterations = 500;
};

class AdhesiveBemSolver {
 public:
  // The surface's own periodicity chooses the operator; modulus is E* [Pa].
  AdhesiveBemSolver(const Surface& surface, Real modulus, const AdhesionLaw& law,
                    AdhesiveSolverOptions options = {}, int threads = 1);
  ~AdhesiveBemSolver();

  // The flat at `separation` [m] above the mean plane of the heights (periodic: the mean gap of the
  // non-adhesive problem's convention, BemSolver::solve_for_separation), starting from the last state.
  const AdhesiveSolution& solve_for_separation(Real separation);
  // The net mean pressure P/A0 [Pa], which may be negative, starting from the last state.
  const AdhesiveSolution& solve(Real mean_pressure);
  // The next solve starts with no attraction and no contact (a fresh approach).
  void forget();

  const AdhesiveSolution& solution() const { return solution_; }
  const AdhesionLaw& law() const { return law_; }
  const Surface& surface() const { return surface_; }  // centred

  // The energy of the last state per nominal area [J/m^2] (docs/theory.md section 10.7): the elastic energy
  // ½ mean(t u), u = g - d + h the surface's displacement (its mean removed when periodic, where the uniform
  // mode carries none), plus the interface's potential mean(V): V = -a (δc - g) for a Dugdale point pulled by
  // a (so dV/dg = a, the edge points' half stress included), V = -w exp(-g/ρ) for the exponential law. On a
  // continuous branch of separation control dU/dd = -P/A0 (the net load), which the approach-retract path
  // (bem/adhesive_path.hpp) uses to tell a jump from a step.
  Real energy() const;

 private:
  enum class Control { separation, load };
  const AdhesiveSolution& solve_with(Control control, Real value);
  // projected_lbfgs: the whole problem as one minimisation (bem/adhesive_lbfgs.hpp).
  const AdhesiveSolution& solve_whole(Control control, Real value);
  // a from the gap (and, for Dugdale, whether each point is in contact); returns the change (points that
  // changed side, or max |Δa| / peak) after relaxation.
  Real update_attraction(const ContactSolution& contact);
  void describe(const ContactSolution& contact, const HeightMap& attraction);

  Surface surface_;  // centred
  AdhesionLaw law_;
  AdhesiveSolverOptions options_;
  std::unique_ptr<ContactSolver> engine_;
  std::unique_ptr<HalfSpace> half_space_;
  HeightMap attraction_, lift_, effective_heights_;
  // Dugdale: how often each point changed side in this solve. A point that keeps changing side (two points
  // pulling each other across the edge in turn, where the zone is barely resolved) is an edge point: the
  // zone's edge crosses it, and it carries half the stress from then on (kFlipsToEdge, adhesive_solver.cpp).
  std::vector<unsigned char> flips_;
  // The displacement of a pixel under a unit pressure on itself [m/Pa] (the Dugdale zone's rule).
  Real self_response_ = 0;
  Real relaxation_ = 1;  // exponential law: the fraction of the new attraction taken
  Real last_change_ = 0;
  bool warm_ = false;
  std::unique_ptr<ExponentialLbfgs> whole_;  // projected_lbfgs only
  HeightMap whole_gap_;                      // its last state, the next solve's start
  AdhesiveSolution solution_;
};

}  // namespace contactbench

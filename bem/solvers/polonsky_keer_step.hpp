// The step control of Polonsky & Keer's constrained CG that the serial solver (bem/solvers/
// polonsky_keer_solver.cpp) and the distributed one (mpi/distributed_bem_solver.cpp) share, so that both
// take the same decisions from the same sums: the stopping criterion, the damping of a cycling iteration and
// the step lengths (docs/solvers.md).
#pragma once

#include <limits>

namespace contactbench {

class PolonskyKeerStep {
 public:
  // PK's criterion: the relative change of the pressure in the last iteration, sum |p - p_old| / sum p.
  static double relative_change(double change, double sum) {
    return sum > 0 ? change / sum : (change == 0 ? 0.0 : std::numeric_limits<double>::infinity());
  }

  // Converged: the change below the tolerance and, for the preconditioned direction, no node entered or left
  // the contact set in the last update (the set has settled, so the change measures a CG step on a fixed
  // set; docs/solvers.md).
  static bool converged(double change, double tolerance, bool preconditioned, double entered) {
    return change < tolerance && (!preconditioned || entered == 0);
  }

  // Step damping. On a contact set with hundreds of nodes at one height (a flat around a spike) PK's full
  // step drives hundreds of nodes out of the set and its entry step (eq. 14) drives as many back in, every
  // iteration, for ever (tests/test_bem_validation.cpp: a cycle with a relative change ~1.3 for 20000
  // iterations). A cycle shows as a relative change that stops decreasing: after kStall iterations without
  // a new lowest change, the steps are halved (deterministic; never below 2^-30 of PK's). A small enough
  // step is projected gradient descent on a convex quadratic, which converges; on problems without a
  // cycle the damping never starts and the iteration is PK's.
  void observe(double change) {
    if (change < lowest_change_) {
      lowest_change_ = change;
      since_lowest_ = 0;
    } else if (++since_lowest_ >= kStall && damping_ > 0x1p-30) {
      damping_ *= 0.5;
      since_lowest_ = 0;
      lowest_change_ = change;
    }
  }
  double damping() const { return damping_; }

  // The step lengths, from the sums of the direction pass: gt = <g - gbar, t>, tr = <t, G t - rbar> on the
  // contact set, tt = <t, t>. No descent left on the contact set (tr = 0: the gap is already uniform there,
  // e.g. a set of one node) is not convergence: nodes outside it may still penetrate the flat. The update
  // then moves no contact node (tau = 0) and lets those enter; if none does, the pressure is unchanged and
  // the criterion stops the loop. Nodes entering (or, plastic, leaving) the set take the step of the
  // descent; without one the stiffness of one pixel, 1/G(0). Preconditioned, t is a pressure [Pa] and tau
  // a number, so PK's entry (the overlap times tau) would have the wrong dimension; entering nodes take the
  // overlap times the plain step of t instead, <t, t>/<t, G t> [Pa/m] (the stiffness t meets).
  struct Lengths {
    double tau = 0;    // of the direction
    double enter = 0;  // of a node entering: its overlap times this
  };
  Lengths lengths(double gt, double tr, double tt, double self_response, bool preconditioned) const {
    Lengths l;
    l.tau = tr > 0 ? damping_ * gt / tr : 0.0;
    if (preconditioned)
      l.enter = damping_ * (tr > 0 && tt > 0 ? tt / tr : 1 / self_response);
    else
      l.enter = tr > 0 ? l.tau : damping_ / self_response;
    return l;
  }

 private:
  static constexpr long kStall = 25;
  double damping_ = 1, lowest_change_ = std::numeric_limits<double>::infinity();
  long since_lowest_ = 0;
};

}  // namespace contactbench

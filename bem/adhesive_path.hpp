// The approach–retract path of an adhesive contact under separation control (docs/solvers.md "Adhesion",
// docs/theory.md section 10.7): the flat comes down from `start` to `turn` in equal steps, then goes back up
// to `start`, each solve starting from the last state (AdhesiveBemSolver), so the surfaces jump into contact
// on the way in and out of it on the way out where the elastic solid becomes unstable, as they do in an
// experiment with a stiff machine.
//
// A jump is told from a step by the energy: on a continuous branch the energy U (AdhesiveBemSolver::energy)
// falls by the work the load does, ΔU = -∫ P/A0 dd (trapezoid rule over the step, error O(Δd^3)); at a jump
// the state changes at fixed d and releases energy that no load did. A step is a jump when that released
// energy, -(ΔU + trapezoid), exceeds `jump_fraction` of the path's energy range (max U - min U): the steps of
// a continuous branch release only the trapezoid's error, a jump a share of the hysteresis. And a jump leaves
// the legs in different states at one separation: a step whose ends the other leg passes through with the
// same loads (to 1e-3 of the load range) is no jump, however coarse (its trapezoid error, of opposite sign on
// the way back, can exceed the threshold).
// Summed over a closed cycle the released energies are the hysteresis: the work the machine does around the
// cycle, -∮ P/A0 dd (tests/test_adhesive_path.cpp checks the two agree).
//
// The pull-off, the least net load on the retract leg, is located, not only sampled: where the leg's least
// sampled load has a higher one on each side on the same branch (no jump in either step), the minimum lies
// between those two separations, and a golden-section search there (each solve warm from the last, all on
// that branch) narrows it until the load at the bracket's ends is within kPullOffLoad of the least one found;
// the path then goes on from its sampled state as before. Where the least sampled load is the last one
// before a jump out (the branch ends before its minimum is bracketed), the sampled state is reported and
// `pull_off_located` says so.
#pragma once

#include <vector>

#include "contactbench/bem/adhesive_solver.hpp"

namespace contactbench {

struct AdhesivePathState {
  bool approaching = true;     // on the approach leg (else the retract leg)
  Real separation = 0;         // d [m]
  Real mean_pressure = 0;      // net P/A0 [Pa], negative when tensile
  Real adhesive_pressure = 0;  // mean(a) [Pa]
  Index contact_points = 0;    // g = 0
  Index attractive_points = 0;
  Real mean_gap = 0;  // [m]
  Real energy = 0;    // U per nominal area [J/m^2]
  Index iterations = 0;
  bool converged = false;
};

// A jump between two consecutive states of the path (index `after` in AdhesivePath::states, after - 1
// before it).
struct AdhesiveJump {
  bool into_contact = true;  // on the approach leg (a snap in), else on the retract leg (a snap out)
  Index after = 0;
  Real separation_before = 0, separation_after = 0;        // [m]
  Real mean_pressure_before = 0, mean_pressure_after = 0;  // [Pa]
  Index contact_points_before = 0, contact_points_after = 0;
  Real released_energy = 0;  // -(ΔU + trapezoid work) per nominal area [J/m^2]
};

struct AdhesivePathOptions {
  Real start = 0;   // the separation the path starts and ends at [m]
  Real turn = 0;    // the deepest separation [m], < start
  Index steps = 0;  // per leg, >= 2
  Real jump_fraction = 0.02;
};

struct AdhesivePath {
  std::vector<AdhesivePathState> states;
  std::vector<AdhesiveJump> jumps;
  Real pull_off_pressure = 0;     // the most tensile net P/A0 on the retract leg [Pa] (<= 0)
  Real pull_off_separation = 0;   // where it occurs [m]
  bool pull_off_located = false;  // located between two samples of one branch (else the least sample)
  Index pull_off_solves = 0;      // the solves the location took (not among the states)
  Real cycle_work = 0;            // -∮ P/A0 dd over the path [J/m^2], trapezoid rule
  Real released_energy = 0;       // summed over the jumps [J/m^2]
  bool converged = false;         // every state converged
};

// Runs the path from a fresh approach (the solver forgets its state first). Throws Error on bad options.
AdhesivePath approach_retract(AdhesiveBemSolver& solver, const AdhesivePathOptions& options);

}  // namespace contactbench

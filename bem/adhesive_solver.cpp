#include "contactbench/bem/adhesive_solver.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "contactbench/bem/adhesive_constrained_cg.hpp"
#include "contactbench/bem/adhesive_lbfgs.hpp"
#include "contactbench/bem/half_space.hpp"
#include "contactbench/bem/solvers/contact_solver.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// The smallest fraction of the new attraction an exponential outer iteration takes (after halvings).
constexpr Real kSmallestRelaxation = 1.0 / 256;
// Dugdale: a point that changed side this often in one solve is cycling: the zone's edge crosses it. Three:
// in, out and in again (a point that only enters or only leaves changes side once).
constexpr unsigned char kFlipsToEdge = 3;
// constrained_cg: the whole-surface CG only has to bring the zone to where it settles; the contact solver
// that follows converges to the contact tolerance. Its stop: the pressure's relative change per step.
constexpr Real kWholeSurfaceTolerance = 1e-3;

}  // namespace

AdhesiveMethodRefusal adhesive_method_refusal(AdhesiveMethod method, AdhesionModel model, bool periodic) {
  // The whole-surface CG moves a two-state zone (a in {0, σ0}, docs/theory.md 10.10): a smooth law has none.
  if (method == AdhesiveMethod::constrained_cg && model != AdhesionModel::dugdale)
    return {
        "adhesive_solver = \"constrained_cg\" moves the Dugdale law's zone of constant attraction inside "
        "one CG, and the " +
            std::string(adhesion_model_name(model)) + " law has no such zone (its attraction is smooth)",
        "the dugdale law, or adhesive_solver = \"fixed_point\" or \"projected_lbfgs\""};
  if (method != AdhesiveMethod::projected_lbfgs) return {};
  if (model != AdhesionModel::exponential)
    return {"adhesive_solver = \"projected_lbfgs\" minimises an energy by its gradient, and the " +
                std::string(adhesion_model_name(model)) +
                " law's potential has a kink (its attraction is a step)",
            "the exponential law, or adhesive_solver = \"fixed_point\" or \"constrained_cg\""};
  if (!periodic)
    return {
        "adhesive_solver = \"projected_lbfgs\" solves the periodic problem only (its elastic energy "
        "needs the stiffness, the inverse of the half-space operator, which only the periodic one has "
        "cheaply)",
        "a periodic problem, or adhesive_solver = \"fixed_point\""};
  return {};
}

AdhesiveBemSolver::AdhesiveBemSolver(const Surface& surface, Real modulus, const AdhesionLaw& law,
                                     AdhesiveSolverOptions options, int threads)
    : surface_(surface.centred()), law_(law), options_(std::move(options)) {
  validate_adhesion_law(law_, "adhesive BEM");
  const BemSolverOptions& contact = options_.contact;
  if (!(contact.tolerance > 0) || contact.max_iterations < 1 || options_.max_outer_iterations < 1)
    throw Error("adhesive BEM: tolerance must be > 0, max_iterations and max_outer_iterations >= 1");
  if (contact.hardness)
    throw Error(
        "adhesive BEM: adhesion together with a hardness is not modelled (the plastic cap and the "
        "attraction are not solved together); accepted: one of the two");
  if (contact.single_precision && contact.tolerance < kSinglePrecisionTolerance)
    throw Error("adhesive BEM: single precision needs a tolerance >= 1e-6");
  if (const AdhesiveMethodRefusal refusal =
          adhesive_method_refusal(options_.method, law_.model, surface_.grid().periodic);
      !refusal.reason.empty())
    throw Error("adhesive BEM: " + refusal.reason + "; accepted: " + refusal.accepted);
  engine_ = solver_entry(contact.solver).make(surface_, modulus, threads, contact.single_precision);
  engine_->set_between_iterations(contact.between_iterations);
  half_space_ = make_half_space(surface_.grid(), modulus, threads);
  const HeightMap& h = surface_.heights();
  attraction_ = HeightMap::Zero(h.rows(), h.cols());
  lift_ = attraction_;
  effective_heights_ = h;
  HeightMap unit = attraction_;
  unit(0, 0) = 1;
  half_space_->apply(unit, lift_);
  self_response_ = lift_(0, 0);
  lift_.setZero();
  if (options_.method == AdhesiveMethod::projected_lbfgs)
    whole_ = std::make_unique<ExponentialLbfgs>(surface_.grid(), h, modulus, law_, threads);
}

AdhesiveBemSolver::~AdhesiveBemSolver() = default;

void AdhesiveBemSolver::forget() {
  warm_ = false;
  engine_->forget();
}

const AdhesiveSolution& AdhesiveBemSolver::solve_for_separation(Real separation) {
  if (!std::isfinite(separation))
    throw Error("adhesive BEM: the separation must be finite, got " + std::to_string(separation));
  // As for the non-adhesive solve (bem/bem_solver.cpp): the lift of the attraction has no mean on a periodic
  // surface either, so the mean gap is the separation, and none of zero or less has an answer.
  if (surface_.grid().periodic && !(separation > 0))
    throw Error(
        "adhesive BEM: on a periodic surface the separation is the mean gap and must be > 0 m (a mean gap of "
        "zero or less needs an infinite load), got " +
        std::to_string(separation));
  return solve_with(Control::separation, separation);
}

const AdhesiveSolution& AdhesiveBemSolver::solve(Real mean_pressure) {
  if (!std::isfinite(mean_pressure))
    throw Error("adhesive BEM: the mean pressure must be finite, got " + std::to_string(mean_pressure));
  return solve_with(Control::load, mean_pressure);
}

Real AdhesiveBemSolver::update_attraction(const ContactSolution& contact) {
  const HeightMap& gap = contact.gap;
  const Index n = gap.size();
  if (law_.model == AdhesionModel::dugdale) {
    Index changed = 0;
    const Real reach = law_.reach();
    // A point outside contact is in the zone when its gap with half of its own attraction is below δc: the
    // same test whichever side it is on now (in, its gap holds all of its own pull, s = G_self σ0; out,
    // none), so a point cannot stay on either side only because it was there. Decided on the gap as it is, a
    // band of about s / (dg/dr) at the zone's edge keeps its last state, and the force carries that history:
    // 4 % of the pull-off at λ = 1, 40 pixels across the contact (tests/test_adhesive_bem.cpp).
    const Real half_own_pull = self_response_ * law_.stress / 2;
    for (Index i = 0; i < n; ++i) {
      unsigned char& flipped = flips_[static_cast<std::size_t>(i)];
      if (flipped >= kFlipsToEdge) continue;  // an edge point: half the stress, settled
      const Real own = attraction_.data()[i] > 0 ? half_own_pull : -half_own_pull;
      const bool in = contact.pressure.data()[i] > 0 || gap.data()[i] + own < reach;
      const Real a = in ? law_.stress : 0;
      if (a == attraction_.data()[i]) continue;
      ++changed;
      attraction_.data()[i] = ++flipped >= kFlipsToEdge ? law_.stress / 2 : a;
    }
    return static_cast<Real>(changed);
  }
  Real change = 0;
  const Real peak = law_.peak_stress();
  for (Index i = 0; i < n; ++i)
    change = std::max(change, std::abs(law_.attraction(gap.data()[i]) - attraction_.data()[i]) / peak);
  // Under-relaxed where the plain fixed point overshoots (the change grew), relaxed again while it falls.
  if (last_change_ > 0 && change > last_change_)
    relaxation_ = std::max(relaxation_ / 2, kSmallestRelaxation);
  else if (last_change_ > 0)
    relaxation_ = std::min(relaxation_ * 1.25, 1.0);
  last_change_ = change;
  for (Index i = 0; i < n; ++i) {
    Real& a = attraction_.data()[i];
    a += relaxation_ * (law_.attraction(gap.data()[i]) - a);
  }
  return change;
}

const AdhesiveSolution& AdhesiveBemSolver::solve_whole(Control control, Real value) {
  const auto start = std::chrono::steady_clock::now();
  const BemSolverOptions& options = options_.contact;
  const HeightMap& h = surface_.heights();
  const bool load = control == Control::load;
  AdhesiveSolution& s = solution_;
  s = AdhesiveSolution{};
  HeightMap gap;
  if (warm_ && whole_gap_.size() == h.size()) {
    gap = whole_gap_;
  } else if (load && value > 0) {
    // The fixed point's own first solve, so that both methods leave from the same state: the non-adhesive
    // contact at the load.
    engine_->forget();
    engine_->set_heights(h);
    const SolveOutcome o = engine_->solve_load(value, std::numeric_limits<Real>::infinity(),
                                               options.tolerance, options.max_iterations, false);
    ContactSolution contact;
    engine_->write(contact);
    gap = contact.gap;
    s.iterations += o.iterations;
    s.outer_iterations = 1;
  } else {
    // The rigid flat: touching the highest point (a tensile load), or at the separation (the solver's
    // projection then holds the mean gap).
    gap = load ? HeightMap(h.maxCoeff() - h) : HeightMap(value - h);
  }
  const LbfgsOutcome r =
      whole_->solve(load, value, residual_bound(options.tolerance), options.max_iterations, gap);
  s.iterations += r.evaluations;
  s.cg_iterations = r.iterations;
  s.separated = r.separated;
  s.residual = r.residual;
  s.attraction_change = r.residual;
  s.traction = whole_->traction();
  HeightMap attraction = gap.unaryExpr([&](Real g) { return law_.attraction(g); });
  // The repulsive pressure: what holds a point at g = 0 against the traction and the attraction.
  s.pressure = (gap == 0).select((s.traction + attraction).max(0), 0.0);
  s.gap = gap;
  s.separation = gap.mean();  // periodic: the separation is the mean gap
  s.repulsive_pressure = s.pressure.mean();
  s.adhesive_pressure = attraction.mean();
  s.mean_pressure = whole_->mean_traction();
  s.mean_gap = s.separation;
  ContactSolution contact;
  contact.pressure = s.pressure;
  contact.gap = gap;
  describe(contact, attraction);
  s.converged = r.converged && !r.separated;
  warm_ = !s.separated;
  whole_gap_ = gap;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!s.converged && !s.separated && options.warning) {
    std::ostringstream text;
    text << "adhesive BEM (projected_lbfgs) did not converge at " << (load ? "P/A0 = " : "separation = ")
         << value << " after " << r.iterations << " steps (force imbalance " << r.residual
         << " of the peak stress); the result is marked converged = false";
    options.warning(text.str());
  }
  return s;
}

const AdhesiveSolution& AdhesiveBemSolver::solve_with(Control control, Real value) {
  if (whole_) return solve_whole(control, value);
  const auto start = std::chrono::steady_clock::now();
  const BemSolverOptions& options = options_.contact;
  const HeightMap& h = surface_.heights();
  const Real infinite = std::numeric_limits<Real>::infinity();
  if (!warm_) {
    attraction_.setZero();
    engine_->forget();
  }
  relaxation_ = 1;
  last_change_ = 0;
  flips_.assign(static_cast<std::size_t>(h.size()), 0);
  AdhesiveSolution& s = solution_;
  s = AdhesiveSolution{};
  const bool whole_surface_cg =
      options_.method == AdhesiveMethod::constrained_cg;  // Dugdale (refused otherwise)
  ContactSolution contact;
  HeightMap used;  // the attraction of the last contact solve
  bool contact_converged = true, settled = false;
  for (Index outer = 0; outer < options_.max_outer_iterations && !settled; ++outer) {
    half_space_->apply(attraction_, lift_);
    effective_heights_ = h + lift_;
    engine_->set_heights(effective_heights_);
    used = attraction_;
    SolveOutcome o;
    o.converged = true;
    if (control == Control::load) {
      const Real repulsive = value + attraction_.mean();
      if (!(repulsive > 0)) {  // the attraction of this state cannot hold the load with any contact
        s.separated = true;
        break;
      }
      o = engine_->solve_load(repulsive, infinite, options.tolerance, options.max_iterations, false);
      engine_->write(contact);
      contact.separation = engine_->separation();
    } else if (value >= effective_heights_.maxCoeff()) {
      // The flat above every point of the lifted surface: no contact, p = 0 meets every condition.
      contact.pressure = HeightMap::Zero(h.rows(), h.cols());
      contact.gap = value - effective_heights_.array();
      contact.separation = value;
      contact.residual = 0;
      engine_->forget();
    } else {
      o = engine_->solve_separation(value, infinite, options.tolerance, options.max_iterations);
      engine_->write(contact);
      contact.separation = value;
    }
    s.iterations += o.iterations;
    ++s.outer_iterations;
    contact_converged = o.converged && contact.residual <= residual_bound(options.tolerance);
    s.attraction_change = update_attraction(contact);
    settled = law_.model == AdhesionModel::dugdale ? s.attraction_change == 0
                                                   : s.attraction_change <= residual_bound(options.tolerance);
    if (whole_surface_cg && outer == 0 && !settled) {
      // After the first contact solve (the fixed point's own start, so both methods leave from the same
      // state), the whole-surface CG moves the zone to where it settles; the contact solver starts from its
      // pressure, and the outer iterations that follow check and settle it.
      HeightMap pressure = contact.pressure;
      s.cg_iterations =
          solve_dugdale_constrained_cg(*half_space_, h, law_, control == Control::load, value,
                                       kWholeSurfaceTolerance, options.max_iterations, pressure, attraction_)
              .iterations;
      if (pressure.maxCoeff() > 0) engine_->start_from(pressure);
    }
  }
  warm_ = !s.separated;
  if (s.outer_iterations > 0 && contact.pressure.size() > 0) {
    s.traction = contact.pressure - used;
    s.pressure = contact.pressure;
    s.gap = contact.gap;
    s.separation = contact.separation;
    s.residual = contact.residual;
    s.repulsive_pressure = contact.pressure.mean();
    s.adhesive_pressure = used.mean();
    s.mean_pressure = s.repulsive_pressure - s.adhesive_pressure;
    s.mean_gap = contact.gap.mean();
    describe(contact, used);
  }
  s.converged = settled && contact_converged && !s.separated;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!s.converged && !s.separated && options.warning) {
    std::ostringstream text;
    text << "adhesive BEM did not converge at " << (control == Control::load ? "P/A0 = " : "separation = ")
         << value << " after " << s.outer_iterations << " outer iterations (last change of the attraction "
         << s.attraction_change << "); the result is marked converged = false";
    options.warning(text.str());
  }
  return s;
}

Real AdhesiveBemSolver::energy() const {
  const AdhesiveSolution& s = solution_;
  if (s.traction.size() == 0) return 0;
  HeightMap displacement = s.gap.array() - s.separation + surface_.heights().array();
  if (surface_.grid().periodic) displacement.array() -= displacement.mean();
  const Real elastic = 0.5 * (s.traction.array() * displacement.array()).mean();
  Real potential = 0;
  const Index n = s.gap.size();
  for (Index i = 0; i < n; ++i) {
    const Real g = s.gap.data()[i];
    if (law_.model == AdhesionModel::dugdale) {
      const Real pull = s.pressure.data()[i] - s.traction.data()[i];
      potential -= pull * (law_.reach() - g);
    } else {
      potential -= law_.work * std::exp(-g / law_.range);
    }
  }
  return elastic + potential / static_cast<Real>(n);
}

ContactSolution AdhesiveSolution::contact() const {
  ContactSolution s;
  s.pressure = pressure;
  s.gap = gap;
  s.mean_pressure = mean_pressure;
  s.separation = separation;
  s.contact_points = contact_points;
  s.iterations = iterations;
  s.change = attraction_change;
  s.residual = residual;
  s.converged = converged;
  s.seconds = seconds;
  return s;
}

void AdhesiveBemSolver::describe(const ContactSolution& contact, const HeightMap& attraction) {
  AdhesiveSolution& s = solution_;
  const Grid& grid = surface_.grid();
  const Index nx = grid.nx, ny = grid.ny;
  const Real reach = law_.reach();
  auto in_contact = [&](Index y, Index x) { return contact.pressure(y, x) > 0; };
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      if (!in_contact(y, x)) {
        s.attractive_points +=
            law_.model == AdhesionModel::dugdale ? attraction(y, x) > 0 : contact.gap(y, x) < reach;
        continue;
      }
      ++s.contact_points;
      // A neighbour out of contact (off the grid counts as out when the surface does not repeat).
      bool edge = false;
      const Index ys[2] = {y - 1, y + 1}, xs[2] = {x - 1, x + 1};
      for (int k = 0; k < 2 && !edge; ++k) {
        Index yy = ys[k], xx = xs[k];
        if (grid.periodic) {
          yy = (yy + ny) % ny;
          xx = (xx + nx) % nx;
        }
        edge = (yy < 0 || yy >= ny || !in_contact(yy, x)) || (xx < 0 || xx >= nx || !in_contact(y, xx));
      }
      s.edge_points += edge;
    }
  s.zone_pixels = s.edge_points > 0
                      ? static_cast<Real>(s.attractive_points) / static_cast<Real>(s.edge_points)
                      : std::numeric_limits<Real>::quiet_NaN();
}

}  // namespace contactbench

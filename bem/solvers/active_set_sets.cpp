#include "contactbench/bem/solvers/active_set_method.hpp"

namespace contactbench {

using namespace active_set_tuning;

// The sets of the bearing area (the limit of a very soft contact), with the current displacement: the m
// nodes the flat penetrates deepest (largest h - u) plastic, m the most whose pressure H stays below the
// load (none without a hardness), and the next (or those tied with it) elastic with the rest of the load.
template <class T>
void ActiveSet<T>::reseat(std::vector<T>& p, double total) {
  const double most = std::isfinite(static_cast<double>(cap_)) ? std::ceil(total / cap_) - 1 : 0.0;
  const std::size_t m = static_cast<std::size_t>(std::clamp(most, 0.0, static_cast<double>(n_ - 1)));
  operator_->apply(p.data(), u_.data());
  std::vector<T> ranked(n_);  // the depths h - u, partly sorted
  for (std::size_t k = 0; k < n_; ++k)
    ranked[k] = h_[k] - u_[k];
  std::nth_element(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(m), ranked.end(),
                   std::greater<>());
  const T level = ranked[m];
  for (std::size_t k = 0; k < n_; ++k) {
    const T depth = h_[k] - u_[k];  // as ranked: the same operation on the same values
    plastic_[k] = depth > level;
    in_[k] = depth == level;
    weights_current_ = false;
    p[k] = plastic_[k] ? cap_ : T(in_[k] ? 1 : 0);
  }
  displacement_current_ = displacement_fresh_ = false;
}

// u += G dp for the changes of p that the last pass recorded with keep_to_sets (at most kFewChanges in
// all; each thread's first ones, in sums_[thread].c): dp_k times G's column k, the response to a unit
// pressure at node 0 (response_) shifted to node k (wrapped when periodic; mirrored otherwise: the
// half-space's response depends on |dx| and |dy| only). u stays current, not fresh.
template <class T>
void ActiveSet<T>::add_columns() {
  if (response_.empty()) {  // made on first use (the constructor's comment says why)
    response_.assign(n_, T(0));
    std::vector<T> unit(n_, T(0));
    unit[0] = T(1);
    operator_->apply(unit.data(), response_.data());
  }
  std::vector<Change> all;
  for (std::size_t thread = 0; thread < sums_.size(); ++thread)
    for (std::size_t i = 0; i < static_cast<std::size_t>(sums_[thread].c); ++i)
      all.push_back(changes_[thread][i]);
  const Index nx = grid_.nx, ny = grid_.ny;
  const bool periodic = grid_.periodic;
#pragma omp parallel for num_threads(team()) schedule(static)
  for (Index y = 0; y < ny; ++y) {
    T* const row = u_.data() + y * nx;
    for (const Change& change : all) {
      const Index ky = static_cast<Index>(change.node) / nx, kx = static_cast<Index>(change.node) % nx;
      const Index dy = periodic ? (y - ky + ny) % ny : std::abs(y - ky);
      const T* const column = response_.data() + dy * nx;
      const T dp = static_cast<T>(change.dp);
      if (periodic) {
        for (Index x = kx; x < nx; ++x)
          row[x] += dp * column[x - kx];
        for (Index x = 0; x < kx; ++x)
          row[x] += dp * column[x - kx + nx];
      } else {
        for (Index x = kx; x < nx; ++x)
          row[x] += dp * column[x - kx];
        for (Index x = 0; x < kx; ++x)
          row[x] += dp * column[kx - x];
      }
    }
  }
  displacement_fresh_ = false;
}

// After the set update: its flips join those pending, or the weights are to be made afresh.
template <class T>
void ActiveSet<T>::note_flips() {
  if (!weights_current_) return;
  std::size_t total = pending_flips_.size();
  for (const auto& log : flips_)
    total += log.size();
  if (total > few_flips()) {
    weights_current_ = false;
    pending_flips_.clear();
    return;
  }
  for (const auto& log : flips_)
    pending_flips_.insert(pending_flips_.end(), log.begin(), log.end());
}

// p off the plastic set times `factor`; G p is no longer current.
template <class T>
void ActiveSet<T>::scale_pressure(std::vector<T>& p, double factor) {
  over_points([&](std::size_t begin, std::size_t end, Sums&) {
    for (std::size_t k = begin; k < end; ++k)
      if (!plastic_[k]) p[k] = static_cast<T>(factor * static_cast<double>(p[k]));
  });
  displacement_current_ = false;
}

// The pressures off the plastic set scaled so that the sum of p is `total` (the plastic nodes at H);
// false, and nothing changed, when the plastic nodes alone carry `total` or more.
template <class T>
bool ActiveSet<T>::scale_to(std::vector<T>& p, double total) {
  const Sums s = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k)
      if (plastic_[k])
        part.g += static_cast<double>(cap_);
      else
        part.a += static_cast<double>(p[k]);
  });
  double factor = 1;
  if (!load_scale(s.a, s.g, total, factor)) return false;
  // Without plastic nodes G p scales with p; with them only the elastic nodes' share does.
  if (displacement_current_ && s.g == 0)
    scale_with_displacement(p, factor);
  else
    scale_pressure(p, factor);
  return true;
}

// p and u = G p (no plastic nodes) times `factor`: u stays G p, as fresh as before to one rounding.
template <class T>
void ActiveSet<T>::scale_with_displacement(std::vector<T>& p, double factor) {
  over_points([&](std::size_t begin, std::size_t end, Sums&) {
    for (std::size_t k = begin; k < end; ++k) {
      p[k] = static_cast<T>(factor * static_cast<double>(p[k]));
      u_[k] = static_cast<T>(factor * static_cast<double>(u_[k]));
    }
  });
}

// One set update (solve's comment says the rule) with p held to the new sets; e: the largest |g| on the
// elastic set before it, d: its nodes above the hardness, h: the nodes that changed set.
template <class T>
typename ActiveSet<T>::Sums ActiveSet<T>::update_sets(std::vector<T>& p, double d, double limit, double entry,
                                                      bool capping) {
  for (auto& log : flips_)
    log.clear();
  // The pass with the arrays and the sums in locals: p's stores could alias the sums (both double in
  // double precision) and the members' pointers, which kept both in memory, reloaded and stored again at
  // every node (a profile of the 1024^2 `bem` command: about 4 % of its samples in this pass). The same
  // operations in the same order as keep_to_sets's (results bit-identical).
  const Sums update = over_points([&, d, limit, entry](std::size_t begin, std::size_t end, Sums& part) {
    const T* const u = u_.data();
    const T* const h = h_.data();
    T* const pp = p.data();
    std::uint8_t* const in = in_.data();
    std::uint8_t* const plastic_set = plastic_.data();
    const T cap = cap_;
    auto& changes = changes_[static_cast<std::size_t>(omp_get_thread_num())];
    double largest = part.e, above = 0, changed_sets = 0;                               // e, d, h
    double changed_pressures = 0, elastic_sum = 0, elastic_nodes = 0, plastic_sum = 0;  // c, a, b, g
    for (std::size_t k = begin; k < end; ++k) {
      const double g = d + static_cast<double>(u[k]) - static_cast<double>(h[k]);
      const T before = pp[k];
      bool elastic = in[k], plastic = plastic_set[k];
      if (elastic) {
        largest = std::max(largest, std::abs(g));
        above += before > cap ? 1.0 : 0.0;
        elastic = before >= 0 && (before <= cap || !capping);
        plastic = before > cap && capping;
      } else if (plastic) {
        plastic = g <= limit;
        elastic = !plastic;
      } else {
        elastic = g < -entry;
      }
      if (elastic != static_cast<bool>(in[k]) || plastic != static_cast<bool>(plastic_set[k])) {
        if (elastic != static_cast<bool>(in[k])) log_flip(k, elastic);
        in[k] = elastic;
        plastic_set[k] = plastic;
        changed_sets += 1;
      }
      // p held to the sets (keep_to_sets), for the next outer step or the output's clipping below.
      const T held = plastic ? cap : (elastic ? before : T(0));
      if (held != before) {  // stored only when changed: most nodes keep p = 0, their memory untouched
        pp[k] = held;
        changed_pressures += 1;
        if (changed_pressures <= kFewChanges)  // the first few of each thread, for add_columns
          changes[static_cast<std::size_t>(changed_pressures) - 1] = {
              k, static_cast<double>(held) - static_cast<double>(before)};
      }
      elastic_sum += elastic ? static_cast<double>(held) : 0.0;
      elastic_nodes += elastic;
      plastic_sum += plastic ? static_cast<double>(cap) : 0.0;
    }
    part.e = largest;
    part.d += above;
    part.h += changed_sets;
    part.c += changed_pressures;
    part.a += elastic_sum;
    part.b += elastic_nodes;
    part.g += plastic_sum;
  });
  note_flips();
  return update;
}

template typename ActiveSet<double>::Sums ActiveSet<double>::update_sets(std::vector<double>&, double, double,
                                                                         double, bool);
template typename ActiveSet<float>::Sums ActiveSet<float>::update_sets(std::vector<float>&, double, double,
                                                                       double, bool);
template void ActiveSet<double>::reseat(std::vector<double>& p, double total);
template void ActiveSet<float>::reseat(std::vector<float>& p, double total);
template void ActiveSet<double>::add_columns();
template void ActiveSet<float>::add_columns();
template void ActiveSet<double>::note_flips();
template void ActiveSet<float>::note_flips();
template void ActiveSet<double>::scale_pressure(std::vector<double>& p, double factor);
template void ActiveSet<float>::scale_pressure(std::vector<float>& p, double factor);
template bool ActiveSet<double>::scale_to(std::vector<double>& p, double total);
template bool ActiveSet<float>::scale_to(std::vector<float>& p, double total);
template void ActiveSet<double>::scale_with_displacement(std::vector<double>& p, double factor);
template void ActiveSet<float>::scale_with_displacement(std::vector<float>& p, double factor);

}  // namespace contactbench

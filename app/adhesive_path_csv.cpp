#include "contactbench/app/adhesive_path_csv.hpp"

#include "contactbench/app/json_writer.hpp"

namespace contactbench {

void write_adhesive_path_csv(std::ostream& out, const AdhesivePath& path, Real modulus, Index points,
                             const std::string& what, const Provenance& provenance) {
  const auto number = [](Real value) { return json_number(value); };
  const auto fraction = [&](Index count) {
    return number(static_cast<Real>(count) / static_cast<Real>(points));
  };
  out << "# " << what << " (commit " << provenance.commit << ", " << provenance.date << ", "
      << threads_text(provenance) << ", " << provenance.machine << "): " << provenance.command << '\n'
      << "# separation d [m] of the flat (docs/solvers.md \"Separation control\"); load = net P/(E* A0), "
         "negative when tensile; energy U per nominal area [J/m^2] (docs/theory.md 10.7)\n";
  out << "# pull_off_load = " << number(path.pull_off_pressure / modulus)
      << ", at separation = " << number(path.pull_off_separation)
      << (path.pull_off_located ? " (located between two samples of the retract branch)"
                                : " (the least sample of the retract leg: its minimum is not bracketed)")
      << '\n';
  out << "# cycle work -oint P/A0 dd = " << number(path.cycle_work)
      << " J/m^2; released by the jumps = " << number(path.released_energy) << " J/m^2\n";
  for (const AdhesiveJump& jump : path.jumps)
    out << "# jump " << (jump.into_contact ? "into" : "out of") << " contact between separation "
        << number(jump.separation_before) << " and " << number(jump.separation_after) << ": load "
        << number(jump.mean_pressure_before / modulus) << " -> " << number(jump.mean_pressure_after / modulus)
        << ", contact_fraction " << fraction(jump.contact_points_before) << " -> "
        << fraction(jump.contact_points_after) << ", released " << number(jump.released_energy) << " J/m^2\n";
  if (!path.converged) out << "# NOT CONVERGED: some states did not converge (converged = 0)\n";
  out << kAdhesivePathColumns << '\n';
  for (const AdhesivePathState& s : path.states)
    out << (s.approaching ? "approach" : "retract") << ',' << number(s.separation) << ','
        << number(s.mean_pressure / modulus) << ',' << number(s.adhesive_pressure / modulus) << ','
        << fraction(s.contact_points) << ',' << fraction(s.attractive_points) << ',' << number(s.mean_gap)
        << ',' << number(s.energy) << ',' << s.iterations << ',' << (s.converged ? 1 : 0) << '\n';
}

}  // namespace contactbench

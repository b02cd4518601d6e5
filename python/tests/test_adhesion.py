"""Adhesion from Python (BemSolver(..., adhesion={...})): the CLI's numbers (`contactbench bem --adhesion`),
the non-adhesive answer as the work of adhesion goes to 0, and bad laws refused naming the key."""
import csv
import io

import numpy as np
import pytest

import contactbench as cb

MODULUS = 100e9 / (1 - 0.3**2)  # the CLI's default E* [Pa]
# A sphere of radius R = 1 mm on 64 x 64 pixels of 3.1 um, not periodic: at the loads below the Hertz contact
# radius is 5-9 pixels. Dugdale with delta_c = w/sigma0 = 0.5 um, whose attractive zone is resolved here (9-12
# pixels wide at the contact edge, measured; Maugis' lambda 6e-3, the DMT end).
SIZE, POINTS, RADIUS = 2e-4, 64, 1e-3
DUGDALE = {"model": "dugdale", "work": 0.5, "stress": 1e6}
LOADS = [2e-4, 5e-4]


def sphere():
    x = (np.arange(POINTS) - POINTS / 2) * (SIZE / POINTS)
    heights = -(x[None, :] ** 2 + x[:, None] ** 2) / (2 * RADIUS)
    return cb.Surface(np.ascontiguousarray(heights), lx=SIZE, periodic=False)


def test_equals_the_cli(cli, tmp_path):
    surface = sphere()
    surface.write(tmp_path / "sphere.txt")
    text = cli("bem", tmp_path / "sphere.txt", "--loads", ",".join(map(str, LOADS)), "--adhesion",
               "dugdale,work=0.5,stress=1e6")
    rows = list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))
    results = cb.BemSolver(surface, MODULUS, adhesion=DUGDALE).solve_loads(LOADS)
    assert len(rows) == len(results) == len(LOADS)
    for row, result in zip(rows, results):
        # Same engine, same inputs, same order: the same iterations and outer iterations; areas and the
        # adhesive quantities to 1e-12 (the CSV prints 17 digits).
        assert result.iterations == int(row["iterations"])
        assert result.outer_iterations == int(float(row["outer_iterations"]))
        assert result.area_fraction == pytest.approx(float(row["area_fraction_nodes"]), abs=1e-12)
        assert result.area_fraction_corrected == pytest.approx(float(row["area_fraction_corrected"]), abs=1e-12)
        assert result.attractive_fraction == pytest.approx(float(row["attractive_fraction"]), abs=1e-12)
        assert result.adhesive_load == pytest.approx(float(row["adhesive_load"]), rel=1e-12)
        assert result.zone_pixels == pytest.approx(float(row["zone_pixels"]), rel=1e-12)
        assert result.converged and not result.separated
        # The attraction is there: it pulls (so the repulsive load, load + adhesive_load, exceeds the load)
        # and a zone outside contact is attracted.
        assert result.adhesive_load > 0 and result.attractive_fraction > 0 and result.zone_pixels >= 5


@pytest.mark.parametrize("law", [{"model": "exponential", "work": 1e-9, "range": 1e-9},
                                 {"model": "dugdale", "work": 1e-12, "stress": 1e-3}])
def test_vanishing_work_gives_the_non_adhesive_answer(law):
    surface = sphere()
    plain = cb.BemSolver(surface, MODULUS).solve_loads(LOADS)
    weak = cb.BemSolver(surface, MODULUS, adhesion=law).solve_loads(LOADS)
    for a, b in zip(weak, plain):
        # Peak attraction 1 Pa (exponential) or 1e-3 Pa (Dugdale) against mean pressures of 2e7-6e7 Pa: the
        # answer moves by the pull alone (measured: max pressure 1e-9 relative, separation 1e-11, as
        # adhesive_load/load). 1e-6 is what the solver's tolerance (1e-8 on the pressure change) guarantees
        # of the separation and peak; a law that did not vanish with w (an attraction left at the contact
        # edge) moves them by far more. The node count of the contact set is the same.
        assert a.adhesive_load < 1e-7 * a.load
        assert a.contact_points == b.contact_points
        assert a.separation == pytest.approx(b.separation, rel=1e-6)
        assert a.max_pressure == pytest.approx(b.max_pressure, rel=1e-6)
        assert a.converged
    assert plain[0].adhesive_load is None and plain[0].outer_iterations is None


def test_separation_control_with_adhesion():
    solver = cb.BemSolver(sphere(), MODULUS, adhesion=DUGDALE)
    by_load = solver.solve(5e-4)
    by_separation = cb.BemSolver(sphere(), MODULUS, adhesion=DUGDALE).solve_for_separation(by_load.separation)
    # One adhesive state, found by its load or by its separation: the load back to the outer fixed point's
    # accuracy (measured 4e-11 relative; 1e-5 leaves a margin for the Dugdale zone's discrete rule).
    assert by_separation.load == pytest.approx(by_load.load, rel=1e-5)
    assert by_separation.contact_points == by_load.contact_points
    assert solver.adhesion == DUGDALE


@pytest.mark.parametrize("law, named", [
    ({"model": "dugdale", "work": 0.05, "range": 1e-9}, "adhesion.range"),  # range is exponential's
    ({"model": "coulomb", "work": 0.05}, "adhesion.model"),
    ({"work": 0.05, "stress": 1e7}, "adhesion.model"),
    ({"model": "dugdale", "work": -0.05, "stress": 1e7}, "adhesion.work"),
    ({"model": "exponential", "work": 0.05, "range": float("nan")}, "adhesion.range"),
    ({"model": "dugdale", "work": 0.05}, "adhesion.stress"),
    ({"model": "dugdale", "work": "much", "stress": 1e7}, "adhesion.work"),
    ("dugdale,work=0.05,stress=1e7", "adhesion"),
])
def test_bad_laws_are_refused_naming_the_key(law, named):
    with pytest.raises(cb.Error, match=named.replace(".", r"\.")):
        cb.BemSolver(sphere(), MODULUS, adhesion=law)


@pytest.mark.parametrize("law, adhesive_solver, named", [
    ({"model": "exponential", "work": 0.05, "range": 1e-6}, "constrained_cg", "constrained_cg"),
    (DUGDALE, "projected_lbfgs", "projected_lbfgs"),
])
def test_an_adhesive_solver_that_cannot_take_the_law_is_refused(law, adhesive_solver, named):
    # Refused by name before any solve, never run as another solver (the law and the accepted values named).
    with pytest.raises(cb.Error, match=named) as error:
        cb.BemSolver(sphere(), MODULUS, adhesion=law,
                     adhesive_solver=adhesive_solver)
    assert law["model"] in str(error.value) and "fixed_point" in str(error.value)


def test_unknown_key_is_named():
    with pytest.raises(cb.Error, match="range") as error:
        cb.BemSolver(sphere(), MODULUS, adhesion={"model": "dugdale", "work": 0.05, "stress": 1e7, "range": 1})
    assert "stress" in str(error.value)  # the accepted keys are listed


def test_adhesion_with_a_hardness_is_refused():
    with pytest.raises(cb.Error, match="adhesion and a hardness"):
        cb.BemSolver(sphere(), MODULUS, hardness=1e9, adhesion=DUGDALE)


def test_approach_retract_equals_the_cli(cli, tmp_path):
    # The sphere's apex is 3.33 um above the mean plane: from 3.4 um down to 3.2 um (an indentation of 0.13
    # um) and back, 10 steps a leg.
    surface = sphere()
    surface.write(tmp_path / "sphere.txt")
    text = cli("bem", tmp_path / "sphere.txt", "--adhesion", "dugdale,work=0.5,stress=1e6", "--approach-retract",
               "3.4e-6,3.2e-6,10")
    rows = list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))
    path = cb.BemSolver(surface, MODULUS, adhesion=DUGDALE).approach_retract(3.4e-6, 3.2e-6, 10)
    assert len(rows) == len(path.load) == 21
    # Same engine, same path: the same states to 1e-12 (the CSV prints 17 digits) and the same iterations.
    assert [r["leg"] == "approach" for r in rows] == list(path.approaching)
    assert [int(r["iterations"]) for r in rows] == list(path.iterations)
    for column in ["separation", "load", "adhesive_load", "contact_fraction", "attractive_fraction", "energy"]:
        expected = np.array([float(r[column]) for r in rows])
        assert getattr(path, column) == pytest.approx(expected, rel=1e-12, abs=1e-300), column
    assert path.converged and all(path.state_converged)
    # In contact at the turn, out of it at both ends, and pulled (tensile) just out of contact.
    assert path.contact_fraction[10] > 0 and path.contact_fraction[0] == path.contact_fraction[-1] == 0
    assert path.pull_off_load < 0
    # Located between two samples, the pull-off is at least as tensile as every sample and is reached by
    # solves of its own; not bracketed, it is the least sample itself.
    if path.pull_off_located:
        assert path.pull_off_load <= min(path.load) and path.pull_off_solves > 0
    else:
        assert path.pull_off_load == pytest.approx(min(path.load), rel=1e-15) and path.pull_off_solves == 0


def test_approach_retract_needs_adhesion_and_a_path():
    with pytest.raises(cb.Error, match="needs adhesion"):
        cb.BemSolver(sphere(), MODULUS).approach_retract(3.4e-6, 3.2e-6, 10)
    with pytest.raises(cb.Error, match="turn < start"):
        cb.BemSolver(sphere(), MODULUS, adhesion=DUGDALE).approach_retract(3.2e-6, 3.4e-6, 10)
    with pytest.raises(cb.Error, match="steps"):
        cb.BemSolver(sphere(), MODULUS, adhesion=DUGDALE).approach_retract(3.4e-6, 3.2e-6, 1)

"""The plastic BEM from Python (BemSolver(..., hardness=H)): the CLI's numbers (`contactbench bem --hardness`),
the elastic answer when the cap is above the largest elastic pressure, the load path up and down against a
scene's (`loads.path = "as listed"`, its residual topography), and bad hardnesses refused naming the key."""
import csv
import io

import numpy as np
import pytest

import contactbench as cb

MODULUS = 100e9 / (1 - 0.3**2)  # the CLI's default E* [Pa]
# A sphere of radius R = 1 mm on 64 x 64 pixels of 3.1 um, not periodic, and H/E* = 0.01: Hertz's peak
# pressure p0 = (6 P E*^2 / (pi^3 R^2))^(1/3) reaches H at P/(E* A0) = 1.9e-5, so at the loads below (10 to 40
# times that) a core of the contact is plastic (measured: 25 to 35 % of the contact nodes).
SIZE, POINTS, RADIUS = 2e-4, 64, 1e-3
HARDNESS = 0.01 * MODULUS
LOADS = [2e-4, 5e-4, 8e-4]


def sphere():
    x = (np.arange(POINTS) - POINTS / 2) * (SIZE / POINTS)
    heights = -(x[None, :] ** 2 + x[:, None] ** 2) / (2 * RADIUS)
    return cb.Surface(np.ascontiguousarray(heights), lx=SIZE, periodic=False)


def rough(seed=3):
    """A periodic self-affine 64^2 surface (H = 0.8), rough enough that its tallest summits yield."""
    grid = cb.Grid(nx=64, ny=64, lx=1e-4, ly=1e-4, periodic=True)
    psd = cb.SelfAffinePsd(sigma=0.5e-6, hurst=0.8, qr=2 * np.pi / 2.5e-5)
    return cb.generate_surface(grid, psd, seed)


def csv_rows(text):
    return list(csv.DictReader(io.StringIO("\n".join(l for l in text.splitlines() if not l.startswith("#")))))


@pytest.mark.parametrize("solver", ["active_set", "polonsky_keer", "preconditioned_cg"])
def test_equals_the_cli(cli, tmp_path, solver):
    surface = sphere()
    surface.write(tmp_path / "sphere.txt")
    text = cli("bem", tmp_path / "sphere.txt", "--loads", ",".join(map(str, LOADS)), "--hardness", repr(HARDNESS),
               "--solver", solver, "--boundary", "as_is",  # the solver below solves the record as is
               "--threads", "1")  # one thread as the solver below: the same sums
    rows = csv_rows(text)
    results = cb.BemSolver(surface, MODULUS, hardness=HARDNESS, solver=solver).solve_loads(LOADS)
    assert len(rows) == len(results) == len(LOADS)
    for row, result in zip(rows, results):
        # Same engine, same inputs, same order: the same iterations; the fractions to 1e-12 (the CSV prints 17
        # digits, and both are ratios of the same node counts).
        assert result.iterations == int(row["iterations"])
        assert result.area_fraction == pytest.approx(float(row["area_fraction_nodes"]), abs=1e-12)
        assert result.area_fraction_corrected == pytest.approx(float(row["area_fraction_corrected"]), abs=1e-12)
        assert result.plastic_area_fraction == pytest.approx(float(row["plastic_area_fraction"]), abs=1e-12)
        assert result.plastic_load_fraction == pytest.approx(float(row["plastic_load_fraction"]), abs=1e-12)
        assert result.converged
        # The cap is there and met: plastic nodes, none above H (the solver projects onto [0, H]).
        assert 0 < result.plastic_points < result.contact_points
        assert result.max_pressure <= HARDNESS * (1 + 1e-12)
        # H x plastic area is part of the load: the fraction lies in (0, 1).
        assert 0 < result.plastic_load_fraction < 1


@pytest.mark.parametrize("solver", ["active_set", "polonsky_keer", "preconditioned_cg"])
def test_a_hardness_above_the_largest_elastic_pressure_gives_the_elastic_answer(solver):
    surface = rough()
    elastic = cb.BemSolver(surface, MODULUS, solver=solver).solve_loads(LOADS)
    cap = 1.01 * max(r.max_pressure for r in elastic)
    capped = cb.BemSolver(surface, MODULUS, hardness=cap, solver=solver).solve_loads(LOADS)
    for a, b in zip(capped, elastic):
        assert a.plastic_points == 0 and a.plastic_area_fraction == 0 and a.plastic_load_fraction == 0
        assert a.contact_points == b.contact_points
        if solver == "active_set":
            # It carries the cap in its own iteration (a plastic set, empty here), whose warm start from the
            # load before differs from the elastic one's: the same solution to the solver's tolerance (1e-8 on
            # the relative pressure change; measured on three seeds at most 1.4e-9 of the peak pressure, and
            # 6e-12 on the separation). A cap that bit anywhere would move the peak by 1 %.
            assert np.max(np.abs(a.pressure - b.pressure)) <= 1e-8 * b.max_pressure
            assert a.separation == pytest.approx(b.separation, rel=1e-9)
        else:
            # The search on the flat's height never runs when the elastic peak is below H (docs/solvers.md
            # "Hardness"): the very same solves, so the same iterations and the same numbers to the last bit.
            assert a.iterations == b.iterations
            assert np.array_equal(a.pressure, b.pressure) and a.separation == b.separation
    assert elastic[0].plastic_area_fraction is None and elastic[0].plastic_load_fraction is None


PATH = [2e-4, 5e-4, 8e-4, 5e-4, 2e-4, 5e-4, 8e-4]


def test_the_path_equals_the_scene(cli, tmp_path):
    surface = rough()
    surface.write(tmp_path / "rough.txt")
    scene = tmp_path / "cycle.toml"
    scene.write_text(f"""name = "cycle"
[surface]
file = "rough.txt"
[material]
estar = {MODULUS!r}
[interface]
hardness = {HARDNESS!r}
[loads]
values = [{", ".join(map(repr, PATH))}]
path = "as listed"
[methods.bem]
residual_topography = "residual.txt"
""")
    cli("run", scene, "--out", tmp_path / "report", "--no-plots", "--threads", "1")
    rows = csv_rows((tmp_path / "report" / "bem_path.csv").read_text())
    path = cb.BemSolver(surface, MODULUS, hardness=HARDNESS).solve_path(PATH)
    assert len(rows) == len(path.results) == len(PATH)
    # Same engine, same surface, same steps: the columns to 1e-12 (17 digits printed; fractions of node counts,
    # separations of some 1e-7 m).
    for name, ours in [("load", path.load), ("direction", path.direction),
                       ("area_fraction", path.area_fraction_corrected), ("area_fraction_nodes", path.area_fraction),
                       ("plastic_area_fraction", path.plastic_area_fraction),
                       ("plastic_load_fraction", path.plastic_load_fraction)]:
        np.testing.assert_allclose(ours, [float(r[name]) for r in rows], rtol=0, atol=1e-12, err_msg=name)
    np.testing.assert_allclose(path.separation, [float(r["separation"]) for r in rows], rtol=1e-12, atol=0)
    assert path.converged and all(path.state_converged)
    assert list(path.direction) == [1, 1, 1, -1, -1, 1, 1]
    # The residual topography the scene wrote (lossless text) is the one the path left.
    written = cb.read_topography(tmp_path / "residual.txt")
    residual = path.residual_topography
    assert np.max(np.abs(written.heights - residual.heights)) <= 1e-12 * np.ptp(surface.heights)


def test_the_path_keeps_the_plastic_deformation():
    surface = rough()
    path = cb.BemSolver(surface, MODULUS, hardness=HARDNESS).solve_path(PATH)
    area = path.area_fraction
    # Unloading is the elastic response of the flattened summits: more area than the first loading at the same
    # load, and no node flows anew on the way down.
    assert area[4] > area[0] and area[3] > area[1]
    assert path.results[4].plastic_points == 0
    # Reloading to the top load gives the loaded state again (shakedown): the contact set to 1 % of its nodes,
    # what tests/test_bem_plastic_cycle.cpp asks of the C++ solver on surface A (nodes on the cap's edge may
    # settle either side of it at the solver's tolerance).
    assert area[6] == pytest.approx(area[2], rel=1e-2)
    # The residual surface lies nowhere above the given one (the flow only lowers heights) and is lowered
    # somewhere; the given surface is centred by the solver, the residual keeps that mean plane.
    given = surface.centred().heights
    lowered = given - path.residual_topography.heights
    assert lowered.min() >= -1e-15 * np.ptp(given) and lowered.max() > 0
    # Without a hardness the path is the elastic curve in the listed order: no residual topography, and
    # the same load gives the same area going up and down (no memory), to the solver's tolerance.
    elastic = cb.BemSolver(surface, MODULUS).solve_path(PATH)
    assert elastic.residual_topography is None
    assert elastic.area_fraction[4] == pytest.approx(elastic.area_fraction[0], abs=2 / 64**2)


@pytest.mark.parametrize("bad, words", [(-1e9, "hardness: "), (0.0, "hardness: "), (float("nan"), "hardness: "),
                                        (float("inf"), "hardness: "), ("hard", "hardness: wrong type"),
                                        (True, "hardness: wrong type")])
def test_bad_hardness_is_refused_naming_the_key(bad, words):
    with pytest.raises(cb.Error, match=words) as error:
        cb.BemSolver(sphere(), MODULUS, hardness=bad)
    assert "interface." not in str(error.value)  # the key as the caller wrote it


def test_a_load_at_or_above_the_hardness_is_refused_naming_it():
    solver = cb.BemSolver(sphere(), MODULUS, hardness=HARDNESS)
    for call in [lambda: solver.solve_loads([2e-4, 0.01, 0.02]), lambda: solver.solve_path([2e-4, 0.02, 2e-4]),
                 lambda: solver.solve(0.02)]:
        with pytest.raises(cb.Error, match=r"hardness: .*loads\[[0-9]\].*full plastic contact"):
            call()
    with pytest.raises(cb.Error, match="loads: .*path"):
        solver.solve_path([2e-4, -1.0])

"""Bad arguments raise clear Python exceptions with the C++ message; none crashes the interpreter."""
import math

import numpy as np
import pytest

import contactbench as cb


def surface():
    return cb.Surface(np.random.default_rng(0).normal(scale=1e-7, size=(16, 16)), lx=1e-5, periodic=True)


def test_negative_modulus():
    with pytest.raises(ValueError, match="modulus"):
        cb.BemSolver(surface(), -1e11)


@pytest.mark.parametrize("bad, what", [
    (np.zeros((4, 4), dtype=np.float32), "float32"),
    (np.zeros((4, 4), dtype=np.int64), "int64"),
    (np.zeros(16), "shape \\(16,\\)"),
    (np.zeros((2, 2, 2)), "shape \\(2, 2, 2\\)"),
    (np.zeros((8, 8))[:, ::2], "non-contiguous"),
    (np.zeros((8, 8)).T, "non-contiguous"),
    (np.zeros((0, 4)), "at least one point"),
    ([[0.0, 1.0]], "list"),
])
def test_heights_must_be_2d_c_contiguous_float64(bad, what):
    with pytest.raises(cb.Error, match=what):
        cb.Surface(bad, lx=1e-5)


def test_nan_height_is_named():
    heights = np.zeros((4, 5))
    heights[2, 3] = math.nan
    with pytest.raises(ValueError, match=r"\(ix, iy\) = \(3, 2\)"):
        cb.Surface(heights, lx=1e-5)


def test_bad_sizes_and_parameters():
    with pytest.raises(ValueError, match="lateral sizes"):
        cb.Surface(np.zeros((4, 4)), lx=-1.0)
    with pytest.raises(ValueError, match="hurst"):
        cb.generate_surface(cb.paper.grid(), cb.SelfAffinePsd(sigma=1e-6, hurst=1.5, qr=1e5))
    for call in [lambda: cb.surface_a(threads=0), lambda: cb.sweep(surface(), threads=-1),
                 lambda: cb.BemSolver(surface(), 1e11, threads=0), lambda: surface().moments(threads=2000)]:
        with pytest.raises(ValueError, match="threads"):
            call()
    with pytest.raises(ValueError, match="levels"):
        cb.sweep(surface(), levels="everything")
    with pytest.raises(ValueError, match="connectivity"):
        cb.sweep(surface(), connectivity=6)
    with pytest.raises(ValueError, match="load"):
        cb.BemSolver(surface(), 1e11).solve(-1.0)
    with pytest.raises(ValueError, match="ascending"):
        cb.BemSolver(surface(), 1e11).solve_loads([0.02, 0.01])
    with pytest.raises(ValueError, match="single precision"):
        cb.BemSolver(surface(), 1e11, tolerance=1e-9, precision="single")
    # The keywords are the scene's (app/methods/bem_settings.cpp), checked as a scene's are: a tolerance that
    # would stop far from the solution is refused, not passed off as converged.
    with pytest.raises(ValueError, match=r"tolerance: out of range: got 1; accepted: a number in \[1e-13, 0.01\]"):
        cb.BemSolver(surface(), 1e11, tolerance=1.0)
    with pytest.raises(ValueError, match="unknown keyword single_precision; accepted: tolerance"):
        cb.BemSolver(surface(), 1e11, single_precision=True)
    with pytest.raises(ValueError, match="solver: unknown choice \"multigrid\""):
        cb.BemSolver(surface(), 1e11, solver="multigrid")
    with pytest.raises(ValueError, match="max_iterations: wrong type"):
        cb.BemSolver(surface(), 1e11, max_iterations=2.5)
    with pytest.raises(ValueError):
        cb.persson_curve(surface().moments(), [0.02, 0.01])


def test_bad_file_names_file_and_line(tmp_path):
    path = tmp_path / "m.txt"
    path.write_text("1e-6 2e-6\n3e-6 oops\n")
    with pytest.raises(cb.InputError, match=r"m.txt:2:") as caught:
        cb.read_topography(path, lx=1e-5)
    assert isinstance(caught.value, OSError) and isinstance(caught.value, ValueError)
    assert caught.value.path == str(path) and caught.value.line == 2


def test_scene_errors_are_listed(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text('name = "bad"\nreference = "bem"\n[material]\nE = -1\nnu = 0.3\n')
    with pytest.raises(cb.SceneError) as caught:
        cb.read_scene(path)
    assert caught.value.problems and any("material" in p for p in caught.value.problems)

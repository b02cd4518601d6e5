"""Surfaces: numpy round trips, files, and the generator against the CLI's file (bit for bit)."""
import numpy as np
import pytest

import contactbench as cb


def test_numpy_round_trip_is_unchanged():
    rng = np.random.default_rng(5)
    heights = rng.normal(scale=1e-6, size=(24, 40))  # ny = 24 rows, nx = 40 columns
    surface = cb.Surface(heights, lx=4e-5, ly=3e-5, periodic=True)
    assert (surface.nx, surface.ny) == (40, 24)
    assert (surface.lx, surface.ly, surface.periodic) == (4e-5, 3e-5, True)
    back = surface.heights
    assert back.dtype == np.float64 and back.flags.c_contiguous and back.shape == heights.shape
    assert np.array_equal(back, heights)  # exact: no arithmetic on the way
    assert not back.flags.writeable  # a view of the immutable surface, not a copy
    assert np.shares_memory(back, surface.heights)


def test_square_pixels_by_default():
    surface = cb.Surface(np.zeros((10, 20)), lx=2e-5)
    assert surface.ly == pytest.approx(1e-5, rel=1e-15)
    assert surface.grid.dx == surface.grid.dy


def test_view_outlives_the_surface():
    heights = cb.Surface(np.arange(6.0).reshape(2, 3), lx=1.0).heights  # the surface object is gone
    assert np.array_equal(heights, np.arange(6.0).reshape(2, 3))


def test_file_round_trip_is_bit_for_bit(tmp_path):
    heights = np.random.default_rng(1).normal(scale=3e-7, size=(16, 12))
    surface = cb.Surface(heights, lx=1.2e-5, ly=1.6e-5, periodic=True)
    surface.write(tmp_path / "s.txt")
    back = cb.read_topography(tmp_path / "s.txt")
    assert np.array_equal(back.heights, heights)
    assert (back.lx, back.ly, back.periodic) == (1.2e-5, 1.6e-5, True)


def test_measured_file_orientation(source_dir):
    # matrix-4.txt is 75 points wide (x) and 305 high (y): rows of the array are y.
    surface = cb.read_topography(source_dir / "data/measured/matrix-4.txt")
    assert surface.heights.shape == (305, 75)
    assert not surface.periodic


@pytest.mark.parametrize("refine", [None, 48])
def test_generator_is_bit_identical_to_the_cli(cli, tmp_path, refine):
    psd = cb.SelfAffinePsd(sigma=2e-7, hurst=0.7, qr=2e5)
    grid = cb.Grid(nx=32, ny=24, lx=1e-4, ly=7.5e-5)
    args = ["generate", "--sigma", "2e-7", "--hurst", "0.7", "--qr", "2e5", "--size", "1e-4", "--size-y",
            "7.5e-5", "--grid", "32", "--grid-y", "24", "--seed", "12345678901234", "--out", tmp_path / "g.txt"]
    if refine:
        args += ["--refine", refine]
    cli(*args)
    from_cli = cb.read_topography(tmp_path / "g.txt")
    from_python = cb.generate_surface(grid, psd, 12345678901234, refine=refine, refine_y=None)
    assert from_python.heights.shape == from_cli.heights.shape
    assert np.array_equal(from_python.heights, from_cli.heights)  # bit for bit, not approximately
    assert (from_python.lx, from_python.ly, from_python.periodic) == (from_cli.lx, from_cli.ly, True)


def test_paper_surface_a_moments():
    surface = cb.surface_a(seed=1)
    assert surface.heights.shape == (256, 256) and surface.lx == 200e-6
    moments = surface.moments()
    # The generator normalises sigma on the lattice exactly: only round-off (1e-12) remains.
    assert moments.rms_height == pytest.approx(0.5e-6, rel=1e-12)
    # Isotropic PSD with deterministic moduli: m2x = m2y up to the lattice's symmetry, to round-off.
    assert moments.m2x == pytest.approx(moments.m2y, rel=1e-12)


def test_refine_keeps_the_nodes():
    coarse = cb.surface_a(seed=2)
    fine = cb.refine(coarse, 512)
    # Fourier interpolation keeps the original nodes to round-off of the FFTs: 1e-12 of sigma = 0.5 um.
    assert np.max(np.abs(fine.heights[::2, ::2] - coarse.heights)) < 1e-12 * 0.5e-6

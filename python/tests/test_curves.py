"""The sweep, the plateau model, the theories and a scene run from Python."""
import json

import numpy as np
import pytest

import contactbench as cb


def test_sweep_and_plateau_model():
    surface = cb.surface_a(seed=1)
    sweep = cb.sweep(surface, levels="paper")
    assert len(sweep) == 501 and sweep.z[0] == surface.heights.max()
    assert np.all(np.diff(sweep.z) < 0) and sweep.area_fraction[0] == 0 and sweep.spots[0] == 0
    assert sweep.points.dtype == np.int64
    # A_c = points / (nx ny) exactly (docs/theory.md section 3).
    assert np.array_equal(sweep.area_fraction, sweep.points / 65536)
    model = cb.plateau_model(sweep)
    curve = cb.plateau_curve_at_loads(sweep, model, [1e-3, 1e-2])
    assert curve.method == "plateau" and len(curve) == 2
    assert np.all(np.diff(curve.area_fraction) > 0)


@pytest.mark.parametrize("theory", [cb.gw_mccool_curve, cb.bgt_curve, cb.bgt_linear_curve, cb.persson_curve])
def test_theories_give_curves(theory):
    moments = cb.surface_a(seed=1).moments()
    curve = theory(moments, [1e-3, 1e-2, 3e-2])
    assert np.array_equal(curve.load, [1e-3, 1e-2, 3e-2]) or np.allclose(curve.load, [1e-3, 1e-2, 3e-2], rtol=1e-12)
    assert np.all(np.diff(curve.area_fraction) > 0) and np.all(curve.area_fraction <= 1)


def test_persson_is_erf():
    moments = cb.surface_a(seed=1).moments()
    m2 = (moments.m2x + moments.m2y) / 2
    from math import erf, sqrt
    curve = cb.persson_curve(moments, [0.01])
    assert curve.area_fraction[0] == pytest.approx(erf(0.01 / sqrt(m2)), rel=1e-14)


def test_run_a_scene_writes_the_cli_files(tmp_path):
    scene = tmp_path / "small.toml"
    scene.write_text("""name = "small"
reference = "bem"
[surface]
generate = { sigma = 1e-7, hurst = 0.8, qr = 1e5, size = 1e-4, grid = 64, seed = 2 }
[material]
E = 100e9
nu = 0.3
[loads]
values = [0.005, 0.02]
[methods.bem]
[methods.plateau]
[methods.persson]
""")
    report, comparison = cb.run(scene, out=tmp_path / "out", plots=False)
    assert [m.label for m in report.methods] == ["bem", "plateau", "persson"]
    assert report.scene.name == "small" and report.grid.nx == 64
    assert all(seconds >= 0 for _, seconds in report.stages) and report.stages
    bem = report.curves["bem"]
    assert np.array_equal(report.loads, [0.005, 0.02])
    assert len(bem.area_fraction) == 2
    assert "iterations" in report.methods[0].columns
    assert comparison.reference == "bem"
    assert np.all(comparison.methods[0].relative_error == 0)  # the reference against itself
    for name in ["curves.csv", "summary.json", "table.md"]:
        assert (tmp_path / "out" / name).is_file()
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary  # the CLI's summary, parsed

"""The tutorial (examples/python/, steps 1 to 4) runs from start to end with the package under test and writes
only into the folder given by --out: nothing into the clone, nothing into the working folder."""
import os
import subprocess
import sys

import pytest

STEPS = ["1_surface.py", "2_bem_curve.py", "3_compare_theories.py", "4_measured_pressure.py"]
PLOTS = {"1_surface.py": "psd.png", "2_bem_curve.py": "bem_curve.png",
         "3_compare_theories.py": "load_area_surface_a.png", "4_measured_pressure.py": "measured_pressure.png"}


def tree_listing(folder):
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


@pytest.mark.parametrize("step", STEPS)
def test_tutorial_step_writes_only_into_out(step, source_dir, tmp_path):
    examples = source_dir / "examples" / "python"
    before = tree_listing(examples)
    work, out = tmp_path / "work", tmp_path / "out"
    work.mkdir()
    env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
    done = subprocess.run([sys.executable, str(examples / step), "--out", str(out), "--threads", "2"], cwd=work,
                          env=env, capture_output=True, text=True, timeout=240)
    assert done.returncode == 0, done.stderr
    assert tree_listing(examples) == before and not any(work.iterdir())
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        assert "no plot" in done.stdout
    else:
        assert (out / PLOTS[step]).stat().st_size > 0

"""Every shipped scene (scenes/**/*.toml) under mpiexec: what the distributed path cannot do is refused in
preflight, before any work, naming the key (app/distributed_stages.cpp, docs/mpi.md).

Usage: test_mpi_scenes.py CONTACTBENCH MPIEXEC RANKS SCENES_FOLDER

Each scene falls in one of two classes, decided from its own keys (read with tomllib):
  refused  - it asks for something the distributed BEM stage lacks: interface.hardness with a BEM whose
             solver is not active_set (the default), interface.adhesion, loads.path with a hardness, compare = [..
             "stiffness" ..], approach_retract. The run must exit 1
             with "has no distributed version" and the name of every such key in its error, and must leave no
             curves.csv (refused before any solve). Under 1 s a scene: the surface is never built.
  accepted - none of those (a hardness with active_set included). Each is run once as one process and
             once under mpiexec, `--threads 1 --quiet --no-plots`, a generated surface at `--grid 32` (app/scene_grid_override.hpp: every refine
             scaled alike; the least grid the error names when 32 cannot carry the spectrum), a surface read
             from a file on the crop px:0,0,64,64 of that file (a copy of the scene with that crop, the file
             path made absolute: the whole 650 x 650 record takes 15 s a run; its BEMs' boundary as the scene
             says, so a record's unset boundary is mirrored on the ranks as in one process). The BEM rows of curves.csv
             must agree: areas, spots, iterations and convergence equal; separation, mean gap and largest
             pressure to a bound that follows each BEM's own tolerance (pressure_bound below: 1e-12 where
             it is 1e-8 or tighter; above that 10x the round-off sensitivity of the serial solver itself,
             results/studies/roundoff/table.md).
A scene whose keys the test cannot classify fails the test.
"""
import os
import re
import subprocess
import sys
import tempfile
import tomllib

from mpi_outputs import csv_differences, relative, rows

contactbench, mpiexec, ranks, scenes_folder = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")
failures = []
DEFAULT_TOLERANCE = 1e-10  # BemSolverOptions::tolerance (bem/bem_solver.hpp), a BEM method without `tolerance`


def pressure_bound(tolerance):
    """How far the separation, mean gap and largest pressure of one process and of the ranks may differ
    (relative), for a BEM stopped at `tolerance`. The distributed solver takes the serial iteration step for
    step; only the order of its global sums differs. A solve stopped early keeps that round-off undamped: the
    SERIAL solver alone, on 1 against 2 threads or on heights perturbed by 1e-15, moves the largest pressure
    by up to 1.3e-10 relative at tolerance 1e-4 and 2.9e-12 at 1e-6, ~1e-14 at 1e-8 and below (the study
    results/studies/roundoff/table.md, scripts/studies/roundoff_sensitivity.py, 256^2-1024^2). So: 1e-12 where
    tolerance <= 1e-8 (a factor of 1e2 over that study, 1e3 over what 1-3 ranks showed), and above it 10x the
    serial sensitivity measured: 3e-11 up to 1e-6, 1e-9 up to 1e-4. Looser tolerances were not measured: None
    (the test fails, naming the method, until they are)."""
    if tolerance <= 1e-8:
        return 1e-12
    if tolerance <= 1e-6:
        return 3e-11
    if tolerance <= 1e-4:
        return 1e-9
    return None


def refused_keys(scene):
    """The phrases bem_refusal (app/distributed_stages.cpp) must name for this scene."""
    keys = []
    interface = scene.get("interface", {})
    bem_methods = [m for name, m in scene.get("methods", {}).items() if m.get("method", name) == "bem"]
    # A hardness is distributed with the default solver, active_set, only (a BEM that ignores it aside).
    if "hardness" in interface and any(m.get("solver", "active_set") != "active_set" and
                                       "hardness" not in m.get("ignore", []) for m in bem_methods):
        keys.append("interface.hardness")
    if "adhesion" in interface:
        keys.append("interface.adhesion")
    # A load path is distributed when elastic; with a hardness its plastic flow kept along the path is not.
    if scene.get("loads", {}).get("path", "ascending") != "ascending" and "hardness" in interface:
        keys.append("loads.path")
    for method in bem_methods + [scene]:
        if "stiffness" in method.get("compare", []):
            keys.append("compare = [\"stiffness\"]")
        if "approach_retract" in method:
            keys.append("approach_retract = {")
    return sorted(set(keys))


def bem_tolerances(scene):
    """Each BEM method's label and its stopping tolerance, as the scene gives it."""
    return {label: float(m.get("tolerance", DEFAULT_TOLERANCE)) for label, m in scene.get("methods", {}).items()
            if m.get("method", label) == "bem"}


def same_bem_rows(distributed, serial, tolerances, what):
    """Every count equal, iterations included (with a hardness too: the one branch the order of the sums
    decided, whether an outer step makes G p afresh, is decided alike since bem/solvers/active_set_method.hpp's
    kUnitScaleSlack); the fields to their tolerances."""
    distributed = [r for r in distributed if r["method"] in tolerances]
    serial = [r for r in serial if r["method"] in tolerances]
    if not serial or len(distributed) != len(serial):
        failures.append(f"{what}: {len(distributed)} BEM rows against {len(serial)}")
        return
    for d, s in zip(distributed, serial):
        if int(d["iterations"]) != int(s["iterations"]):
            failures.append(f"{what}: {s['method']} iterations {d['iterations']} against {s['iterations']} at load "
                            f"{s['load']}")
        for key in ("method", "load", "area_fraction", "spots", "area_fraction_nodes", "area_fraction_corrected",
                    "plastic_area_fraction", "converged"):
            if d.get(key) != s.get(key):
                failures.append(f"{what}: {s['method']} {key} {d.get(key)} against {s.get(key)} at load {s['load']}")
        bound = pressure_bound(tolerances[s["method"]])
        if bound is None:
            failures.append(f"{what}: {s['method']} at tolerance {tolerances[s['method']]}: no measured bound "
                            "for a tolerance above 1e-4 (pressure_bound)")
            continue
        for key in ("separation", "mean_gap", "max_pressure"):
            if relative(d[key], s[key]) > bound:
                failures.append(f"{what}: {s['method']} {key} {d[key]} against {s[key]} at load {s['load']} "
                                f"(bound {bound:g} at tolerance {tolerances[s['method']]:g})")


def runnable_copy(path, scene, work):
    """The scene, and the flags that make it small: --grid for a generated surface; for a file, a copy of the
    scene on a 128 x 128 crop of it (what the test says it ran)."""
    surface = scene["surface"]
    if "generate" in surface:
        return path, ["--grid", "32"], "--grid 32"
    if "crop" in surface:
        return path, [], "as shipped (it has its own crop)"
    folder = os.path.dirname(os.path.abspath(path))
    with open(path) as f:
        text = f.read()
    absolute = os.path.normpath(os.path.join(folder, surface["file"]))
    text, count = re.subn(r'(?m)^file = ".*"$', f'file = "{absolute}"\ncrop = "px:0,0,64,64"', text)
    if count != 1:
        failures.append(f"{path}: cannot make a cropped copy (file = ... not found on a line of its own)")
    copy = os.path.join(work, "cropped_" + os.path.basename(path))
    with open(copy, "w") as f:
        f.write(text)
    return copy, [], "on crop px:0,0,64,64 of its file"


scene_files = sorted(os.path.join(folder, name) for folder, _, names in os.walk(scenes_folder)
                     for name in names if name.endswith(".toml"))
if not scene_files:
    failures.append(f"no scene under {scenes_folder}")
accepted = []
with tempfile.TemporaryDirectory() as work:
    for path in scene_files:
        with open(path, "rb") as f:
            scene = tomllib.load(f)
        keys = refused_keys(scene)
        out = os.path.join(work, os.path.relpath(path, scenes_folder).replace(os.sep, "_"))
        if not keys:
            run_path, flags, how = runnable_copy(path, scene, work)
            outputs = []
            for distributed in (False, True):
                folder = out + ("_mpi" if distributed else "")
                command = (([mpiexec, "--oversubscribe", "-np", str(ranks)] if distributed else []) +
                           [contactbench, "run", run_path, "--out", folder, "--threads", "1", "--quiet",
                            "--no-plots"] + flags)
                done = subprocess.run(command, capture_output=True, text=True, env=environment, timeout=120)
                least = re.search(r"accepted: --grid (\d+) or more", done.stderr)
                if done.returncode == 1 and "--grid" in flags and least:
                    # 64 points cannot carry this spectrum: the least grid the error names.
                    flags, how = ["--grid", least.group(1)], f"--grid {least.group(1)}"
                    command = command[:-2] + flags
                    done = subprocess.run(command, capture_output=True, text=True, env=environment, timeout=120)
                if done.returncode != 0:
                    failures.append(f"{' '.join(command)}: exit {done.returncode}\n{done.stderr}")
                    break
                outputs.append(rows(os.path.join(folder, "curves.csv")))
            if len(outputs) == 2:
                name = os.path.relpath(path, scenes_folder)
                same_bem_rows(outputs[1], outputs[0], bem_tolerances(scene),
                              f"{name} ({how}) on {ranks} ranks")
                # The distributions (measured on rank 0 from the gathered fields): every table equal, numbers
                # to the bound of the scene's tightest BEM (its tables are the BEM's fields').
                for table in sorted(os.listdir(out)):
                    if table.endswith(("_distribution.csv", "_patch_sizes.csv")):
                        bound = pressure_bound(max(bem_tolerances(scene).values())) or 0.0
                        failures.extend(csv_differences(os.path.join(out + "_mpi", table),
                                                        os.path.join(out, table), bound))
            accepted.append(f"{os.path.relpath(path, scenes_folder)} ({how})")
            continue
        command = [mpiexec, "--oversubscribe", "-np", str(ranks), contactbench, "run", path, "--out", out,
                   "--threads", "1", "--quiet", "--no-plots"]
        done = subprocess.run(command, capture_output=True, text=True, env=environment, timeout=60,
                              cwd=os.path.dirname(os.path.abspath(scenes_folder)))
        if done.returncode != 1:
            failures.append(f"{path} on {ranks} ranks: exit {done.returncode}, expected 1\n{done.stderr}")
        if "has no distributed version" not in done.stderr:
            failures.append(f"{path} on {ranks} ranks: not refused as undistributed: {done.stderr}")
        for key in keys:
            if key not in done.stderr:
                failures.append(f"{path} on {ranks} ranks: the refusal does not name {key}: {done.stderr}")
        if os.path.exists(os.path.join(out, "curves.csv")):
            failures.append(f"{path} on {ranks} ranks: curves.csv written, so work was done before the refusal")

print(f"accepted under mpiexec, run as one process and as {ranks} ranks and their BEM rows compared: "
      f"{', '.join(accepted)}")
for failure in failures:
    print("FAILED:", failure)
print(f"test_mpi_scenes on {ranks} ranks: {len(scene_files)} scenes, {len(accepted)} accepted and compared, "
      f"{len(failures)} failures")
sys.exit(1 if failures else 0)

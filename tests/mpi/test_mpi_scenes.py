"""Every shipped scene (scenes/**/*.toml) under mpiexec: what the distributed path cannot do is refused in
preflight, before any work, naming the key (app/distributed_stages.cpp, docs/mpi.md).

Usage: test_mpi_scenes.py CONTACTBENCH MPIEXEC RANKS SCENES_FOLDER

Each scene falls in one of two classes, decided from its own keys (read with tomllib):
  refused  - it asks for something the distributed BEM stage lacks: interface.hardness with a solver other
             than active_set, interface.adhesion,
             loads.path, compare = [.. "stiffness" ..], distributions, approach_retract. The run must exit 1
             with "has no distributed version" and the name of every such key in its error, and must leave no
             curves.csv (refused before any solve). Under 1 s a scene: the surface is never built.
  accepted - none of those keys. Each is run once as one process and once under mpiexec, `--threads 1
             --quiet --no-plots`, a generated surface at `--grid 32` (app/scene_grid_override.hpp: every refine
             scaled alike; the least grid the error names when 32 cannot carry the spectrum), a surface read
             from a file on the crop px:0,0,64,64 of that file (a copy of the scene with that crop, the file
             path made absolute; the whole 650 x 650 record takes 15 s a run). The BEM rows of curves.csv
             must agree: areas, spots, iterations and convergence equal; separation, mean gap and largest
             pressure to a bound that follows the method's tolerance (agreement_bound below: 1e-12 at the
             scenes' 1e-8, looser where the solve stops earlier and round-off alone moves the answer more).
A scene whose keys the test cannot classify fails the test.
"""
import os
import re
import subprocess
import sys
import tempfile
import tomllib

from mpi_outputs import relative, rows

contactbench, mpiexec, ranks, scenes_folder = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")
failures = []


def agreement_bound(tolerance):
    """How close a distributed BEM row must come to one process's in separation, mean gap and largest
    pressure, by the method's tolerance. The distributed solver takes the serial iteration step for step;
    only the order of its global sums differs. How far so small a change moves an answer depends on where
    the iteration stopped: results/studies/roundoff/table.md (scripts/studies/roundoff_sensitivity.py)
    measured the serial solver alone, on 1 against 2 threads and on heights perturbed by 1e-15, on surface A
    at 256^2 to 1024^2: its largest pressure moved up to 1.3e-10 relative at tolerance 1e-4, 2.9e-12 at
    1e-6, 4.5e-14 at 1e-8, with the same iterations and contact points. The bound is 10x that, and 1e-12 at
    the scenes' tolerance 1e-8 and tighter (1e3 above what 1-3 ranks show there, tests/mpi/test_mpi_cli.py).
    Areas, spots, iterations and convergence must be equal whatever the tolerance."""
    if tolerance <= 1e-8:
        return 1e-12
    if tolerance <= 1e-6:
        return 3e-11
    return 1e-9


def refused_keys(scene):
    """The phrases bem_refusal (app/distributed_stages.cpp) must name for this scene."""
    keys = []
    interface = scene.get("interface", {})
    # A hardness is distributed with active_set (the default); a BEM that models it with another solver is
    # refused.
    if "hardness" in interface and any(
            m.get("solver", "active_set") != "active_set" and "hardness" not in m.get("ignore", [])
            for name, m in scene.get("methods", {}).items() if m.get("method", name) == "bem"):
        keys.append("interface.hardness")
    if "adhesion" in interface:
        keys.append("interface.adhesion")
    if "path" in scene.get("loads", {}):
        keys.append("loads.path")
    bem_methods = [m for name, m in scene.get("methods", {}).items() if m.get("method", name) == "bem"]
    for method in bem_methods + [scene]:
        if "stiffness" in method.get("compare", []):
            keys.append("compare = [\"stiffness\"]")
        if "distributions" in method:
            keys.append("distributions = {")
        if "approach_retract" in method:
            keys.append("approach_retract = {")
    return sorted(set(keys))


def bem_tolerances(scene):
    """Each BEM method's tolerance (its own key, else the solver's default 1e-8)."""
    return {label: float(m.get("tolerance", 1e-8)) for label, m in scene.get("methods", {}).items()
            if m.get("method", label) == "bem"}


def same_bem_rows(distributed, serial, tolerances, what, capped):
    """capped: the BEM methods that model a hardness, whose iterations may differ by one (docs/mpi.md: the
    capped method's fresh G p after a rescaled load hangs on a factor being exactly 1, which the order of
    the sums decides); their plastic area must be equal."""
    labels = set(tolerances)
    distributed = [r for r in distributed if r["method"] in labels]
    serial = [r for r in serial if r["method"] in labels]
    if not serial or len(distributed) != len(serial):
        failures.append(f"{what}: {len(distributed)} BEM rows against {len(serial)}")
        return
    for d, s in zip(distributed, serial):
        one_more = s["method"] in capped
        for key in ("method", "load", "area_fraction", "spots", "area_fraction_nodes", "area_fraction_corrected",
                    "converged", "plastic_area_fraction") + (() if one_more else ("iterations",)):
            if d.get(key) != s.get(key):
                failures.append(f"{what}: {s['method']} {key} {d.get(key)} against {s.get(key)} at load {s['load']}")
        if one_more and abs(int(d["iterations"]) - int(s["iterations"])) > 1:
            failures.append(f"{what}: {s['method']} iterations {d['iterations']} against {s['iterations']}")
        bound = agreement_bound(tolerances[s["method"]])
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
                capped = {label for label, m in scene.get("methods", {}).items()
                          if m.get("method", label) == "bem" and "hardness" in scene.get("interface", {})
                          and "hardness" not in m.get("ignore", [])}
                same_bem_rows(outputs[1], outputs[0], bem_tolerances(scene), f"{name} ({how}) on {ranks} ranks",
                              capped)
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

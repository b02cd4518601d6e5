"""Every shipped scene (scenes/**/*.toml) under mpiexec: what the distributed path cannot do is refused in
preflight, before any work, naming the key (app/distributed_stages.cpp, docs/mpi.md).

Usage: test_mpi_scenes.py CONTACTBENCH MPIEXEC RANKS SCENES_FOLDER

Each scene falls in one of two classes, decided from its own keys (read with tomllib):
  refused  - it asks for something the distributed BEM stage lacks: interface.hardness, interface.adhesion,
             loads.path, compare = [.. "stiffness" ..], distributions, approach_retract. The run must exit 1
             with "has no distributed version" and the name of every such key in its error, and must leave no
             curves.csv (refused before any solve). Under 1 s a scene: the surface is never built.
  accepted - none of those keys. These are NOT run here yet (issue 39, step 1 (a), left undone: the shipped
             grids are too big for a fast test and `contactbench run` has no grid override yet); the test only
             lists them, so a new scene is classified and nothing is silently skipped.
A scene whose keys the test cannot classify fails the test.
"""
import os
import subprocess
import sys
import tempfile
import tomllib

contactbench, mpiexec, ranks, scenes_folder = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMP_NUM_THREADS="1", OMP_WAIT_POLICY="PASSIVE")
failures = []


def refused_keys(scene):
    """The phrases bem_refusal (app/distributed_stages.cpp) must name for this scene."""
    keys = []
    interface = scene.get("interface", {})
    if "hardness" in interface:
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
        if not keys:
            accepted.append(os.path.relpath(path, scenes_folder))
            continue
        out = os.path.join(work, os.path.relpath(path, scenes_folder).replace(os.sep, "_"))
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

print(f"accepted under mpiexec (not run by this test yet): {', '.join(accepted)}")
for failure in failures:
    print("FAILED:", failure)
print(f"test_mpi_scenes on {ranks} ranks: {len(scene_files)} scenes, {len(accepted)} accepted, "
      f"{len(failures)} failures")
sys.exit(1 if failures else 0)

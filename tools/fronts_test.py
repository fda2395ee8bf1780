#!/usr/bin/python3
"""ctest program_fronts: scripts/fronts on sweeps written by hand (its front,
its dominance verdict, the points it lists, what it leaves off a front), and
end to end on two CSV files. Usage: fronts_test.py (needs no build)."""

import csv
import importlib.machinery
import importlib.util
import pathlib
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
loader = importlib.machinery.SourceFileLoader("fronts", str(ROOT / "scripts" / "fronts"))
spec = importlib.util.spec_from_loader("fronts", loader)
fronts = importlib.util.module_from_spec(spec)
loader.exec_module(fronts)

HEADER = ["scene", "knob", "substeps", "velocity_iterations", "position_iterations", "dt",
          "worlds", "threads", "simd_target", "ns_per_world_step", "position_error_max",
          "position_error_rms", "velocity_residual_max", "velocity_residual_rms",
          "trajectory_position_rms", "trajectory_position_max", "trajectory_rotation_rms",
          "trajectory_rotation_max", "energy_drift_max", "energy_drift_final",
          "coupling_error_max", "coupling_error_rms", "unhealthy_worlds"]


def row(scene, substeps, ns, error, unhealthy=0, position=2):
    values = dict.fromkeys(HEADER, "")
    values.update(scene=scene, knob="grid", substeps=substeps, velocity_iterations=10,
                  position_iterations=position, dt=0.01667, worlds=16, threads=1,
                  simd_target="AVX3", ns_per_world_step=ns, position_error_max=error,
                  trajectory_position_rms=error, trajectory_rotation_rms=0,
                  unhealthy_worlds=unhealthy)
    return values


def write(folder, rows):
    folder.mkdir(parents=True, exist_ok=True)
    with open(folder / "sweep.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=HEADER)
        writer.writeheader()
        writer.writerows(rows)


failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


with tempfile.TemporaryDirectory() as tmp:
    tmp = pathlib.Path(tmp)
    # Gauss-Seidel: a front of (100, 1e-2), (200, 1e-3), (800, 1e-4); (300, 5e-3)
    # is behind it; (50, 1e-6) has an unhealthy world and is on no front.
    write(tmp / "gs", [row("a", 1, 100, 1e-2), row("a", 2, 200, 1e-3), row("a", 4, 300, 5e-3),
                       row("a", 8, 800, 1e-4), row("a", 1, 50, 1e-6, unhealthy=1, position=0),
                       row("b/x", 1, 100, 1e-2)])
    # Exact: dominates a's front from 100 ns up; on b/x it is dearer for the
    # same error, so b/x's one Gauss-Seidel point is not dominated.
    write(tmp / "exact", [row("a", 1, 90, 1e-5), row("a", 2, 400, 1e-7),
                          row("b/x", 1, 150, 1e-2)])
    gs = fronts.read_sweep(tmp / "gs" / "sweep.csv")
    exact = fronts.read_sweep(tmp / "exact" / "sweep.csv")
    a_front = fronts.front([r for r in gs if r["scene"] == "a"], "position_error_max")
    check([r["ns_per_world_step"] for r in a_front] == [100, 200, 800],
          "front of a: %s" % [r["ns_per_world_step"] for r in a_front])
    exact_a = fronts.front([r for r in exact if r["scene"] == "a"], "position_error_max")
    check(fronts.not_dominated(a_front, exact_a, "position_error_max") == [],
          "exact dominates a")
    b_left = fronts.not_dominated(
        fronts.front([r for r in gs if r["scene"] == "b/x"], "position_error_max"),
        fronts.front([r for r in exact if r["scene"] == "b/x"], "position_error_max"),
        "position_error_max")
    check(len(b_left) == 1 and b_left[0]["ns_per_world_step"] == 100, "b/x not dominated")
    # Equal cost and error counts as dominated (no dearer, no worse).
    check(fronts.not_dominated(a_front, a_front, "position_error_max") == [],
          "a front dominates itself")

    check(fronts.main(["--gauss-seidel", str(tmp / "gs"), "--exact", str(tmp / "exact"),
                       "--out", str(tmp / "out")]) == 0, "main returns 0")
    md = (tmp / "out" / "fronts.md").read_text()
    check("| a | joint error max (m or rad) | yes |" in md, "a's verdict in fronts.md")
    check("| b/x | joint error max (m or rad) | no |" in md, "b/x's verdict in fronts.md")
    # Only the cheapest of three front points left: dominated above it.
    g3 = [dict(ns_per_world_step=c, position_error_max=e) for c, e in
          ((10, 1e-1), (20, 1e-2), (40, 1e-3))]
    e3 = [dict(ns_per_world_step=15, position_error_max=1e-4)]
    left3 = fronts.not_dominated(g3, e3, "position_error_max")
    check(fronts.verdict(g3, left3) == "above 10 ns", "verdict: %s" % fronts.verdict(g3, left3))
    check("1 / 10 / 2 (100 ns, 0.01)" in md, "b/x's undominated point listed")
    # trajectory_rotation_rms is 0 everywhere: not a metric to compare.
    check("rad) |" not in md.replace("(m or rad)", ""), "all-zero metric left out")
    gp = (tmp / "out" / "fronts.gp").read_text()
    check("set output 'b_x-fronts.png'" in gp, "'/' in a scene id becomes '_'")
    # Each panel: every setting as dots and the front as a line, per solver.
    panels = gp.count("\nplot ")
    check(gp.count("with linespoints") == 2 * panels and gp.count("with points") == 2 * panels,
          "one front line and one set of dots per solver and panel")

    # A quote in a scene id stays inside gnuplot's strings and out of the file
    # name; a metric that is NaN everywhere has no panel and no verdict.
    nan = row("it's", 1, 100, 1e-2)
    nan["trajectory_position_rms"] = "nan"
    write(tmp / "gs2", [nan])
    write(tmp / "exact2", [dict(nan, ns_per_world_step=50)])
    check(fronts.main(["--gauss-seidel", str(tmp / "gs2"), "--exact", str(tmp / "exact2"),
                       "--out", str(tmp / "out2")]) == 0, "main returns 0 on the quoted id")
    gp = (tmp / "out2" / "fronts.gp").read_text()
    check("set output 'it_s-fronts.png'" in gp, "a quote in an id is not in the file name")
    check("title 'it''s: both fronts" in gp, "a quote in an id is doubled in gnuplot")
    md = (tmp / "out2" / "fronts.md").read_text()
    check("trajectory RMS" not in md and "| it's | joint error max (m or rad) | yes |" in md,
          "the NaN metric is left out, the other compared")

if failures:
    sys.exit("fronts_test: %d failure(s)" % len(failures))
print("fronts_test: ok")

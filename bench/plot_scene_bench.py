#!/usr/bin/python3
"""Plots of one scene_bench run (the README's "Results").

Reads the JSON that scene_bench writes with
  --benchmark_out=run.json --benchmark_out_format=json
and draws two PNGs:
  <prefix>-throughput.png  world-steps/s against worlds per scene, 1 and 2
                           threads, and the scalar reference stepper's rate;
  <prefix>-roofline.png    achieved GFLOP/s of the whole step and of the
                           velocity iterations (10 minus 1) per scene at 4096
                           worlds, 1 thread, against the FMA peak measured in
                           the same run;
and prints the README's results table (markdown, 4096 worlds) to stdout.
Needs matplotlib for Debian's /usr/bin/python3 (apt-get install python3-matplotlib).

  bench/plot_scene_bench.py [--cpu] run.json docs/results/scene_bench
"""
import json
import re
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TABLE_WORLDS = 4096


def load(path):
    with open(path) as f:
        data = json.load(f)
    rows = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b["run_name"] if "run_name" in b else b["name"]
        name = name.replace("/real_time", "")
        rows[name] = b
    return data["context"], rows


def main(path, prefix, cpu):
    context, rows = load(path)
    batch = defaultdict(dict)  # scene -> threads -> [(worlds, world-steps/s)]
    reference = {}
    for name, b in rows.items():
        m = re.fullmatch(r"batch/([^/]+)/worlds:(\d+)/threads:(\d+)", name)
        if m:
            batch[m.group(1)].setdefault(int(m.group(3)), []).append(
                (int(m.group(2)), b["items_per_second"]))
        m = re.fullmatch(r"reference/([^/]+)/worlds:\d+", name)
        if m:
            reference[m.group(1)] = b["items_per_second"]
    scenes = list(batch)
    date = context.get("date", "")[:16]

    fig, ax = plt.subplots(figsize=(8, 5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, scene in enumerate(scenes):
        c = colours[i % len(colours)]
        for threads, style in ((1, "-"), (2, "--")):
            points = sorted(batch[scene].get(threads, []))
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], style, color=c,
                        marker="o", markersize=3,
                        label=f"{scene}" if threads == 1 else None)
        if scene in reference:
            ax.axhline(reference[scene], color=c, linestyle=":", linewidth=0.8)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("worlds")
    ax.set_ylabel("world-steps/s")
    ax.set_title(f"Batch::Step, AVX3, float, dt 1/60, 10+2 iterations ({date})\n"
                 "solid 1 thread, dashed 2 threads, dotted: scalar reference, 1 thread")
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8, ncol=2)
    fig.tight_layout()
    fig.savefig(f"{prefix}-throughput.png", dpi=90)

    def per_second(b):  # 1-thread rows: per CPU second with --cpu
        return b["items_per_second"] * (b["real_time"] / b["cpu_time"] if cpu else 1.0)

    peak_row = rows.get("peak/fma/threads:1")
    peak = per_second(peak_row) * 1e-9 if peak_row else None
    step, velocity = [], []
    for scene in scenes:
        ten = rows.get(f"batch/{scene}/worlds:{TABLE_WORLDS}/threads:1")
        one = rows.get(f"batch-v1/{scene}/worlds:{TABLE_WORLDS}/threads:1")
        if not ten or not one:
            step.append(0.0)
            velocity.append(0.0)
            continue
        step.append(ten["flop_per_world_step"] * per_second(ten) * 1e-9)
        flops = ten["flop_per_world_step"] - one["flop_per_world_step"]
        seconds = 1.0 / per_second(ten) - 1.0 / per_second(one)
        velocity.append(flops / seconds * 1e-9 if seconds > 0 else 0.0)
    fig, ax = plt.subplots(figsize=(8, 4.5))
    x = range(len(scenes))
    ax.bar([i - 0.2 for i in x], step, width=0.4, label="whole step")
    ax.bar([i + 0.2 for i in x], velocity, width=0.4, label="velocity iterations 2-10")
    if peak:
        for fraction in (0.1, 0.2, 0.3, 0.5):
            ax.axhline(peak * fraction, color="grey", linewidth=0.5, linestyle=":")
            ax.text(len(scenes) - 0.5, peak * fraction, f"{fraction:.0%} of peak", fontsize=7,
                    va="bottom", ha="right", color="grey")
    ax.set_xticks(list(x))
    ax.set_xticklabels(scenes, rotation=20, fontsize=8)
    ax.set_ylabel("counted GFLOP/s, 1 thread" + (" (per CPU second)" if cpu else ""))
    ax.legend(fontsize=8, loc="upper left")
    ax.set_title(f"Roofline at {TABLE_WORLDS} worlds: FMA peak {peak:.0f} GFLOP/s "
                 f"(AVX3, same run, {date})" if peak else "Roofline")
    fig.tight_layout()
    fig.savefig(f"{prefix}-roofline.png", dpi=90)


def print_table(path, cpu):
    """The README's results table (markdown) from the same run, 4096 worlds.

    With cpu, the 1-thread rates (world-steps/s, the FMA peak) are per CPU
    second of the benchmark thread instead of per wall-clock second: on a
    shared machine that leaves out the time the thread waited for a core.
    2-thread rates are always wall clock (the TBB workers' CPU time is not in
    the benchmark's)."""
    _, rows = load(path)
    w = TABLE_WORLDS

    def rate(name):
        if name not in rows:
            return float("nan")
        b = rows[name]
        if cpu and not name.endswith("threads:2"):
            return b["items_per_second"] * b["real_time"] / b["cpu_time"]
        return b["items_per_second"]

    peak = {t: rate(f"peak/fma/threads:{t}") * 1e-9 for t in (1, 2)}

    print("| scene | 1 thread (world-steps/s) | 2 threads | 2T / 1T | batch / reference "
          "| SIMD, whole step | SIMD, velocity iterations | flop / world-step "
          "| of FMA peak, step (1T) | of FMA peak, velocity iterations (1T) | bytes / world |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    scenes = [m.group(1) for n in rows
              for m in [re.fullmatch(rf"batch/([^/]+)/worlds:{w}/threads:1", n)] if m]
    for scene in scenes:
        one = rate(f"batch/{scene}/worlds:{w}/threads:1")
        two = rate(f"batch/{scene}/worlds:{w}/threads:2")
        ref = rate(f"reference/{scene}/worlds:64")
        scalar = rate(f"scalar/{scene}/worlds:{w}/threads:1")
        v1 = rate(f"batch-v1/{scene}/worlds:{w}/threads:1")
        sv1 = rate(f"scalar-v1/{scene}/worlds:{w}/threads:1")
        row = rows[f"batch/{scene}/worlds:{w}/threads:1"]
        flops = row["flop_per_world_step"]
        vflops = flops - rows[f"batch-v1/{scene}/worlds:{w}/threads:1"]["flop_per_world_step"]
        vtime = 1 / one - 1 / v1
        svtime = 1 / scalar - 1 / sv1
        # 2T / 1T only on the same clock (wall): with cpu the bases differ.
        scaling = "-" if cpu else f"{two / one:.2f}x"
        print(f"| {scene} | {one:.3g} | {two:.3g} | {scaling} | {one / ref:.1f}x "
              f"| {one / scalar:.1f}x | {svtime / vtime:.1f}x | {flops:.0f} "
              f"| {flops * one * 1e-9 / peak[1]:.0%} | {vflops / vtime * 1e-9 / peak[1]:.0%} "
              f"| {row['bytes_per_world']:.0f} |")
    print(f"\nFMA peak: 1 thread {peak[1]:.0f} GFLOP/s, 2 threads {peak[2]:.0f} GFLOP/s"
          + (" (1 thread per CPU second)" if cpu else ""))


if __name__ == "__main__":
    cpu = "--cpu" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--cpu"]
    if len(args) != 2:
        sys.exit(__doc__)
    main(args[0], args[1], cpu)
    print_table(args[0], cpu)

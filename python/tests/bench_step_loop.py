#!/usr/bin/python3
"""What a Python RL step loop costs over Batch::Step alone.

Timings of the same batch, interleaved, median of the repeats, in ns per
world-step (wall clock; for one thread also by the calling thread's CPU
time, on which other programs' load has little effect):
  step()  batch.step() alone, timed from Python around the call (the call
          releases the GIL and runs Batch::Step; it adds one pybind11 call,
          well under a microsecond, to the C++ figure);
  loop    an RL rollout's loop: write the actions from a numpy array
          (set_body_forces), step, read the observations into a preallocated
          array (get_state(out=)), reset the done worlds (reset(mask));
  +numpy  the same loop with the done flags computed from the observations
          with numpy (cart off the track or pole past 0.2 rad) instead of
          drawn beforehand: what a plain numpy environment adds on top;
  forces apart  set_body_forces, then one call for step, resets and
          observations, step(settings, reset_mask=done, state_out=obs);
  fused   the loop as one call: step(settings, body_forces={CART:
          forces}, reset_mask=done, state_out=obs), which writes each
          block's actions just before it steps, resets its done worlds and
          reads its state just after, all inside the step's pass over the
          blocks (the same actions, resets and reads per step as `loop`;
          the reset follows the step, so the observation of a reset world
          is its initial state);
  fused+numpy  `fused` with the numpy done flags of `+numpy`, passed to the
          next step's reset_mask;
  joints  `fused` reading joint coordinates (joints_out=, what
          manyworlds.envs observes) instead of the state.
The overhead is <loop> / step() - 1. Actions and done masks are drawn before
the timing; --reset-rate is the fraction of worlds done per step (default
4 %, a random policy's: its cartpole episodes last about 25 steps).
A breakdown (microseconds per call inside the loop) follows.

    /usr/bin/python3 python/tests/bench_step_loop.py            # 4096 worlds
    /usr/bin/python3 python/tests/bench_step_loop.py --smoke    # seconds (ctest)

Run it with the build tree's package (PYTHONPATH=build/python) or the
installed one. --max-overhead P exits 1 when the fused loop's overhead is above P
percent.
"""

import argparse
import math
import os
import statistics
import sys
import time

import numpy as np

import manyworlds as mw

CART, POLE = mw.reference_scene.CART, mw.reference_scene.POLE
PHASES = ("set_body_forces", "step", "get_state", "reset")
FUSED_PHASES = ("step(body_forces=, reset_mask=, state_out=)",)
LOOPS = ("loop", "numpy", "forces_apart", "fused", "fused_numpy", "joints")
LOOP_LABELS = ("loop", "+numpy", "forces apart", "fused", "fused+numpy", "fused joints")


class Rollout:
    """The loop's inputs, drawn once, and its preallocated outputs."""

    def __init__(self, batch, steps, reset_rate, seed=0):
        worlds = batch.num_worlds
        rng = np.random.default_rng(seed)
        self.forces = np.zeros((steps, worlds, 3), np.float32)
        self.forces[:, :, 0] = rng.uniform(-10, 10, (steps, worlds))
        self.done_masks = rng.random((steps, worlds)) < reset_rate
        self.observations = np.empty((worlds, batch.num_bodies, 13), np.float32)
        self.joints = np.empty((worlds, batch.joint_coordinates_per_world), np.float32)
        self.scratch = np.empty(worlds, np.float32)
        self.done = np.empty(worlds, bool)
        self.tilted = np.empty(worlds, bool)
        self.max_pole_sine = np.float32(math.sin(0.1))  # |q_z| of a 0.2 rad tilt about Z

    def step_only(self, batch, settings):
        wall = cpu = 0
        for _ in range(len(self.forces)):
            start, start_cpu = time.perf_counter_ns(), time.thread_time_ns()
            batch.step(settings)
            wall += time.perf_counter_ns() - start
            cpu += time.thread_time_ns() - start_cpu
        return wall, cpu

    def loop(self, batch, settings):
        obs = self.observations
        start, start_cpu = time.perf_counter_ns(), time.thread_time_ns()
        for forces, done in zip(self.forces, self.done_masks):
            batch.set_body_forces(CART, forces)
            batch.step(settings)
            batch.get_state(out=obs)
            batch.reset(done)
        return time.perf_counter_ns() - start, time.thread_time_ns() - start_cpu

    def loop_with_numpy_done(self, batch, settings):
        obs, scratch, done, tilted = self.observations, self.scratch, self.done, self.tilted
        start, start_cpu = time.perf_counter_ns(), time.thread_time_ns()
        for forces in self.forces:
            batch.set_body_forces(CART, forces)
            batch.step(settings)
            batch.get_state(out=obs)
            np.abs(obs[:, CART, 0], out=scratch)
            np.greater(scratch, 2.4, out=done)
            np.abs(obs[:, POLE, 5], out=scratch)
            np.greater(scratch, self.max_pole_sine, out=tilted)
            np.logical_or(done, tilted, out=done)
            batch.reset(done)
        return time.perf_counter_ns() - start, time.thread_time_ns() - start_cpu

    def forces_apart(self, batch, settings):
        obs = self.observations
        start, start_cpu = time.perf_counter_ns(), time.thread_time_ns()
        for forces, done in zip(self.forces, self.done_masks):
            batch.set_body_forces(CART, forces)
            batch.step(settings, reset_mask=done, state_out=obs)
        return time.perf_counter_ns() - start, time.thread_time_ns() - start_cpu

    def fused(self, batch, settings, output="state_out"):
        outputs = {output: self.observations if output == "state_out" else self.joints}
        start, start_cpu = time.perf_counter_ns(), time.thread_time_ns()
        for forces, done in zip(self.forces, self.done_masks):
            batch.step(settings, body_forces={CART: forces}, reset_mask=done, **outputs)
        return time.perf_counter_ns() - start, time.thread_time_ns() - start_cpu

    def fused_joints(self, batch, settings):
        return self.fused(batch, settings, output="joints_out")

    def fused_with_numpy_done(self, batch, settings):
        obs, scratch, done, tilted = self.observations, self.scratch, self.done, self.tilted
        done[:] = False
        start, start_cpu = time.perf_counter_ns(), time.thread_time_ns()
        for forces in self.forces:
            batch.step(settings, body_forces={CART: forces}, reset_mask=done, state_out=obs)
            np.abs(obs[:, CART, 0], out=scratch)
            np.greater(scratch, 2.4, out=done)
            np.abs(obs[:, POLE, 5], out=scratch)
            np.greater(scratch, self.max_pole_sine, out=tilted)
            np.logical_or(done, tilted, out=done)
        return time.perf_counter_ns() - start, time.thread_time_ns() - start_cpu

    def breakdown(self, batch, settings, fused=False):
        """Microseconds per call of each phase of `loop` (or `fused`),
        summed over the steps and divided by their number."""
        obs = self.observations
        if fused:
            phases = {FUSED_PHASES[0]: lambda forces, done: batch.step(
                settings, body_forces={CART: forces}, reset_mask=done, state_out=obs)}
        else:
            phases = {"set_body_forces": lambda forces, done: batch.set_body_forces(CART, forces)}
            phases["step"] = lambda forces, done: batch.step(settings)
            phases["get_state"] = lambda forces, done: batch.get_state(out=obs)
            phases["reset"] = lambda forces, done: batch.reset(done)
        totals = dict.fromkeys(phases, 0)
        for forces, done in zip(self.forces, self.done_masks):
            for phase, call in phases.items():
                start = time.perf_counter_ns()
                call(forces, done)
                totals[phase] += time.perf_counter_ns() - start
        return {phase: ns / len(self.forces) / 1000 for phase, ns in totals.items()}


def overheads(timings):
    """A table row of the median step() ns/world-step and every loop's with
    its overhead over step(); and the overheads in percent by loop."""
    step_ns = statistics.median(timings["step"])
    row, percent = f"{step_ns:>21.2f}", {}
    for name in LOOPS:
        loop_ns = statistics.median(timings[name])
        percent[name] = 100 * (loop_ns / step_ns - 1)
        row += f" {loop_ns:>7.2f} {percent[name]:>+6.1f}%"
    return row, percent


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--worlds", type=int, default=4096)
    parser.add_argument("--steps", type=int, default=200, help="steps per timing")
    parser.add_argument("--repeats", type=int, default=15)
    parser.add_argument("--threads", type=int, nargs="+", default=[1, 0],
                        help="thread counts (0: the default, every core)")
    parser.add_argument("--reset-rate", type=float, default=0.04,
                        help="fraction of worlds reset per step in `loop`")
    parser.add_argument("--smoke", action="store_true", help="a few steps, to check it runs")
    parser.add_argument("--max-overhead", type=float, default=None,
                        help="exit 1 when `fused` costs more than this percent over step()")
    args = parser.parse_args()
    if args.smoke:
        args.worlds, args.steps, args.repeats = 256, 5, 2

    scene, settings = mw.make_scene("cartpole"), mw.scene_step_settings("cartpole")
    configs = []
    for threads in args.threads:
        batch = mw.Batch(scene, args.worlds, threads=threads)
        rollout = Rollout(batch, args.steps, args.reset_rate)
        configs.append({"batch": batch, "rollout": rollout,
                        "wall": {name: [] for name in ("step",) + LOOPS},
                        "cpu": {name: [] for name in ("step",) + LOOPS},
                        "breakdowns": [], "fused_breakdowns": []})

    load_before = os.getloadavg()
    world_steps = args.steps * args.worlds
    for repeat in range(args.repeats):
        for config in configs:
            batch, rollout = config["batch"], config["rollout"]
            timings = [("step", rollout.step_only), ("loop", rollout.loop),
                       ("numpy", rollout.loop_with_numpy_done),
                       ("forces_apart", rollout.forces_apart), ("fused", rollout.fused),
                       ("fused_numpy", rollout.fused_with_numpy_done),
                       ("joints", rollout.fused_joints)]
            # Rotate the order, so that drift and cache warmth favour none.
            shift = repeat % len(timings)
            for name, timing in timings[shift:] + timings[:shift]:
                wall, cpu = timing(batch, settings)
                config["wall"][name].append(wall / world_steps)
                config["cpu"][name].append(cpu / world_steps)
            config["breakdowns"].append(rollout.breakdown(batch, settings))
            config["fused_breakdowns"].append(rollout.breakdown(batch, settings, fused=True))

    # Another program on the second core makes the 2-thread figures mean little.
    print("load average (1, 5, 15 min): before %.2f %.2f %.2f, after %.2f %.2f %.2f"
          % (load_before + os.getloadavg()))
    print(f"manyworlds {mw.__version__}: cartpole, {args.worlds} worlds, {args.steps} steps "
          f"x {args.repeats} repeats (median), SIMD target {configs[0]['batch'].simd_target}, "
          f"{100 * args.reset_rate:g} % of worlds reset per step")
    print(f"{'threads':>7} {'step() ns/world-step':>21}"
          + "".join(f" {name:>15}" for name in LOOP_LABELS))
    worst = -math.inf
    for config in configs:
        row, percent = overheads(config["wall"])
        worst = max(worst, percent["fused"])
        print(f"{config['batch'].threads:>7} {row}")
    for config in configs:
        # With one thread every part runs on this thread, so its CPU time is
        # the work itself, whatever else the machine runs meanwhile.
        if config["batch"].threads == 1:
            row, _ = overheads(config["cpu"])
            print(f"{'1 (CPU)':>7} {row}   <- this thread's CPU time: robust to other load")
    print("microseconds per call inside the loop (median):")
    for config in configs:
        for loop, phases, key in (("loop", PHASES, "breakdowns"),
                                  ("fused", FUSED_PHASES, "fused_breakdowns")):
            parts = ", ".join(
                f"{phase} {statistics.median(b[phase] for b in config[key]):.1f}"
                for phase in phases)
            print(f"  threads {config['batch'].threads} {loop:>5}: {parts}")
    if args.max_overhead is not None and worst > args.max_overhead:
        print(f"overhead {worst:.1f} % is above {args.max_overhead} %", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""ctest program_<case>: how `manyworlds` talks (issue 16 item 2).

Usage: program_test.py MANYWORLDS CASE, CASE one of
  errors         every bad command line exits 2 with one line on stderr that
                 names the bad value and what is accepted, then one hint line,
                 and writes nothing to stdout
  unknown-scene  `run --scene nosuch` lists every id `manyworlds scenes`
                 lists (AllSceneIds()), reference, stress and contact scenes
                 grouped
  scenes         `scenes`: one line per scene with bodies, constraints and a
                 description
  progress-pty   with stderr on a pseudo-terminal a long run shows a progress
                 line (steps, world-steps/s, time left); Ctrl-C stops it, the
                 line is erased and the report covers the steps done
  progress-pipe  with stderr on a pipe the same run writes nothing to stderr
                 before it ends, and a finished run's stdout is only the report
  sigint         SIGINT mid-run: the report says it was interrupted and after
                 how many steps, fewer than asked; exit code 130
  profile        `run --profile`: the report lists every phase with ns per
                 world-step and shares adding up to 100 %; without --profile
                 there is no phase list
  mpirun         `mpirun -n 2|3 manyworlds run` (MPIEXEC in the environment):
                 one report, from rank 0, over every rank's worlds, with the
                 ranks, their worlds and world-steps/s, and the same constraint
                 errors and health as the run in one process; a usage error, a
                 refused --record and too few worlds print one error, exit != 0;
                 SIGUSR1 to mpirun stops every rank after the same step, with
                 rank 0's report
"""

import os
import pty
import re
import select
import signal
import subprocess
import sys
import time

MANYWORLDS = sys.argv[1]
CASE = sys.argv[2]

# Long enough that no machine finishes it within the tests' waits: they stop
# it with SIGINT.
LONG_RUN = ["run", "--scene", "chain16", "--worlds", "1024", "--steps", "100000000"]


def fail(message):
    print(f"program_test {CASE}: {message}", file=sys.stderr)
    sys.exit(1)


def run(args, timeout=60):
    return subprocess.run([MANYWORLDS, *args], capture_output=True, text=True, timeout=timeout)


def expect_usage_error(args, *names):
    """Exit 2, nothing on stdout, stderr = one error line naming every one of
    `names`, then the hint line."""
    result = run(args)
    shown = " ".join(args) or "(no arguments)"
    if result.returncode != 2:
        fail(f"'{shown}': exit code {result.returncode}, expected 2; stderr: {result.stderr!r}")
    if result.stdout:
        fail(f"'{shown}': wrote to stdout: {result.stdout!r}")
    lines = result.stderr.splitlines()
    if len(lines) != 2:
        fail(f"'{shown}': stderr has {len(lines)} lines, expected an error and a hint: "
             f"{result.stderr!r}")
    error, hint = lines
    if not error.startswith("manyworlds: "):
        fail(f"'{shown}': error line does not start with 'manyworlds: ': {error!r}")
    for name in names:
        if name not in error:
            fail(f"'{shown}': error line does not name {name!r}: {error!r}")
    if hint != "run 'manyworlds --help' for usage":
        fail(f"'{shown}': unexpected hint line {hint!r}")
    return error


def case_errors():
    expect_usage_error([], "no command given", "run, plan, scenes, sweep")
    expect_usage_error(["frobnicate"], "'frobnicate'", "run, plan, scenes, sweep")
    expect_usage_error(["run"], "--scene", "cartpole")
    expect_usage_error(["run", "--scene"], "--scene needs a value")
    expect_usage_error(["run", "--scene", "cartpole", "--worlds", "0"],
                       "--worlds", "'0'", "from 1 to 67108864")
    expect_usage_error(["run", "--scene", "cartpole", "--steps", "-5"],
                       "--steps", "'-5'", "from 1 to 1000000000")
    expect_usage_error(["run", "--scene", "cartpole", "--threads", "5000"],
                       "--threads", "'5000'", "from 0 to 4096")
    expect_usage_error(["run", "--scene", "cartpole", "--mass-range-limit", "0.5"],
                       "--mass-range-limit", "'0.5'", "0 (off)", "from 1 to 1e+30")
    expect_usage_error(["run", "--scene", "cartpole", "--velocity-tolerance", "-1e-3"],
                       "--velocity-tolerance", "'-1e-3'", "[0, 1e6]")
    expect_usage_error(["run", "--scene", "cartpole", "--velocity-tolerance", "nan"],
                       "--velocity-tolerance", "'nan'")
    expect_usage_error(["run", "--scene", "cartpole", "--frob", "3"],
                       "'--frob'", "'run'", "--scene, --worlds", "--mass-range-limit")
    expect_usage_error(["run", "--scene", "cartpole", "extra"], "'extra'", "--worlds")
    expect_usage_error(["run", "--scene", "cartpole", "--scene", "chain16"], "--scene given twice")
    expect_usage_error(["plan", "--scene", "nosuch"], "'nosuch'", "cartpole", "far-1e4")
    expect_usage_error(["plan", "--worlds", "3"], "'--worlds'", "'plan'", "--scene")
    expect_usage_error(["scenes", "--all"], "'scenes' takes no arguments", "'--all'")
    expect_usage_error(["sweep", "--scenes", "nosuch"], "'nosuch'", "rackpinion")
    expect_usage_error(["sweep", "--grid", "diagonal"], "'diagonal'", "'knobs' or 'full'")
    expect_usage_error(["sweep", "--seconds", "0"], "--seconds", "'0'", "from 0.001 to 3600")
    expect_usage_error(["sweep", "--small", "--out"], "--out needs a value")


def case_unknown_scene():
    ids = [line.split()[0] for line in run(["scenes"]).stdout.splitlines()]
    if len(ids) < 20:
        fail(f"'scenes' lists only {len(ids)} ids")
    error = expect_usage_error(["run", "--scene", "nosuch"], "--scene", "'nosuch'")
    listed = re.search(
        r"valid ids: reference scenes (.*); stress scenes (.*); contact scenes (.*)$", error)
    if not listed:
        fail(f"the ids are not grouped into reference, stress and contact scenes: {error!r}")
    named = set()
    for group in listed.groups():
        named |= set(group.split(", "))
    missing = [i for i in ids if i not in named]
    if missing:
        fail(f"the error does not list {missing}: {error!r}")
    if ("cartpole" not in listed.group(1) or "far-1e4" not in listed.group(2)
            or "box-drop" not in listed.group(3)):
        fail(f"reference, stress and contact groups mixed up: {error!r}")


def case_scenes():
    result = run(["scenes"])
    if result.returncode != 0 or result.stderr:
        fail(f"exit code {result.returncode}, stderr {result.stderr!r}")
    line_form = re.compile(r"^(\S+) +(\d+) bodies +(\d+) constraints? {2,}(\S.{5,})$")
    lines = result.stdout.splitlines()
    for line in lines:
        found = line_form.match(line)
        if not found:
            fail(f"line not 'id N bodies N constraints description': {line!r}")
        if (found.group(3) == "1") != (" 1 constraint " in line):
            fail(f"'constraint' and its count disagree: {line!r}")
    by_id = {line.split()[0]: line for line in lines}
    if len(by_id) != len(lines):
        fail("an id is listed twice")
    if not re.match(r"^cartpole +3 bodies +2 constraints  ", by_id.get("cartpole", "")):
        fail(f"cartpole's counts are wrong: {by_id.get('cartpole')!r}")
    if not re.match(r"^flywheel +2 bodies +1 constraint  ", by_id.get("flywheel", "")):
        fail(f"flywheel's counts are wrong: {by_id.get('flywheel')!r}")


def report_steps(stdout):
    """(steps done, steps asked) from an interrupted report's 'timed:' line."""
    found = re.search(r"interrupted by SIGINT after step (\d+) of (\d+)", stdout)
    if not found:
        fail(f"the report does not say it was interrupted: {stdout!r}")
    return int(found.group(1)), int(found.group(2))


def check_interrupted_report(stdout, returncode):
    if returncode != 130:
        fail(f"exit code {returncode} after SIGINT, expected 130")
    done, asked = report_steps(stdout)
    if not 0 < done < asked:
        fail(f"interrupted after step {done} of {asked}: expected 0 < done < asked")
    for key in ("throughput:", "linear:", "angular:", "unhealthy worlds:"):
        if key not in stdout:
            fail(f"the interrupted report has no '{key}' line: {stdout!r}")


def case_progress_pty():
    master, slave = pty.openpty()
    process = subprocess.Popen([MANYWORLDS, *LONG_RUN], stdout=subprocess.PIPE, stderr=slave,
                               text=False)
    os.close(slave)
    seen = b""
    deadline = time.monotonic() + 30
    progress = re.compile(rb"step (\d+) / (\d+) \(\d+%\), [0-9.e+]+ world-steps/s, "
                          rb"(\d+ s|\d+ min \d\d s|\d+ h \d\d min) left")
    # The line appears after about a second and is redrawn a few times a second.
    while len(progress.findall(seen)) < 2 and time.monotonic() < deadline:
        ready, _, _ = select.select([master], [], [], 0.5)
        if ready:
            seen += os.read(master, 4096)
    if len(progress.findall(seen)) < 2:
        process.kill()
        fail(f"no progress line redrawn on the terminal within 30 s: {seen!r}")
    if not seen.startswith(b"\r\x1b[K"):
        process.kill()
        fail(f"the progress line is not drawn in place: {seen[:80]!r}")
    process.send_signal(signal.SIGINT)
    stdout, _ = process.communicate(timeout=60)
    # The rest of the terminal output: the erase, then the interrupt notice.
    while True:
        try:
            ready, _, _ = select.select([master], [], [], 0.5)
            if not ready:
                break
            chunk = os.read(master, 4096)
        except OSError:  # EIO: the program closed the terminal
            break
        if not chunk:
            break
        seen += chunk
    os.close(master)
    check_interrupted_report(stdout.decode(), process.returncode)
    tail = seen[seen.rfind(b"world-steps/s"):]
    if b"\r\x1b[K" not in tail:
        fail(f"the progress line was not erased at the end: {tail!r}")
    after_erase = tail[tail.rfind(b"\r\x1b[K") + 4:]
    if not after_erase.startswith(b"manyworlds: interrupted by SIGINT"):
        fail(f"unexpected terminal output after the erase: {after_erase!r}")
    if b"\r" in stdout or b"\x1b" in stdout or b" left" in stdout:
        fail(f"progress went to stdout: {stdout!r}")


def case_progress_pipe():
    process = subprocess.Popen([MANYWORLDS, *LONG_RUN], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE)
    time.sleep(2.5)  # well past the first draw a terminal would get
    os.set_blocking(process.stderr.fileno(), False)
    early = process.stderr.read() or b""
    if early:
        process.kill()
        fail(f"wrote to a piped stderr during the run: {early!r}")
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    # After SIGINT only the one interrupt line, no terminal control.
    if stderr.count(b"\n") != 1 or b"\x1b" in stderr or b"\r" in stderr:
        fail(f"stderr after SIGINT is not one plain line: {stderr!r}")
    # A run that completes: stdout is the report's lines only, stderr empty.
    result = subprocess.run([MANYWORLDS, "run", "--scene", "cartpole", "--worlds", "64",
                             "--steps", "50"], capture_output=True, timeout=60)
    if result.returncode != 0 or result.stderr:
        fail(f"complete run: exit code {result.returncode}, stderr {result.stderr!r}")
    if b"\r" in result.stdout or b"\x1b" in result.stdout:
        fail(f"terminal control in a piped report: {result.stdout!r}")
    if not result.stdout.startswith(b"scene:                cartpole"):
        fail(f"the report does not start with the scene: {result.stdout[:80]!r}")


def case_sigint():
    process = subprocess.Popen([MANYWORLDS, *LONG_RUN], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    time.sleep(2.0)
    if process.poll() is not None:
        fail(f"the run ended before SIGINT: {process.communicate()}")
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    check_interrupted_report(stdout, process.returncode)
    done, asked = report_steps(stdout)
    if f"interrupted by SIGINT after step {done} of {asked}" not in stderr:
        fail(f"stderr does not say where the run stopped: {stderr!r}")
    timed = re.search(r"timed: +(\d+) of (\d+) steps after (\d+) of (\d+) warm-up steps", stdout)
    if not timed or int(timed.group(1)) + int(timed.group(3)) != done:
        fail(f"the timed line does not add up to {done} steps: {stdout!r}")


PHASES = ("forces", "setup", "warm_start", "velocity", "integration", "position", "finish")


def case_profile():
    args = ["run", "--scene", "cartpole", "--worlds", "64", "--steps", "20", "--threads", "1"]
    result = run(args + ["--profile"])
    if result.returncode != 0 or result.stderr:
        fail(f"exit code {result.returncode}, stderr {result.stderr!r}")
    if not re.search(r"^phases: +ns per world-step", result.stdout, re.M):
        fail(f"no 'phases:' line in the report: {result.stdout!r}")
    shares = []
    for phase in PHASES:
        found = re.search(rf"^  {phase} +([0-9.e+-]+) ns +([0-9.]+) %$", result.stdout, re.M)
        if not found:
            fail(f"phase {phase} missing from the report: {result.stdout!r}")
        if not float(found.group(1)) > 0:
            fail(f"phase {phase} took no time: {found.group(0)!r}")
        shares.append(float(found.group(2)))
    if abs(sum(shares) - 100.0) > 0.5:
        fail(f"shares add up to {sum(shares)} %, not 100")
    plain = run(args)
    if plain.returncode != 0 or "phases:" in plain.stdout:
        fail(f"a run without --profile lists phases or failed: {plain.stdout!r}")


def case_velocity_tolerance():
    """--velocity-tolerance reaches the step: a tolerance above every change
    stops every world after one velocity pass, so the state digest is that of
    --velocity-iterations 1, and the report names the tolerance."""
    args = ["run", "--scene", "cartpole", "--worlds", "64", "--steps", "20", "--threads", "1"]
    tolerant = run(args + ["--velocity-tolerance", "1e6"])
    one_pass = run(args + ["--velocity-iterations", "1"])
    default = run(args)

    def digest(result):
        if result.returncode != 0:
            fail(f"exit code {result.returncode}, stderr {result.stderr!r}")
        found = re.search(r"^state digest: +([0-9a-f]+)", result.stdout, re.M)
        if not found:
            fail(f"no state digest in the report: {result.stdout!r}")
        return found.group(1)

    if not re.search(r"^velocity tolerance: +1e\+06 m/s and rad/s", tolerant.stdout, re.M):
        fail(f"the report does not name the tolerance: {tolerant.stdout!r}")
    if digest(tolerant) != digest(one_pass):
        fail("a tolerance of 1e6 did not step as one velocity pass")
    if digest(tolerant) == digest(default):
        fail("one velocity pass gave the default's ten passes' state: nothing is tested")


def mpirun(ranks, args, timeout=120):
    command = [os.environ["MPIEXEC"], "-n", str(ranks), "--oversubscribe", MANYWORLDS, *args]
    return subprocess.run(command, capture_output=True, text=True, timeout=timeout)


def report_line(stdout, key):
    found = re.search(rf"^ *{key}: +(.*)$", stdout, re.M)
    if not found:
        fail(f"no '{key}:' line in the report: {stdout!r}")
    return found.group(1)


def case_mpirun():
    args = ["run", "--scene", "ragdoll", "--worlds", "100", "--steps", "30", "--threads", "1"]
    alone = run(args)
    if alone.returncode != 0:
        fail(f"the run in one process failed: {alone.stderr!r}")
    for ranks in (2, 3):
        result = mpirun(ranks, args)
        if result.returncode != 0:
            fail(f"{ranks} ranks: exit code {result.returncode}, stderr {result.stderr!r}")
        if result.stdout.count("scene:") != 1:
            fail(f"{ranks} ranks: expected one report (rank 0's), got {result.stdout!r}")
        shares = re.fullmatch(rf"{ranks} \(MPI\), worlds per rank ([0-9 ]+)",
                              report_line(result.stdout, "ranks"))
        if not shares or sum(int(w) for w in shares.group(1).split()) != 100:
            fail(f"{ranks} ranks: the ranks line does not share 100 worlds: {result.stdout!r}")
        rates = report_line(result.stdout, "throughput per rank").split()[-ranks:]
        if not all(float(r) > 0 for r in rates):
            fail(f"{ranks} ranks: expected {ranks} positive rates: {rates}")
        waits = report_line(result.stdout, "per step, per rank").split()[-ranks:]
        if not all(float(w) >= 0 for w in waits):
            fail(f"{ranks} ranks: expected {ranks} times outside stepping: {waits}")
        if report_line(result.stdout, "worlds") != "100":
            fail(f"{ranks} ranks: the report does not cover 100 worlds: {result.stdout!r}")
        # The same worlds bit for bit: the same state digest, worst errors
        # and health. (The means are sums in another order: equal to
        # rounding only.)
        for key in ("state digest", "unhealthy worlds"):
            if report_line(result.stdout, key) != report_line(alone.stdout, key):
                fail(f"{ranks} ranks: '{key}' differs from one process")
        for key in ("linear", "angular"):
            worst = report_line(result.stdout, key).split(",")[0]
            if worst != report_line(alone.stdout, key).split(",")[0]:
                fail(f"{ranks} ranks: worst {key} error {worst!r} differs from one process")

    def expect_one_error(ranks, extra, code, *names):
        result = mpirun(ranks, ["run", "--scene", "cartpole", "--steps", "5", *extra])
        errors = [line for line in result.stderr.splitlines() if line.startswith("manyworlds:")]
        if result.returncode != code or len(errors) != 1 or result.stdout:
            fail(f"{ranks} ranks, {extra}: exit {result.returncode} (expected {code}), "
                 f"expected one error line and no report, got {result.stderr!r} {result.stdout!r}")
        for name in names:
            if name not in errors[0]:
                fail(f"{ranks} ranks, {extra}: the error does not name {name!r}: {errors[0]!r}")

    # Stopped by SIGUSR1 to mpirun (which forwards it to every rank; Ctrl-C
    # would end the job): every rank stops after the same step and rank 0
    # reports the steps done.
    command = [os.environ["MPIEXEC"], "-n", "2", "--oversubscribe", MANYWORLDS, *LONG_RUN]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(3.0)
    if process.poll() is not None:
        fail(f"the mpirun run ended before SIGUSR1: {process.communicate()}")
    process.send_signal(signal.SIGUSR1)
    stdout, stderr = process.communicate(timeout=60)
    found = re.search(r"interrupted by SIGUSR1 after step (\d+) of (\d+)", stdout)
    if not found or not 0 < int(found.group(1)) < int(found.group(2)):
        fail(f"SIGUSR1 under mpirun: no interrupted report: {stdout!r} {stderr!r}")
    if stdout.count("scene:") != 1 or "ranks:" not in stdout:
        fail(f"SIGUSR1 under mpirun: expected rank 0's report once: {stdout!r}")

    expect_one_error(2, ["--worlds", "0"], 2, "--worlds")
    expect_one_error(2, ["--record", "never.npz"], 2, "--record", "one process")
    expect_one_error(3, ["--worlds", "2"], 2, "--worlds 2", "every rank needs at least one world")
    if os.path.exists("never.npz"):
        fail("a refused --record left never.npz behind")


CASES = {
    "mpirun": case_mpirun,
    "profile": case_profile,
    "velocity-tolerance": case_velocity_tolerance,
    "errors": case_errors,
    "unknown-scene": case_unknown_scene,
    "scenes": case_scenes,
    "progress-pty": case_progress_pty,
    "progress-pipe": case_progress_pipe,
    "sigint": case_sigint,
}

if CASE not in CASES:
    fail(f"unknown case; cases: {', '.join(CASES)}")
CASES[CASE]()

#!/usr/bin/env bash
# ctest sweep_smoke: runs `manyworlds sweep --small` and checks what it wrote,
# so the sweep command cannot rot. Usage: sweep_smoke.sh MANYWORLDS OUT_DIR
set -euo pipefail
manyworlds=$1
out=$2
rm -rf "$out"
"$manyworlds" sweep --small --scenes rackpinion,chain16 --out "$out"

fail() { echo "sweep_smoke: $*" >&2; exit 1; }
csv=$out/sweep.csv
[ -s "$csv" ] || fail "$csv missing or empty"
[ -s "$out/sweep.md" ] || fail "$out/sweep.md missing or empty"
[ -s "$out/sweep.gp" ] || fail "$out/sweep.gp missing or empty"

expected='scene,knob,substeps,velocity_iterations,position_iterations,dt,worlds,threads,simd_target,ns_per_world_step,position_error_max,position_error_rms,velocity_residual_max,velocity_residual_rms,trajectory_position_rms,trajectory_position_max,trajectory_rotation_rms,trajectory_rotation_max,energy_drift_max,energy_drift_final,coupling_error_max,coupling_error_rms,unhealthy_worlds'
[ "$(head -n 1 "$csv")" = "$expected" ] || fail "header is '$(head -n 1 "$csv")'"

# --small: the default 1/10/2 plus one other value of each knob = 4 settings
# per scene, 2 scenes.
rows=$(tail -n +2 "$csv" | wc -l)
[ "$rows" -eq 8 ] || fail "$rows rows, expected 8"

# Every cost and error a finite, non-negative number; the energy columns
# present for chain16 only (it conserves energy), the coupling columns for
# rackpinion only; no world blew up.
tail -n +2 "$csv" | awk -F, '
  function finite(x) { return x ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ }
  {
    if (NF != 23) { print "row " NR ": " NF " fields"; bad = 1 }
    for (i = 10; i <= 18; ++i) if (!finite($i) || $i < 0) { print "row " NR " column " i ": " $i; bad = 1 }
    if ($10 <= 0) { print "row " NR ": no time measured"; bad = 1 }
    energy = ($1 == "chain16"); coupling = ($1 == "rackpinion")
    for (i = 19; i <= 20; ++i) if (energy != finite($i)) { print "row " NR " energy column " i ": \"" $i "\""; bad = 1 }
    for (i = 21; i <= 22; ++i) if (coupling != finite($i)) { print "row " NR " coupling column " i ": \"" $i "\""; bad = 1 }
    if ($23 != 0) { print "row " NR ": " $23 " unhealthy worlds"; bad = 1 }
  }
  END { exit bad }' || fail "bad numbers in $csv"

# Halving dt must bring chain16 closer to its dt/16 reference: the
# integrator is first order, so 2 substeps should roughly halve the
# trajectory error (measured: 0.0139 m -> 0.0059 m); a sweep that mixed up
# its settings or its reference would not show it.
awk -F, '$1 == "chain16" && $4 == 10 && $5 == 2 { e[$3] = $15 }
  END { if (!(e[2] < 0.75 * e[1])) { print "trajectory RMS at 2 substeps " e[2] " not below 0.75 x " e[1]; exit 1 } }' \
  "$csv" || fail "substeps do not reduce chain16's trajectory error"

# --solver exact: its own grid, every combination (--small: substeps 1 2,
# velocity iterations 2 10, Newton steps 2 4). Velocity iterations count only
# in scenes with motors, friction or limits: rackpinion (a motor) has all 8
# settings, chain16 only the 4 with the default 10. The exact solve holds
# chain16's joints where Gauss-Seidel leaves centimetres.
exact_out=$out/exact
"$manyworlds" sweep --small --solver exact --scenes rackpinion,chain16 --out "$exact_out"
exact_csv=$exact_out/sweep.csv
counts=$(tail -n +2 "$exact_csv" | awk -F, '{ n[$1]++; if ($1 == "chain16" && $4 != 10) bad = 1 }
  END { print n["rackpinion"] + 0, n["chain16"] + 0, bad + 0 }')
[ "$counts" = "8 4 0" ] || fail "exact rows (rackpinion, chain16, chain16 with velocity iterations other than 10): $counts, expected 8 4 0"
awk -F, '$1 == "chain16" && $5 == 4 && $3 == 1 { if (!($11 < 1e-4)) { print "chain16 exact joint error " $11; exit 1 } }' \
  "$exact_csv" || fail "the exact solve leaves chain16's joints open"
echo "sweep_smoke: $rows rows, header and numbers as expected; exact grid as expected"

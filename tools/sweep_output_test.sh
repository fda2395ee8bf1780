#!/usr/bin/env bash
# ctest sweep_output_<case>: what `manyworlds sweep` does with its output
# folder (issue 21). Usage: sweep_output_test.sh MANYWORLDS CASE, CASE one of
#   no-shell     folder names with ' ; $ spaces backquotes and a newline: the
#                reports and plots land in them and nothing they contain runs
#                (neither in a shell nor in gnuplot); gnuplot is found on PATH
#                and run in the folder as `gnuplot sweep.gp`, and its failure
#                is reported
#   unwritable   a folder that cannot be created or written to is refused
#                with one line naming it before any simulation
#   write-error  a report the disk does not take is an error naming it,
#                never "wrote"
#   existing     an earlier report is refused before any simulation unless
#                --overwrite
# Every case runs in its own temporary folder, removed at the end.
set -euo pipefail
manyworlds=$1
case=$2

tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp"; rm -rf "$tmp"' EXIT  # u+w: the read-only folder
cd "$tmp"

fail() { echo "sweep_output_test $case: $*" >&2; exit 1; }

# A sweep of one scene at the smallest settings: well under a second.
sweep() {
  "$manyworlds" sweep --small --scenes rackpinion --worlds 8 --sample-worlds 2 --seconds 0.05 \
    --min-time 0 "$@"
}

# Runs the sweep with the arguments given; sets $status and leaves its output
# in ./stdout and ./stderr.
run() {
  status=0
  sweep "$@" > stdout 2> stderr || status=$?
}

# The sweep failed with exit code 1 and one line on stderr that contains
# $1, and stepped nothing (its per-setting lines start with the scene id).
expect_refused_early() {
  [ "$status" -eq 1 ] || fail "exit code $status, expected 1; stderr: $(cat stderr)"
  [ "$(wc -l < stderr)" -eq 1 ] || fail "stderr is not one line: $(cat stderr)"
  grep -qF -- "$1" stderr || fail "stderr does not name '$1': $(cat stderr)"
  ! grep -q '^rackpinion' stdout || fail "it simulated before refusing: $(cat stdout)"
}

expect_reports_in() {
  local file
  for file in sweep.csv sweep.md sweep.gp; do
    [ -s "$1/$file" ] || fail "'$1/$file' missing or empty"
  done
}

case $case in
  no-shell)
    names=("x'; touch INJECTED; echo '"
           "it's a \$HOME; \$(touch INJECTED) \`touch INJECTED\` & dir"
           $'new\nsystem "touch INJECTED"\nline')
    for name in "${names[@]}"; do
      run --out "$name"
      # Every INJECTED file anywhere, also inside the folders: gnuplot runs there.
      injected=$(find "$tmp" -name 'INJECTED*')
      [ -z "$injected" ] || fail "--out '$name' ran a command: $injected exists"
      [ "$status" -eq 0 ] || fail "--out '$name': exit code $status: $(cat stderr)"
      expect_reports_in "$tmp/$name"
      if command -v gnuplot > /dev/null; then
        [ -s "$tmp/$name/rackpinion.png" ] || fail "no plot in '$name': $(cat stdout)"
      fi
    done

    # gnuplot is looked up on PATH and run in the folder with the argument
    # sweep.gp; its exit code is reported. A stand-in records how it ran.
    mkdir bin
    cat > bin/gnuplot <<'EOF'
#!/bin/sh
printf '%s\n' "$PWD" "$#" "$1" > "$CALL_LOG"
exit 3
EOF
    chmod +x bin/gnuplot
    name=${names[1]}
    rm -rf "${tmp:?}/$name"
    status=0
    CALL_LOG=$tmp/call PATH=$tmp/bin sweep --out "$name" > stdout 2> stderr || status=$?
    [ "$status" -eq 1 ] || fail "a gnuplot exiting with 3: exit code $status, expected 1"
    grep -q 'exited with code 3' stderr || fail "gnuplot's exit code not reported: $(cat stderr)"
    [ "$(cat call)" = "$(printf '%s\n' "$tmp/$name" 1 sweep.gp)" ] ||
      fail "gnuplot ran as: $(cat call)"

    # Without gnuplot on PATH: the reports, a note, exit code 0.
    rm -rf "${tmp:?}/$name"
    status=0
    PATH=$tmp/nothing-here sweep --out "$name" > stdout 2> stderr || status=$?
    [ "$status" -eq 0 ] || fail "without gnuplot: exit code $status: $(cat stderr)"
    grep -q 'gnuplot not found' stdout || fail "without gnuplot, no note: $(cat stdout)"
    expect_reports_in "$tmp/$name"
    ;;

  unwritable)
    # A folder that cannot be created: its parent is a file.
    touch file
    run --out file/sweep
    expect_refused_early "file/sweep"
    # A folder that exists but takes no file: a read-only one, or for root,
    # who writes through permission bits, /sys, where nobody creates files.
    if [ "$(id -u)" -ne 0 ]; then
      mkdir read-only
      chmod a-w read-only
      folder=$tmp/read-only
    elif [ -d /sys ] && ! touch /sys/manyworlds-probe 2> /dev/null; then
      folder=/sys
    else
      rm -f /sys/manyworlds-probe
      echo "sweep_output_test: no unwritable existing folder here, that half skipped"
      exit 0
    fi
    run --out "$folder"
    expect_refused_early "$folder"
    ;;

  write-error)
    # The folder takes an empty file (the probe) but no byte of a report:
    # a file-size limit of 0; writes fail with EFBIG instead of a signal.
    # The limit holds for every file the sweep writes to, so its output goes
    # through a pipe.
    status=0
    output=$( (ulimit -f 0; trap '' XFSZ; sweep --out out) 2>&1 ) || status=$?
    ! grep -q 'wrote' <<< "$output" || fail "it claims to have written: $output"
    [ "$status" -eq 1 ] || fail "exit code $status, expected 1: $output"
    grep -qF 'out/sweep.csv' <<< "$output" || fail "no error naming out/sweep.csv: $output"
    [ ! -e out/sweep.csv ] || fail "a partial out/sweep.csv was left behind"
    # A full disk: sweep.md a link to /dev/full, which takes no byte (ENOSPC).
    mkdir full
    ln -s /dev/full full/sweep.md
    run --out full --overwrite
    ! grep -q 'wrote' stdout || fail "it claims to have written: $(grep wrote stdout)"
    [ "$status" -eq 1 ] || fail "/dev/full: exit code $status, expected 1: $(cat stderr)"
    grep -qF 'full/sweep.md' stderr || fail "no error naming full/sweep.md: $(cat stderr)"
    ;;

  existing)
    # The reports and the plot, one at a time.
    files=(sweep.csv sweep.md sweep.gp rackpinion.png)
    for file in "${files[@]}"; do
      rm -rf out
      mkdir out
      echo keep > "out/$file"
      run --out out
      expect_refused_early "out/$file"
      grep -qF -- '--overwrite' stderr || fail "the error does not mention --overwrite"
      [ "$(cat "out/$file")" = keep ] || fail "out/$file was changed"
    done
    for file in "${files[@]}"; do echo keep > "out/$file"; done
    run --out out --overwrite
    [ "$status" -eq 0 ] || fail "--overwrite: exit code $status: $(cat stderr)"
    command -v gnuplot > /dev/null || unset 'files[3]'
    for file in "${files[@]}"; do
      [ "$(head -c 4 "out/$file")" != keep ] || fail "--overwrite did not replace out/$file"
    done
    ;;

  *) fail "unknown case" ;;
esac
echo "sweep_output_test $case: passed"

# Sourced by scripts/run and scripts/accuracy-report, which run the manyworlds
# program with defaults that their caller's arguments replace. The program
# refuses an option given twice (tools/options.h), so a default goes on the
# command line only when the caller does not give that option.
#
#   args=("$@"); defaults=()
#   default_option --worlds 4096   # appends to defaults unless args hold
#                                  # --worlds or --worlds=...
#   manyworlds run "${defaults[@]}" "${args[@]}"
default_option() {
  local arg
  for arg in "${args[@]}"; do
    [[ $arg == "$1" || $arg == "$1="* ]] && return 0
  done
  defaults+=("$@")
}

# shellcheck shell=bash
# Stage times for the build and test scripts (sourced, not run), so each run shows where its
# time goes. `stage NAME COMMAND...` runs COMMAND, prints how long it took (wall, and the CPU
# time of the processes it ran, which other work on the machine does not inflate) and keeps
# that line in $STAGE_TIMES; `stage_summary` (the scripts' EXIT trap) prints every line kept
# and the whole run's times, after a failure too. A script run by another (sanitize.sh by test.sh) adds
# its stages to the list of the one that ran it, which prints them all at its end.
if [ -z "${STAGE_TIMES:-}" ]; then
  STAGE_TIMES=$(mktemp "${TMPDIR:-/tmp}/patina-stages.XXXXXX")
  export STAGE_TIMES
  stages_owner=$$ stages_start=$SECONDS
fi

# CPU seconds (user and system) of this shell's finished children so far: cutime and cstime
# of /proc/PID/stat, fields 16 and 17 counted after the command name's closing parenthesis.
children_cpu() {
  local stat
  stat=$(</proc/$$/stat)
  awk -v ticks="$(getconf CLK_TCK)" '{ printf "%d", ($14 + $15) / ticks }' <<<"${stat##*) }"
}

stage() {
  # Names of its own, as the command sees the caller's variables (fuzz.sh's `status`).
  local stage_name=$1 stage_start=$SECONDS stage_cpu stage_exit=0 stage_line
  stage_cpu=$(children_cpu)
  shift
  "$@" || stage_exit=$?
  stage_line=$(printf '%-20s %5d s   cpu %5d s' "$stage_name" $((SECONDS - stage_start)) \
    $(($(children_cpu) - stage_cpu)))
  [ "$stage_exit" -eq 0 ] || stage_line+="  FAILED (exit $stage_exit)"
  echo "$stage_line" >>"$STAGE_TIMES"
  echo "stage: $stage_line"
  return "$stage_exit"
}

stage_summary() {
  [ "${stages_owner:-}" = $$ ] || return 0
  echo "stage times:"
  sed 's/^/  /' "$STAGE_TIMES"
  printf '  %-20s %5d s   cpu %5d s\n' "in all" $((SECONDS - stages_start)) "$(children_cpu)"
  rm -f "$STAGE_TIMES"
}

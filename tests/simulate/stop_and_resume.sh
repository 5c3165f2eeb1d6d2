# Sourced by the resume tests (needs $sim). stop_and_resume NAME SCENE...: the scene run uninterrupted to
# NAME-full.h5, and again to NAME-term.h5, stopped by SIGTERM a quarter of the way in (by the first
# run's time; exit status 1 and a checkpoint) and resumed from the checkpoint alone. The caller compares.
stop_and_resume() {
  local name=$1; shift
  local start seconds pid status
  start=$(date +%s.%N)
  "$sim" "$@" -o "$name-full.h5"
  seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  "$sim" "$@" -o "$name-term.h5" & pid=$!
  sleep "$(awk -v t="$seconds" 'BEGIN { print 0.25 * t }')"
  kill -TERM "$pid"
  status=0; wait "$pid" || status=$?
  [ "$status" -eq 1 ] || { echo "$name SIGTERM: exit status $status, expected 1 (0: the run ended first, machine too fast?)"; exit 1; }
  [ -f "$name-term.h5.checkpoint.h5" ] || { echo "$name: SIGTERM: no checkpoint written"; exit 1; }
  "$sim" --quiet -o "$name-term.h5" --resume "$name-term.h5.checkpoint.h5"
}

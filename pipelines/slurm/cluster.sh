#!/bin/bash
# cluster.sh: a private single-node Slurm (slurmctld + slurmd on this host) for tests and measurements.
#
#   pipelines/slurm/cluster.sh start DIR [--cpus N] [--munge]   # config, state, logs under DIR
#   export SLURM_CONF=DIR/slurm.conf                           # then sbatch/srun/squeue talk to it
#   pipelines/slurm/cluster.sh stop DIR                        # cancel its jobs, stop what start started
#
# start fills pipelines/slurm/slurm.conf (a template) into DIR/slurm.conf with this host's name, free
# ports and N CPUs (default: all), starts the daemons in the foreground of background processes (so
# their PIDs are known: DIR/pids), and waits until the node is idle. Authentication is auth/none (no
# munged); --munge uses auth/munge with a fresh key and a munged on a private socket instead.
# stop cancels the jobs, then ends exactly the processes start recorded, by PID (TERM, then KILL after
# a grace period), plus any leftover slurmstepd of this cluster (one that holds a file under DIR open)
# and the job processes under it. It is safe to call twice, and after a failed start.
# Needs root (slurmd runs jobs as their submitting user); Debian package slurm-wlm (22.05).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

die() { echo "cluster.sh: $*" >&2; exit 1; }

port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }
free_port() {  # first free TCP port from $1 on
  local p=$1
  while ! port_free "$p"; do p=$((p + 1)); done
  echo "$p"
}

# Running (a zombie waiting for init to reap it counts as ended).
# spawn LOG CMD...: start CMD in the background as a daemon of ours: own session (a Ctrl-C in the terminal
# reaches the caller's trap, which runs stop, not the daemons directly), stdin /dev/null, output to LOG,
# no inherited descriptor beyond 0-2 (a make jobserver pipe or a `| tee` must not stay open). $! is its PID.
spawn() {
  local log=$1; shift
  (
    for fd in "/proc/$BASHPID/fd"/*; do
      fd=${fd##*/}
      [ "$fd" -le 2 ] || exec {fd}>&-
    done
    exec setsid "$@" < /dev/null > "$log" 2>&1
  ) &
}

alive() {
  local st
  [ -n "$1" ] && st=$(awk '{ sub(/^.*\) /, ""); print $1 }' "/proc/$1/stat" 2>/dev/null) && [ -n "$st" ] && [ "$st" != Z ]
}

# Descendants of PID $1 (children first found by walking /proc/*/stat).
descendants() {
  local parent=$1 pid stat ppid
  for stat in /proc/[0-9]*/stat; do
    pid=${stat#/proc/}; pid=${pid%/stat}
    ppid=$(awk '{ sub(/^.*\) /, ""); print $2 }' "$stat" 2>/dev/null) || continue
    if [ "$ppid" = "$parent" ]; then descendants "$pid"; echo "$pid"; fi
  done
}

# End the given PIDs: TERM, wait up to $grace s, then KILL.
end_pids() {
  local grace=$1; shift
  local pid left i
  [ $# -gt 0 ] || return 0
  kill -TERM "$@" 2>/dev/null || true
  for ((i = 0; i < grace * 10; ++i)); do
    left=""
    for pid in "$@"; do alive "$pid" && left="$left $pid"; done
    [ -z "$left" ] && return 0
    sleep 0.1
  done
  echo "cluster.sh: still running after ${grace}s, sending KILL to:$left" >&2
  # shellcheck disable=SC2086
  kill -KILL $left 2>/dev/null || true
}

start() {
  local dir=$1; shift
  local cpus munge=0
  cpus=$(nproc)
  while [ $# -gt 0 ]; do
    case $1 in
      --cpus) cpus=$2; shift 2 ;;
      --munge) munge=1; shift ;;
      *) die "unknown option $1 (use --cpus N, --munge)" ;;
    esac
  done
  [ "$(id -u)" = 0 ] || die "needs root (slurmd must be able to run jobs as their user)"
  command -v slurmctld >/dev/null && command -v slurmd >/dev/null ||
    die "slurmctld/slurmd not found: apt-get install slurm-wlm (make -f Makefile.study test-slurm does it)"
  mkdir -p "$dir"
  dir=$(cd "$dir" && pwd)
  [ ! -s "$dir/pids" ] || die "$dir/pids exists: a cluster may still run there (cluster.sh stop $dir)"
  mkdir -p "$dir/state" "$dir/spool" "$dir/log"
  local host ctld_port slurmd_port auth=auth/none cred=cred/none authinfo=""
  host=$(hostname -s)
  ctld_port=$(free_port "${GG_SLURM_PORT:-16817}")
  slurmd_port=$(free_port $((ctld_port + 1)))
  : > "$dir/pids"

  if [ "$munge" = 1 ]; then
    command -v munged >/dev/null || die "munged not found: apt-get install munge"
    mkdir -p "$dir/munge"; chmod 700 "$dir/munge"
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$dir/munge/munge.key"
    spawn "$dir/log/munged.out" munged --foreground --force --key-file="$dir/munge/munge.key" \
      --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" --log-file="$dir/log/munged.log" \
      --seed-file="$dir/munge/seed"
    echo "munged $!" >> "$dir/pids"
    auth=auth/munge; cred=cred/munge
    authinfo="AuthInfo=socket=$dir/munge/munge.socket"   # used by cred/munge too
    local i
    for ((i = 0; i < 100; ++i)); do [ -S "$dir/munge/munge.socket" ] && break; sleep 0.1; done
    [ -S "$dir/munge/munge.socket" ] || die "munged did not start (see $dir/log/munged.log)"
  fi

  awk -v host="$host" -v cp="$ctld_port" -v sp="$slurmd_port" -v user="$(id -un)" -v dir="$dir" \
      -v cpus="$cpus" -v auth="$auth" -v cred="$cred" -v authinfo="$authinfo" '
    { gsub(/@HOST@/, host); gsub(/@CTLD_PORT@/, cp); gsub(/@SLURMD_PORT@/, sp); gsub(/@USER@/, user)
      gsub(/@DIR@/, dir); gsub(/@CPUS@/, cpus); gsub(/@AUTH@/, auth); gsub(/@CRED@/, cred)
      if ($0 == "@AUTHINFO@") $0 = authinfo
      print }' "$here/slurm.conf" > "$dir/slurm.conf"
  export SLURM_CONF=$dir/slurm.conf

  # -D: stay in the foreground (we keep the PID); -c: clear any saved state; -i: ignore state errors.
  spawn "$dir/log/slurmctld.out" slurmctld -D -c -i -f "$SLURM_CONF"
  echo "slurmctld $!" >> "$dir/pids"
  spawn "$dir/log/slurmd.out" slurmd -D -f "$SLURM_CONF"
  echo "slurmd $!" >> "$dir/pids"

  local state="" i
  for ((i = 0; i < 300; ++i)); do
    state=$(sinfo -h -N -o %t 2>/dev/null | head -n1) || true
    case $state in idle|mix|alloc) break ;; esac
    while read -r name pid; do
      alive "$pid" || die "$name exited during start (see $dir/log/$name.log and $dir/log/$name.out)"
    done < "$dir/pids"
    sleep 0.2
  done
  case $state in idle|mix|alloc) ;; *) die "node not ready after 60 s (state '$state'; see $dir/log/)" ;; esac
  echo "cluster.sh: single-node Slurm up: $cpus CPUs on $host, ports $ctld_port/$slurmd_port, $auth; SLURM_CONF=$SLURM_CONF" >&2
}

stop() {
  local dir=$1
  [ -d "$dir" ] || return 0
  dir=$(cd "$dir" && pwd)
  [ -f "$dir/pids" ] || return 0
  export SLURM_CONF=$dir/slurm.conf
  local ctld
  ctld=$(awk '$1 == "slurmctld" { print $2 }' "$dir/pids")
  # Cancel the jobs while the controller is up, and give them a moment to end cleanly.
  if alive "$ctld" && [ -f "$SLURM_CONF" ]; then
    local jobs i
    jobs=$(squeue -h -o %A 2>/dev/null || true)
    if [ -n "$jobs" ]; then
      # shellcheck disable=SC2086
      scancel $jobs 2>/dev/null || true
      for ((i = 0; i < 150; ++i)); do
        [ -z "$(squeue -h -o %A 2>/dev/null || true)" ] && break
        sleep 0.2
      done
    fi
  fi
  # Daemons in reverse start order: slurmd, slurmctld, munged.
  local pids
  pids=$(tac "$dir/pids" | awk '{ print $2 }')
  local pid
  for pid in $pids; do
    alive "$pid" && end_pids 15 "$pid"
  done
  # Leftover step daemons of this cluster (and the job processes under them): the slurmstepd processes
  # that hold a file under DIR open (slurmd's log, which they inherit).
  local stepds="" f spid l
  for f in /proc/[0-9]*/comm; do
    spid=${f#/proc/}; spid=${spid%/comm}
    [ "$(cat "$f" 2>/dev/null)" = slurmstepd ] || continue
    for l in "/proc/$spid/fd"/*; do
      case $(readlink "$l" 2> /dev/null) in "$dir"/*) stepds="$stepds $spid"; break ;; esac
    done
  done
  if [ -n "$stepds" ]; then
    local all=""
    for pid in $stepds; do all="$all $(descendants "$pid" | tr '\n' ' ') $pid"; done
    echo "cluster.sh: ending leftover step processes:$all" >&2
    # shellcheck disable=SC2086
    end_pids 5 $all
  fi
  : > "$dir/pids"
  echo "cluster.sh: single-node Slurm in $dir stopped" >&2
}

case ${1:-} in
  start) [ $# -ge 2 ] || die "usage: cluster.sh start DIR [--cpus N] [--munge]"; shift; start "$@" ;;
  stop)  [ $# -eq 2 ] || die "usage: cluster.sh stop DIR"; stop "$2" ;;
  *) die "usage: cluster.sh start DIR [--cpus N] [--munge] | stop DIR" ;;
esac

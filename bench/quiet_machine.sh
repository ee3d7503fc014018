# Sourced by the benchmarks: timing that cannot flatter. Every timed run records the 1-minute
# load average before it starts and its CPU share (CPU seconds of the run / wall seconds /
# threads): a run that another process slowed shows a low share. Ratios come from alternating
# pairs and are reported as min / median / max.
#
# Needs $threads and $work (a scratch folder). Provides: require_quiet_machine MAX_LOAD, timed_run NAME COMMAND ARGS...
# (sets timed_seconds and timed_note), summarize_ratios LABEL RATIO..., median VALUE...,
# geometric_mean RATIO...,
# install_debian_packages PACKAGE...

load_average() { cut -d' ' -f1 /proc/loadavg; }

# Refuses to benchmark on a busy machine: waits up to 3 minutes for the 1-minute load average to
# fall under MAX_LOAD (our own build may have just finished), then gives up.
require_quiet_machine() {
  local max=$1 waited=0
  while awk -v l="$(load_average)" -v m="$max" 'BEGIN {exit !(l > m)}'; do
    if ((waited >= 180)); then
      echo "the machine is not quiet: load average $(load_average) > $max after 3 minutes; rerun when it is" >&2
      exit 1
    fi
    sleep 10
    waited=$((waited + 10))
  done
  echo "load average at start: $(load_average) (limit $max)" >&2
}

# CPU seconds (user + system) used so far by finished children of this shell, into $1. `times`
# must run in this shell, not in a $(...) subshell, whose children are not ours.
children_cpu_seconds() {
  local quiet_machine_times="$work/.times"
  times >"$quiet_machine_times"
  printf -v "$1" '%s' "$(awk 'NR == 2 {
    split($1, u, /[ms]/); split($2, s, /[ms]/); print u[1] * 60 + u[2] + s[1] * 60 + s[2] }' "$quiet_machine_times")"
}

# timed_run NAME COMMAND ARGS...: runs the command, sets timed_seconds (wall) and timed_note
# ("load L, CPU share S"); a share under 0.8 is marked "SLOWED" (something else ran).
timed_run() {
  local name=$1 load cpu0 cpu1 t0 t1
  shift
  load=$(load_average)
  children_cpu_seconds cpu0
  t0=$(date +%s.%N)
  "$@"
  t1=$(date +%s.%N)
  children_cpu_seconds cpu1
  timed_seconds=$(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", b - a}')
  timed_note=$(awk -v l="$load" -v c="$(echo "$cpu1 - $cpu0" | bc)" -v w="$timed_seconds" -v t="$threads" 'BEGIN {
    share = c / w / t; printf "load %.2f, CPU share %.2f%s", l, share, share < 0.8 ? " SLOWED" : "" }')
}

median() { printf '%s\n' "$@" | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
# The geometric mean of ratios: over an even number of rounds whose runs swap cores, a fixed
# difference between the cores' speeds cancels in it (bench/ab_pair.sh).
geometric_mean() { printf '%s\n' "$@" | awk '{s += log($1)} END {print exp(s / NR)}'; }

summarize_ratios() {
  local label=$1
  shift
  printf '%s\n' "$@" | sort -g | awk -v label="$label" '{a[NR] = $1} END {
    m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2
    printf "%s over %d alternating pairs: median %.3f (min %.3f, max %.3f)\n", label, NR, m, a[1], a[NR] }'
}

install_debian_packages() {
  local sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "$@" >&2
}

#!/usr/bin/env bash
# Soak: one process taking a long run of work must hold a flat resident memory once warm.
#   frames:  `radiant render --frames 0-(N-1)` of an animated glTF (assets/models/turntable.gltf)
#   session: `radiant session` fed M commands (moves, turns, sets, saves, infos and garbage)
#   batch:   `radiant batch` of V render lines (views from different places)
# Tiny images at 1 spp, so the run measures what stays behind, not the renders. VmRSS is read
# from /proc/PID/status every 0.1 s with the progress made so far (frames or views written,
# session renders finished); "first" is the median of the samples taken between 10% and 20% of
# the progress (after the first frames), "last" of those after 90%; growth is
# (last - first) / first. Exit 1 when any growth reaches --max-growth percent.
#
# Usage: bench/soak.sh [--radiant PATH] [--frames 1000] [--commands 10000] [--views 1000]
#                      [--size 16] [--max-growth 1]
set -euo pipefail
cd "$(dirname "$0")/.."
radiant="" frames=1000 commands=10000 views=1000 size=16 max_growth=1
while (($#)); do
  case $1 in
    --radiant) radiant=$(realpath "$2"); shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --commands) commands=$2; shift 2 ;;
    --views) views=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --max-growth) max_growth=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
if [ -z "$radiant" ]; then
  cmake --build build --target radiant -j2 >/dev/null
  radiant=$(realpath build/radiant)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=$(realpath assets/models/turntable.gltf)
flags=(--width "$size" --height "$size" --spp 1 --threads 1)
failed=0

# Samples "progress VmRSS(KiB)" of process $1 into file $2 until it exits, the progress being the
# output of command $3; returns the process's exit code.
sample_rss() {
  local pid=$1 out=$2 progress=$3 rss
  while kill -0 "$pid" 2>/dev/null; do
    rss=$(awk '/^VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null || true)
    [ -n "$rss" ] && echo "$(eval "$progress" 2>/dev/null) $rss" >>"$out"
    sleep 0.1
  done
  wait "$pid"
}

# Prints first, last, peak and growth of the samples in $2 for run $1.
report() {
  python3 - "$1" "$2" "$max_growth" <<'PY'
import statistics, sys
name, path, limit = sys.argv[1], sys.argv[2], float(sys.argv[3])
samples = [tuple(map(int, line.split())) for line in open(path) if len(line.split()) == 2]
total = max((p for p, _ in samples), default=0)
early = [r for p, r in samples if 0.1 * total <= p <= 0.2 * total]
late = [r for p, r in samples if p >= 0.9 * total]
rss = [r for _, r in samples]
if not early or not late:
    print(f"{name}: {len(samples)} samples do not cover the run; run longer"); sys.exit(1)
first, last = statistics.median(early), statistics.median(late)
growth = 100 * (last - first) / first
print(f"{name}: {len(rss)} samples, first {first / 1024:.1f} MiB, last {last / 1024:.1f} MiB, "
      f"peak {max(rss) / 1024:.1f} MiB, growth {growth:+.2f}%")
sys.exit(1 if growth >= limit else 0)
PY
}

# ---------------------------------------------------------------- frames
mkdir -p "$work/frames"
"$radiant" render "$scene" --frames "0-$((frames - 1))" --fps 24 -o "$work/frames/f-####.png" "${flags[@]}" -q &
sample_rss $! "$work/frames.rss" "ls '$work/frames' | wc -l" || { echo "frames: radiant failed" >&2; failed=1; }
echo "frames written: $(ls "$work/frames" | wc -l) of $frames"
report "frames ($frames)" "$work/frames.rss" || failed=1
rm -rf "$work/frames"

# ---------------------------------------------------------------- session
mkfifo "$work/commands"
touch "$work/session.out"
"$radiant" session "$scene" -o "$work/session.png" "${flags[@]}" <"$work/commands" >"$work/session.out" 2>"$work/session.err" &
pid=$!
python3 - "$commands" "$work" >"$work/commands" <<'PY' &
import random, sys, time
count, work = int(sys.argv[1]), sys.argv[2]
rng = random.Random(1)
def command(i):
    kind = i % 10
    if kind == 0: return f"moveto {rng.uniform(-4, 4):.3f} {rng.uniform(0.5, 3):.3f} {rng.uniform(3, 6):.3f}"
    if kind == 1: return f"move {rng.uniform(-0.1, 0.1):.3f} 0 {rng.uniform(-0.1, 0.1):.3f}"
    if kind == 2: return f"turn 0 {rng.uniform(-5, 5):.2f} 0"
    if kind == 3: return "turnto 0 -0.3 -1"
    if kind == 4: return f"set seed {i}"
    if kind == 5: return f"set env-color {rng.random():.2f},{rng.random():.2f},{rng.random():.2f}"
    if kind == 6: return f"save {work}/saved-{i % 7}.png"
    if kind == 7: return "info"
    if kind == 8: return rng.choice(["frobnicate", "move 1 2", "set spp -3", "moveto x y z", "size 0 0", "#"])
    return "wait"
for i in range(count):
    print(command(i), flush=True)
    if i % 50 == 49: time.sleep(0.05)  # spread the run over time, as a client would
print("quit", flush=True)
PY
sample_rss $pid "$work/session.rss" "wc -l <'$work/session.out'" || true  # garbage lines make the exit code 2
wait
echo "session: $(wc -l <"$work/session.out") renders finished, $(wc -l <"$work/session.err") error lines"
report "session ($commands commands)" "$work/session.rss" || failed=1

# ---------------------------------------------------------------- batch
mkdir -p "$work/views"
{
  echo "scene $scene"
  for ((i = 0; i < views; i++)); do
    echo "render -o views/v-$i.png --width $size --height $size --spp 1 --threads 1 --seed $i" \
         "--look-from $((i % 7 - 3)),2,$((4 + i % 3)) --look-at 0,0.5,0"
  done
} >"$work/views.txt"
"$radiant" batch "$work/views.txt" -q &
sample_rss $! "$work/batch.rss" "ls '$work/views' | wc -l" || { echo "batch: radiant failed" >&2; failed=1; }
echo "views written: $(ls "$work/views" | wc -l) of $views"
report "batch ($views views)" "$work/batch.rss" || failed=1
exit $failed

#!/usr/bin/env bash
# radiant's Whitted ray tracer against POV-Ray 3.7 on the same scene: five spheres (a mirror
# ball, a glossy red, a gold, a blue and a grey), a floor and a back wall, two point lights
# without attenuation, an ambient light, Phong highlights and mirror reflection up to 6 levels,
# 81 jittered samples per pixel. POV-Ray's lighting model matches the .scene format's classic
# one term by term (diffuse = pigment * diffuse * light * cos, ambient = pigment * ambient *
# ambient_light, phong = phong * (R.V)^phong_size * light, reflection), so both trace the same
# rays; POV-Ray is left-handed, and `right -x` in its camera makes it right-handed like radiant.
# With +A0.0 +AM1 +R9 POV-Ray supersamples every pixel that differs from a neighbour with a
# jittered 9x9 grid; the back wall leaves no flat background, and the script reads POV-Ray's
# own statistics to check that it took 81 samples per pixel.
#
# Runs alternate; each pair gives one time ratio. Reported: min/median/max of the ratios, and
# the 1-minute load average and the CPU share (CPU seconds / wall seconds / threads) of every
# run, so a run slowed by another process is visible. The script refuses to start when the
# load average is above --max-load (the machine is not quiet).
#
# Usage: bench/povray_whitted.sh [--size 512] [--repeats 5] [--threads 2] [--max-load 0.5]
#        KEEP_IMAGES=PREFIX keeps both images as PREFIX-povray.png and PREFIX-radiant.png
# Needs: povray (Debian package povray; installed here on first use, not in CI).
set -euo pipefail
cd "$(dirname "$0")/.."
size=512 repeats=5 threads=2 max_load=0.5
while (($#)); do
  case $1 in
    --size) size=$2; shift 2 ;;
    --repeats) repeats=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --max-load) max_load=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
source bench/quiet_machine.sh
command -v povray >/dev/null || install_debian_packages povray
cmake --build build --target radiant -j2 >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name  x y z  radius  r g b (pigment = kd)  ambient  phong  phong_size  reflection
spheres="mirror -1.6 1 -0.4 1 0.05 0.05 0.05 0.05 0.8 300 0.85
red 1.3 0.7 0.4 0.7 0.75 0.12 0.1 0.1 0.6 80 0.15
gold 0.2 0.35 1.8 0.35 0.55 0.42 0.1 0.1 0.8 120 0.35
blue -0.2 0.5 0.9 0.5 0.1 0.25 0.8 0.1 0.7 120 0.1
grey 2.6 0.45 -1.2 0.45 0.7 0.7 0.7 0.1 0.3 30 0"
# name  point  normal  r g b  ambient phong phong_size reflection
planes="floor 0 0 0 0 1 0 0.6 0.57 0.5 0.1 0.1 10 0.06
wall 0 0 -4 0 0 1 0.36 0.45 0.6 0.1 0.05 5 0"
# x y z  r g b (1 = 255 in the .scene scale)
lights="4 6 5 0.9 0.85 0.8
-5 4 3 0.35 0.35 0.4"

{
  echo "#version 3.7;"
  echo "global_settings { max_trace_level 6 adc_bailout 0.001 ambient_light rgb <1, 1, 1> assumed_gamma 1.0 }"
  echo "camera { perspective location <0, 2, 8> look_at <0, 0.8, 0> right -x up y angle 40 }"
  while read -r x y z r g b; do echo "light_source { <$x, $y, $z> color rgb <$r, $g, $b> }"; done <<<"$lights"
  while read -r name x y z radius r g b ka ks n kr; do
    echo "sphere { <$x, $y, $z>, $radius pigment { color rgb <$r, $g, $b> }" \
      "finish { ambient $ka diffuse 1 phong $ks phong_size $n reflection $kr } }"
  done <<<"$spheres"
  while read -r name px py pz nx ny nz r g b ka ks n kr; do
    echo "plane { <$nx, $ny, $nz>, $(awk -v px="$px" -v py="$py" -v pz="$pz" -v nx="$nx" -v ny="$ny" -v nz="$nz" \
      'BEGIN {print px * nx + py * ny + pz * nz}') pigment { color rgb <$r, $g, $b> }" \
      "finish { ambient $ka diffuse 1 phong $ks phong_size $n reflection $kr } }"
  done <<<"$planes"
} >"$work/whitted.pov"

# The same scene in radiant's format: colours on the 0-255 scale, ka = ambient * pigment
# (radiant's ambient term is ka * A; POV-Ray's is pigment * ambient * ambient_light).
{
  echo "@camera"
  echo "position 0 2 8"
  echo "look-at 0 0.8 0"
  echo "up 0 1 0"
  echo "fov 40"
  echo "@light ambient"
  echo "color 255 255 255"
  while read -r x y z r g b; do
    echo "@light point"
    echo "position $x $y $z"
    echo "color $(awk -v r="$r" -v g="$g" -v b="$b" 'BEGIN {print r * 255, g * 255, b * 255}')"
  done <<<"$lights"
  material() {  # r g b ka ks n kr
    awk -v r="$1" -v g="$2" -v b="$3" -v ka="$4" -v ks="$5" -v n="$6" -v kr="$7" 'BEGIN {
      printf "kd %s %s %s\nka %g %g %g\nks %s\nshininess %s\nkr %s\n", r, g, b, ka * r, ka * g, ka * b, ks, n, kr }'
  }
  while read -r name x y z radius r g b ka ks n kr; do
    echo "@sphere"
    echo "center $x $y $z"
    echo "radius $radius"
    material "$r" "$g" "$b" "$ka" "$ks" "$n" "$kr"
  done <<<"$spheres"
  while read -r name px py pz nx ny nz r g b ka ks n kr; do
    echo "@plane"
    echo "point $px $py $pz"
    echo "normal $nx $ny $nz"
    material "$r" "$g" "$b" "$ka" "$ks" "$n" "$kr"
  done <<<"$planes"
} >"$work/whitted.scene"

run_povray() {
  povray -D +I"$work/whitted.pov" +O"$1" +W"$size" +H"$size" +A0.0 +AM1 +R9 +J1.0 +WT"$threads" +FN +GS \
    >"$work/povray.log" 2>&1
}
run_radiant() {
  build/radiant render "$work/whitted.scene" -o "$1" --width "$size" --height "$size" --spp 81 --sampler jittered \
    --mode whitted --max-depth 6 --threads "$threads" --quiet
}

require_quiet_machine "$max_load"
keep=${KEEP_IMAGES:-}
povray_times=() radiant_times=() ratios=() log=""
for ((i = 0; i < repeats; i++)); do
  timed_run povray run_povray "$work/povray.png"
  p=$timed_seconds p_note=$timed_note
  timed_run radiant run_radiant "$work/radiant.png"
  r=$timed_seconds r_note=$timed_note
  povray_times+=("$p") radiant_times+=("$r") ratios+=("$(echo "$r / $p" | bc -l)")
  log+="| $((i + 1)) | $p ($p_note) | $r ($r_note) | $(printf '%.3f' "$(echo "$r / $p" | bc -l)") |"$'\n'
done
samples_per_pixel=$(awk '/Smpls\/Pxl/ {print $NF}' "$work/povray.log")
samples=$(awk '/Samples:/ {print $4}' "$work/povray.log")
difference=$(oiiotool "$work/radiant.png" "$work/povray.png" --diff 2>&1 | awk '/Mean error/ {print $NF}' || true)

echo "Whitted scene (5 spheres, floor, wall, 2 point lights, ambient, reflection depth 6), ${size}x${size}, 81 jittered spp, $threads threads"
echo "POV-Ray samples: $samples ($(awk -v s="$samples" -v n="$size" 'BEGIN {printf "%.2f", s / (n * n)}') per pixel; its own Smpls/Pxl counts edge pixels twice: $samples_per_pixel)"
echo "mean absolute difference of the two 8-bit images: ${difference:-?}"
echo
echo "| pair | POV-Ray s (load, CPU share) | radiant s (load, CPU share) | radiant / POV-Ray |"
echo "|---|---|---|---|"
printf '%s' "$log"
echo
summarize_ratios "radiant / POV-Ray" "${ratios[@]}"
echo "median wall time: POV-Ray $(median "${povray_times[@]}") s, radiant $(median "${radiant_times[@]}") s"
if [[ -n $keep ]]; then cp "$work/povray.png" "$keep-povray.png"; cp "$work/radiant.png" "$keep-radiant.png"; fi

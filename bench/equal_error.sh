# Sourced by the equal-noise benchmarks: an image's noise measured against a converged reference
# without letting the reference flatter it.
#
# The measured image and its reference must not share samples: a render at n spp with the same
# seed as a reference at N spp is the first part of the reference's own sample sequence, and
# with a low-discrepancy sampler its error then looks far smaller than it is. So references are
# rendered with other seeds. What remains is the reference's own error, which adds to the
# measured one: E^2 = e_n^2 + e_N^2 for independent images. Two references with two seeds give
# e_N^2 = RMS(ref1 - ref2)^2 / 2, and the image's own error is sqrt(E^2 - e_N^2).
#
# Images are compared as linear values clamped to [0, 1] (oiiotool's RMS error).
# Needs oiiotool (openimageio-tools).

# rms_error A B: the RMS difference of two images (oiiotool --diff exits non-zero when they differ).
rms_error() { { oiiotool "$1" "$2" --diff 2>&1 || true; } | awk '/RMS error/ {print $NF}'; }

# clamped_linear IN OUT: IN's values clamped to [0, 1], as float (the comparison space).
clamped_linear() { oiiotool "$1" --ch R,G,B --clamp:min=0:max=1 -d float -o "$2"; }

# reference_error REF1 REF2: the error of one reference, from two with different seeds.
reference_error() { awk -v d="$(rms_error "$1" "$2")" 'BEGIN {printf "%.6g", d / sqrt(2)}'; }

# own_error E REFERENCE_ERROR: an image's error with its independent reference's error removed.
own_error() { awk -v e="$1" -v r="$2" 'BEGIN {v = e * e - r * r; printf "%.6g", (v > 0 ? sqrt(v) : 0)}'; }

# nested_own_error E n N: the error of the first n of a reference's N independent samples, for a
# renderer whose seed cannot be changed (Embree's tutorial): E^2 = sigma^2 (1/n - 1/N), so
# e_n = E sqrt(N / (N - n)).
nested_own_error() { awk -v e="$1" -v n="$2" -v N="$3" 'BEGIN {printf "%.6g", e * sqrt(N / (N - n))}'; }

# mean_value IMAGE: the mean of its R, G and B values (the level a relative error is relative to).
mean_value() {
  oiiotool "$1" --ch R,G,B --printstats 2>/dev/null | awk '/Stats Avg:/ {printf "%.6g", ($3 + $4 + $5) / 3; exit}'
}

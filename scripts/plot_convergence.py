#!/usr/bin/env python3
"""Draws the chart of `radiant converge`: error against render time on log-log axes, one line
per series (mode or sampler), with a 1/sqrt(t) guide line.

Usage: plot_convergence.py converge.json converge.png
radiant passes a temporary for converge.png and renames it into place itself.
Exit codes: 0 written, 2 usage or unreadable JSON, 3 matplotlib missing.
"""
import json
import math
import os
import sys


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return 3
    json_path, png_path = sys.argv[1], sys.argv[2]
    try:
        with open(json_path) as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        print(f"plot_convergence.py: cannot read {json_path}: {e}", file=sys.stderr)
        return 2

    metric = report.get("metric", "rmse")
    figure, axes = plt.subplots(figsize=(6.4, 4.4), dpi=100)
    anchor = None
    for series in report["series"]:
        points = [(s["seconds"], s[metric], s["spp"]) for s in series["steps"]
                  if s["seconds"] and s[metric] and s["seconds"] > 0 and s[metric] > 0]
        if not points:
            continue
        times, errors, spps = zip(*points)
        exponent = series.get("fit", {}).get("exponent")
        label = series["name"] + (f" (RMSE ∝ spp^{exponent:.2f})" if exponent is not None and metric == "rmse" else "")
        line, = axes.plot(times, errors, marker="o", markersize=4, label=label)
        for t, e, spp in points:
            if report.get("kind") == "supersampling" or spp in (1, 16, 256, 4096):
                axes.annotate(f"{spp}", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7,
                              color=line.get_color())
        if anchor is None:
            anchor = (times, errors)

    if anchor:  # the Monte Carlo rate through the first series' middle point
        times, errors = anchor
        middle = len(times) // 2
        t0, e0 = times[middle], errors[middle]
        guide_t = [min(times), max(times)]
        guide_e = [e0 * math.sqrt(t0 / t) for t in guide_t]
        axes.plot(guide_t, guide_e, linestyle="--", color="gray", linewidth=1, label="1/√t guide")

    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("render time (s, measured)")
    axes.set_ylabel("edge RMSE (linear radiance)" if metric == "edge_rmse" else "RMSE (linear radiance)")
    axes.set_title(report.get("title", os.path.basename(report.get("scene", ""))), fontsize=10)
    axes.grid(True, which="both", linewidth=0.3)
    axes.legend(fontsize=8)
    figure.tight_layout()
    # How the chart was made (radiant's Software, Comment and radiant:* keys) as PNG text chunks,
    # which matplotlib writes as tEXt: Latin-1, so other characters become '?'.
    metadata = {name: value.encode("latin-1", "replace").decode("latin-1")
                for name, value in (report.get("metadata") or {}).items()}
    figure.savefig(png_path, format="png", metadata=metadata)
    return 0


if __name__ == "__main__":
    sys.exit(main())

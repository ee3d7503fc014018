#!/usr/bin/env python3
"""Reruns the two accuracy reports of docs/accuracy.md and refreshes it:

  1. assets/cornell.gltf, path against naive: RMSE against render time, 1 to 256 spp.
  2. assets/showcase.scene, Whitted supersampling: 1, 81 and 324 spp for each sampler,
     error at edges and time multiples of 1 spp.

The CSV, JSON and PNG of each go to docs/accuracy/; the tables between the
<!-- NAME:begin --> and <!-- NAME:end --> markers of docs/accuracy.md are rewritten.
About 3 minutes on 2 cores.

Usage: bench/accuracy.py [--radiant build/radiant] [--threads 2] [--tables-only]
(--tables-only rebuilds the tables from the JSON already in docs/accuracy/, rendering nothing)
"""
import argparse, json, os, re, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "docs", "accuracy")
DOC = os.path.join(ROOT, "docs", "accuracy.md")

REPORTS = [
    # (marker, stem, arguments)
    ("cornell", "converge", ["assets/cornell.gltf", "--mode", "path,naive", "--width", "96", "--height", "96",
                             "--max-spp", "256", "--reference-spp", "2048", "--target-error", "0.01"]),
    ("showcase", "supersampling", ["assets/showcase.scene", "--supersampling", "--width", "96", "--height", "54",
                                   "--spp-ladder", "1,81,324", "--reference-spp", "4096", "--timing-runs", "3"]),
]


def number(value, digits=4):
    return "—" if value is None else f"{value:.{digits}g}"


def ladder_table(report):
    rows = ["| mode | spp | seconds | rays | RMSE | relMSE | PSNR (dB) | time × 1 spp |", "|---|---|---|---|---|---|---|---|"]
    for series in report["series"]:
        for s in series["steps"]:
            rows.append(f"| {series['name']} | {s['spp']} | {s['seconds']:.3f} | {s['rays']:,} | {number(s['rmse'])} | "
                        f"{number(s['relative_mse'])} | {s['psnr']:.1f} | {s['time_multiple']:.1f} |")
    rows.append("")
    for series in report["series"]:
        fit, p = series["fit"], series.get("prediction")
        line = f"- {series['name']}: RMSE ≈ {fit['scale']:.3g} · spp^{fit['exponent']:.2f}"
        if p and p["spp"] is not None:
            line += f"; RMSE {report['target_error']:g} predicted at ≈ {p['spp']:.0f} spp, {p['seconds']:.2g} s"
        rows.append(line)
    return rows


def supersampling_table(report):
    pixels = report["width"] * report["height"]
    rows = ["| sampler | spp | seconds | µs per sample | time × 1 spp | edge RMSE | edge RMSE × 1 spp | RMSE (whole image) |",
            "|---|---|---|---|---|---|---|---|"]
    for series in report["series"]:
        first = series["steps"][0]["edge_rmse"]
        for s in series["steps"]:
            rows.append(f"| {series['name']} | {s['spp']} | {s['seconds']:.3f} | {s['seconds'] * 1e6 / (pixels * s['spp']):.2f} | "
                        f"{s['time_multiple']:.0f} | "
                        f"{number(s['edge_rmse'])} | {s['edge_rmse'] / first:.3f} | {number(s['rmse'])} |")
    return rows


def replace_block(text, marker, rows):
    block = f"<!-- {marker}:begin -->\n" + "\n".join(rows) + f"\n<!-- {marker}:end -->"
    pattern = re.compile(rf"<!-- {marker}:begin -->.*?<!-- {marker}:end -->", re.S)
    if not pattern.search(text):
        sys.exit(f"accuracy.py: docs/accuracy.md has no <!-- {marker}:begin/end --> markers")
    return pattern.sub(lambda _: block, text)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--radiant", default=os.path.join(ROOT, "build", "radiant"))
    parser.add_argument("--threads", default="2")
    parser.add_argument("--tables-only", action="store_true")
    args = parser.parse_args()
    os.makedirs(OUT, exist_ok=True)
    with open(DOC) as f:
        doc = f.read()
    for marker, stem, arguments in REPORTS:
        command = [args.radiant, "converge", *arguments, "--threads", args.threads, "--out", OUT]
        if not args.tables_only:
            print("+", " ".join(command), file=sys.stderr)
            subprocess.run(command, check=True, cwd=ROOT)
        with open(os.path.join(OUT, stem + ".json")) as f:
            report = json.load(f)
        reference = report["references"][0]
        rows = [f"Reference: {reference['mode']}, {reference['spp']} spp ({reference['seconds']:.0f} s); "
                f"{report['width']}×{report['height']} pixels.", ""]
        rows += ladder_table(report) if stem == "converge" else supersampling_table(report)
        doc = replace_block(doc, marker, rows)
    with open(DOC, "w") as f:
        f.write(doc)
    print(f"accuracy.py: refreshed {os.path.relpath(DOC, ROOT)} and {os.path.relpath(OUT, ROOT)}/", file=sys.stderr)


if __name__ == "__main__":
    main()

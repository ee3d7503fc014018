#!/usr/bin/env python3
"""Measures what unused effects cost: each scene rendered by the integrator specialised to its
effect set and by the generic all-effects integrator (--effects=all), alternately, same seed.
Prints a Markdown table (times are medians; the ratio is measured in the same run) and checks
that both images are byte-identical.

Usage: bench/effects.py [--radiant build/radiant] [--repeats 5] [--out docs/effects-table.md]
"""
import argparse, filecmp, json, os, statistics, subprocess, sys, tempfile

SCENES = [
    # (scene, mode, size, spp)
    ("assets/first-render.scene", "whitted", 400, 16),
    ("assets/showcase.scene", "whitted", 320, 16),
    ("assets/room-older-format.scene", "path", 160, 32),
    ("assets/cornell.gltf", "path", 160, 32),
    ("assets/models/checker-cube.gltf", "path", 160, 32),
]


def render(radiant, scene, mode, size, spp, out, stats, effects=None):
    cmd = [radiant, "render", scene, "-o", out, "--mode", mode, "--width", str(size), "--height", str(size),
           "--spp", str(spp), "--threads", "2", "--quiet", "--stats", stats]
    if effects:
        cmd.append("--effects=" + effects)
    subprocess.run(cmd, check=True)
    with open(stats) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--radiant", default="build/radiant")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--out")
    args = parser.parse_args()
    rows = ["| scene | mode | effects the scene calls for | specialised (s) | generic (s) | generic / specialised | images |",
            "|---|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as tmp:
        for scene, mode, size, spp in SCENES:
            if not os.path.exists(scene):
                print(f"skipping {scene}: not found", file=sys.stderr)
                continue
            special, generic = [], []
            a, b = os.path.join(tmp, "a.exr"), os.path.join(tmp, "b.exr")
            for _ in range(args.repeats):  # alternate so machine noise hits both alike
                s = render(args.radiant, scene, mode, size, spp, a, os.path.join(tmp, "a.json"))
                g = render(args.radiant, scene, mode, size, spp, b, os.path.join(tmp, "b.json"), "all")
                special.append(s["seconds"]["render"])
                generic.append(g["seconds"]["render"])
            identical = filecmp.cmp(a, b, shallow=False)
            ms, mg = statistics.median(special), statistics.median(generic)
            rows.append(f"| {scene} | {mode} | {s['effects']} | {ms:.3f} | {mg:.3f} | {mg / ms:.2f} | "
                        f"{'identical' if identical else 'DIFFERENT'} |")
            print(rows[-1], file=sys.stderr)
    table = "\n".join(rows) + "\n"
    print(table)
    if args.out:
        with open(args.out, "w") as f:
            f.write(table)


if __name__ == "__main__":
    main()

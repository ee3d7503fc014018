#!/usr/bin/env python3
"""Measures what unused effects cost: each scene rendered by the integrator specialised to its
effect set and by the generic all-effects integrator (--effects=all), same seed.

Two measures, because this machine is shared and noisy:
  * instructions executed inside the integrator (valgrind --tool=callgrind, exact and
    repeatable) on a small render;
  * CPU seconds (user + system of the render process) on a larger one, median of alternating runs.
It checks that both images are byte-identical and prints a Markdown table.

Usage: bench/effects.py [--radiant build/radiant] [--repeats 5] [--out FILE] [--no-callgrind]
"""
import argparse, filecmp, json, os, re, resource, shutil, statistics, subprocess, sys, tempfile

SCENES = [
    # (scene, mode, size, spp)                  the callgrind run uses size/4 and spp/4
    ("assets/first-render.scene", "whitted", 400, 16),
    ("assets/showcase.scene", "whitted", 320, 16),
    ("assets/room-older-format.scene", "path", 160, 32),
    ("assets/cornell.gltf", "path", 160, 32),
    ("assets/models/checker-cube.gltf", "path", 160, 32),
]


def command(radiant, scene, mode, size, spp, out, effects):
    cmd = [radiant, "render", scene, "-o", out, "--mode", mode, "--width", str(size), "--height", str(size),
           "--spp", str(spp), "--threads", "1", "--quiet",
           "--no-metadata"]  # the command lines differ (--effects): without a record the bytes must not
    if effects:
        cmd.append("--effects=" + effects)
    return cmd


def cpu_seconds(cmd):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(cmd, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def instructions(cmd):
    # Only instructions inside the integrators count (each camera sample's radiance): loading and
    # start-up would dilute the ratio.
    result = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                             "--toggle-collect=*WhittedVariant*run*", "--toggle-collect=*PathVariant*run*"] + cmd,
                            check=True, capture_output=True, text=True)
    return int(re.search(r"Collected : (\d+)", result.stderr).group(1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--radiant", default="build/radiant")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--out")
    parser.add_argument("--no-callgrind", action="store_true")
    args = parser.parse_args()
    use_callgrind = not args.no_callgrind and shutil.which("valgrind")
    rows = ["| scene | mode | effects the scene calls for | instructions, specialised / generic (small render) "
            "| CPU s specialised | CPU s generic | CPU generic / specialised | images |",
            "|---|---|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as tmp:
        for scene, mode, size, spp in SCENES:
            if not os.path.exists(scene):
                print(f"skipping {scene}: not found", file=sys.stderr)
                continue
            a, b = os.path.join(tmp, "a.exr"), os.path.join(tmp, "b.exr")
            special, generic = [], []
            for _ in range(args.repeats):  # alternate so machine noise hits both alike
                special.append(cpu_seconds(command(args.radiant, scene, mode, size, spp, a, None)))
                generic.append(cpu_seconds(command(args.radiant, scene, mode, size, spp, b, "all")))
            identical = filecmp.cmp(a, b, shallow=False)
            stats = os.path.join(tmp, "s.json")
            subprocess.run(command(args.radiant, scene, mode, 16, 1, a, None) + ["--stats", stats], check=True)
            with open(stats) as f:
                effects = json.load(f)["effects"]
            ratio = "n/a"
            if use_callgrind:
                small = (max(size // 4, 16), max(spp // 4, 1))
                # PNG, written without OpenImageIO: its libhwy (through libjxl) runs an instruction
                # valgrind does not know while it loads.
                png_a, png_b = os.path.join(tmp, "a.png"), os.path.join(tmp, "b.png")
                i_special = instructions(command(args.radiant, scene, mode, *small, png_a, None))
                i_generic = instructions(command(args.radiant, scene, mode, *small, png_b, "all"))
                ratio = f"{i_special / 1e6:.0f} M / {i_generic / 1e6:.0f} M = {i_generic / i_special:.3f}"
            ms, mg = statistics.median(special), statistics.median(generic)
            rows.append(f"| {scene} | {mode} | {effects} | {ratio} | {ms:.3f} | {mg:.3f} | {mg / ms:.2f} | "
                        f"{'identical' if identical else 'DIFFERENT'} |")
            print(rows[-1], file=sys.stderr)
    table = "\n".join(rows) + "\n"
    print(table)
    if args.out:
        with open(args.out, "w") as f:
            f.write(table)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Texture filtering at grazing angles: error per spp with and without mip-mapping, and its cost.

A 400 x 400 unit floor under an unlit 1024 x 1024 checkerboard texture (8-texel checks, a PNG in
a data URI, tiled 100 times) seen from 1 unit above, looking 20 degrees down (34 degrees of view): most of the image
minifies the texture, so unfiltered lookups alias. Every --texture-filter is rendered at 1, 2,
4, 8 and 16 spp and compared (RMSE, `radiant compare --json`) with a converged reference: the
unfiltered pixel integral (--texture-filter bilinear at --reference-spp, another seed). The
unlit material makes the image the texture alone: no lighting noise hides the aliasing.
Time is the render's wall clock and peak memory its maximum resident set (per run, os.wait4);
the error table's costs are single runs. The cost of filtering is then timed on its own: bilinear
and trilinear in alternating runs at --timing-spp, --repeats rounds, each run with its load average
and CPU share, the ratio trilinear / bilinear per round as median (min-max). The script waits for a
quiet machine (load under --max-load) before timing; error numbers are not timings and can run
anywhere (--repeats 0 leaves the timing out).

Usage: bench/texture_filtering.py [--radiant build/radiant] [--size 128] [--reference-spp 1024]
                                  [--filters point,bilinear,trilinear] [--spp 1,2,4,8,16] [--out FILE]
                                  [--timing-spp 4] [--repeats 5] [--max-load 0.5]
"""
import argparse, base64, json, math, os, struct, subprocess, sys, tempfile, time, zlib

TEXELS, CHECK, TILES, HALF, PITCH_DEGREES = 1024, 8, 100, 200.0, 20.0


def checker_png():
    """An 8-bit grey PNG of TEXELS x TEXELS, black and white checks of CHECK texels."""
    rows = []
    for y in range(TEXELS):
        row = bytearray([0])  # PNG filter type: none
        for x in range(TEXELS):
            row += b"\xff" if (x // CHECK + y // CHECK) % 2 else b"\x00"
        rows.append(bytes(row))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", TEXELS, TEXELS, 8, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) +
            chunk(b"IEND", b""))


def data_uri(kind, data):
    return "data:" + kind + ";base64," + base64.b64encode(data).decode()


def write_scene(path):
    positions = [-HALF, 0, -HALF, -HALF, 0, HALF, HALF, 0, HALF, HALF, 0, -HALF]
    uvs = [0, 0, 0, TILES, TILES, TILES, TILES, 0]
    indices = [0, 1, 2, 0, 2, 3]
    data = struct.pack("<12f", *positions) + struct.pack("<8f", *uvs) + struct.pack("<6H", *indices)
    pitch = math.radians(PITCH_DEGREES)
    # A glTF camera looks along -z; turning it about x by -pitch tilts it down.
    rotation = [-math.sin(pitch / 2), 0, 0, math.cos(pitch / 2)]
    gltf = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_unlit"],
        "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 1, 0], "rotation": rotation}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.01, "aspectRatio": 1}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0},
                       "extensions": {"KHR_materials_unlit": {}}}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": data_uri("image/png", checker_png())}],
        "buffers": [{"byteLength": len(data), "uri": data_uri("application/octet-stream", data)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [-HALF, 0, -HALF], "max": [HALF, 0, HALF]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    with open(path, "w") as f:
        json.dump(gltf, f)


def render(radiant, scene, out, size, spp, texture_filter, seed, cpu=None):
    """Renders and returns (wall seconds, peak resident MiB) of that one process; its CPU seconds
    go into `cpu` (a list) when given."""
    cmd = [radiant, "render", scene, "-o", out, "--width", str(size), "--height", str(size), "--spp", str(spp),
           "--mode", "path", "--texture-filter", texture_filter, "--seed", str(seed), "--quiet"]
    start = time.monotonic()
    process = subprocess.Popen(cmd)
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.monotonic() - start
    if status != 0:
        sys.exit("failed: " + " ".join(cmd))
    if cpu is not None:
        cpu.append(usage.ru_utime + usage.ru_stime)
    return seconds, usage.ru_maxrss / 1024


def wait_for_quiet(max_load):
    """Waits up to 3 minutes for the 1-minute load average to fall under max_load."""
    for _ in range(18):
        if os.getloadavg()[0] <= max_load:
            return os.getloadavg()[0]
        time.sleep(10)
    sys.exit(f"the machine is not quiet: load average {os.getloadavg()[0]:.2f} > {max_load} after 3 minutes")


def timing_table(radiant, scene, tmp, size, spp, repeats, max_load):
    """Bilinear and trilinear in alternating runs: each run's time, peak memory, load and CPU share,
    and the ratio trilinear / bilinear of each round."""
    start_load = wait_for_quiet(max_load)
    threads = os.cpu_count()
    lines = [f"Timing at {spp} spp, {size}x{size}, {threads} threads, alternating runs (load average at start "
             f"{start_load:.2f})", "", "| round | bilinear s / peak MiB (load, CPU share) | "
             "trilinear s / peak MiB (load, CPU share) | ratio |", "|---|---|---|---|"]
    ratios = []
    for round_index in range(repeats):
        cells, seconds = [], []
        for f in ("bilinear", "trilinear"):
            load, cpu = os.getloadavg()[0], []
            wall, peak = render(radiant, scene, os.path.join(tmp, f"timed-{f}.exr"), size, spp, f, 0, cpu)
            share = cpu[0] / wall / threads
            cells.append(f"{wall:.3f} / {peak:.0f} ({load:.2f}, {share:.2f}{' SLOWED' if share < 0.8 else ''})")
            seconds.append(wall)
        ratios.append(seconds[1] / seconds[0])
        lines.append(f"| {round_index + 1} | {cells[0]} | {cells[1]} | {ratios[-1]:.3f} |")
    ordered = sorted(ratios)
    median = ordered[len(ordered) // 2] if len(ordered) % 2 else (ordered[len(ordered) // 2 - 1] + ordered[len(ordered) // 2]) / 2
    lines += ["", f"time ratio trilinear / bilinear: {median:.3f} ({ordered[0]:.3f}-{ordered[-1]:.3f}) over {repeats} rounds"]
    return lines


def rmse(radiant, image, reference):
    result = subprocess.run([radiant, "compare", image, reference, "--json"], capture_output=True, text=True)
    return json.loads(result.stdout)["metrics"]["rmse"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--radiant", default="build/radiant")
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--reference-spp", type=int, default=1024)
    parser.add_argument("--filters", default="point,bilinear,trilinear")
    parser.add_argument("--spp", default="1,2,4,8,16")
    parser.add_argument("--out")
    parser.add_argument("--timing-spp", type=int, default=4)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--max-load", type=float, default=0.5)
    args = parser.parse_args()
    filters, ladder = args.filters.split(","), [int(s) for s in args.spp.split(",")]
    with tempfile.TemporaryDirectory() as tmp:
        scene = os.path.join(tmp, "grazing-checkerboard.gltf")
        write_scene(scene)
        reference = os.path.join(tmp, "reference.exr")
        render(args.radiant, scene, reference, args.size, args.reference_spp, "bilinear", 7)
        lines = [f"{args.size}x{args.size} pixels; reference: bilinear at {args.reference_spp} spp, seed 7; "
                 "RMSE of linear RGB against it (renders: seed 0)", "",
                 "| spp | " + " | ".join(f"{f} RMSE" for f in filters) + " | " +
                 " | ".join(f"{f} s / peak MiB" for f in filters) + " |",
                 "|---" * (1 + 2 * len(filters)) + "|"]
        for spp in ladder:
            errors, costs = [], []
            for f in filters:
                image = os.path.join(tmp, f"{f}-{spp}.exr")
                seconds, peak = render(args.radiant, scene, image, args.size, spp, f, 0)
                errors.append(f"{rmse(args.radiant, image, reference):.4f}")
                costs.append(f"{seconds:.2f} / {peak:.0f}")
            lines.append(f"| {spp} | " + " | ".join(errors) + " | " + " | ".join(costs) + " |")
        if args.repeats > 0:  # --repeats 0: errors only, which need no quiet machine
            lines += [""] + timing_table(args.radiant, scene, tmp, args.size, args.timing_spp, args.repeats, args.max_load)
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Engines' tables as they ship them, made by normzoo in each engine's convention, then checked:
what `verify lut --check --detect` finds and how long it takes, and the checks' speed targets
(docs/lut.md, "Checking an engine's table"). Imported by lut_bench.py, which writes the page."""
import base64
import os
import statistics
import struct
import subprocess
import tempfile
import time


def run(binary, args, check=True):
    """One run of `verify lut ARGS`: (exit status, stdout, wall seconds, CPU seconds of the child)."""
    before = os.times()
    a = time.perf_counter()
    p = subprocess.run([binary, "lut"] + args, capture_output=True, text=True)
    wall = time.perf_counter() - a
    after = os.times()
    if check and p.returncode not in (0, 1):
        raise RuntimeError(f"verify lut {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return p.returncode, p.stdout, wall, cpu


def timed(binary, args, runs):
    """Median wall and CPU seconds of `runs` runs after one warm-up, and the last run's output."""
    walls, cpus, out = [], [], None
    for i in range(runs + 1):
        status, stdout, wall, cpu = run(binary, args)
        out = (status, stdout)
        if i:
            walls.append(wall)
            cpus.append(cpu)
    return statistics.median(walls), statistics.median(cpus), out


def made(binary, folder, args):
    """The one file `verify lut ARGS --out folder` writes (a fresh folder each time)."""
    out = tempfile.mkdtemp(dir=folder)
    run(binary, args + ["--out", out])
    files = os.listdir(out)
    if len(files) != 1:
        raise RuntimeError(f"verify lut {' '.join(args)} wrote {os.listdir(out)}")
    return os.path.join(out, files[0])


def ktx2_level0(path):
    """The bytes of level 0 of an uncompressed KTX2 (KTX 2.0 specification: the level index
    follows the 80-byte header; byteOffset and byteLength are its first two uint64)."""
    data = open(path, "rb").read()
    offset, length = struct.unpack_from("<QQ", data, 80)
    return data[offset:offset + length]


def threejs_array(ktx2, path, size):
    """three.js's DFGLUTData.js shape: the half bits of an RG16F table in a Uint16Array, handed
    to DataTexture with its size."""
    level = ktx2_level0(ktx2)
    bits = struct.unpack(f"<{len(level) // 2}H", level)
    body = ",".join(f"0x{b:04x}" for b in bits)
    with open(path, "w") as f:
        f.write(f"const DATA = new Uint16Array( [ {body} ] );\n"
                f"lut = new DataTexture( DATA, {size}, {size}, RGFormat, HalfFloatType );\n")


def babylon_source(png, path):
    """Babylon.js's brdfTextureTools.ts shape: the RGBD PNG as a base64 data URI in a string."""
    data = base64.b64encode(open(png, "rb").read()).decode()
    with open(path, "w") as f:
        f.write(f'const _environmentBRDFBase64Texture = "data:image/png;base64,{data}";\n')


# The five tables engines ship, each as normzoo makes it in that engine's convention: (name, the
# `verify lut` making arguments, how the made file becomes the shipped one, the preset).
FIVE = [
    ("glTF Sample Viewer `lut_ggx.png`: 1024^2 RGBA8, (A, B), 1024 samples",
     ["--size", "1024", "--monte-carlo", "1024", "--preset", "gltf-sample-viewer", "--format", "png8"], None, "gltf-sample-viewer"),
    ("Bevy `dfg.ktx2`: 64^2 R16G16_SFLOAT, Zstandard, 1024 samples",
     ["--size", "64", "--monte-carlo", "1024", "--preset", "bevy", "--format", "ktx2-zstd"], None, "bevy"),
    ("a generator's 16-bit `brdfLUT.png`: 512^2, (A, B), Schlick-GGX k = alpha/2",
     ["--size", "512", "--model", "ggx/schlick-ggx/one", "--format", "png16"], None, "learnopengl --layout encoding=unorm16"),
    ("Babylon.js: 256^2 RGBD PNG in base64 in a .ts file, (B, A+B, 0), 1024 samples",
     ["--size", "256", "--monte-carlo", "1024", "--preset", "babylon", "--format", "png8"], "babylon", "babylon"),
    ("three.js `DFGLUTData.js`: 16^2 half bits in a Uint16Array, rows N.V, 4096 samples",
     ["--size", "16", "--monte-carlo", "4096", "--preset", "threejs", "--format", "ktx2"], "threejs", "threejs"),
]


def shipped(binary, folder, making, wrap):
    """The table made, then wrapped as the engine ships it."""
    path = made(binary, folder, ["--kind", "dfg"] + making)
    if wrap == "babylon":
        babylon_source(path, os.path.join(folder, "brdfTextureTools.ts"))
        return os.path.join(folder, "brdfTextureTools.ts")
    if wrap == "threejs":
        threejs_array(path, os.path.join(folder, "DFGLUTData.js"), 16)
        return os.path.join(folder, "DFGLUTData.js")
    return path


def detect_rows(binary, folder, runs=3):
    """Per table: what --detect finds (layout and model), its largest errors, the time of the
    whole check with --detect, and the preset's verdict."""
    import json
    rows = []
    for name, making, wrap, preset in FIVE:
        path = shipped(binary, folder, making, wrap)
        check = ["--check", path, "--kind", "dfg"]
        wall, cpu, _ = timed(binary, check + ["--detect"], runs)
        status, out, _, _ = run(binary, check + ["--detect", "--json"])
        recs = json.loads(out)["records"]
        errors = ", ".join(f"{r['channel']} {r['max_abs_error']:.3g}" for r in recs)
        pstatus, pout, _, _ = run(binary, check + ["--preset"] + preset.split() + ["--json"])
        precs = json.loads(pout)["records"]
        perrors = ", ".join(f"{r['channel']} {r['max_abs_error']:.3g}" for r in precs)
        rows.append(f"| {name} | `{recs[0]['layout']}`, `{recs[0]['model']}` | {errors} | {wall:.2f} s ({cpu:.2f} s CPU) | "
                    f"`--preset {preset}`: {'passes' if pstatus == 0 else 'fails'} ({perrors}) |")
    return rows


def check_speed_rows(binary, folder, runs=3):
    """The checks' speed targets: a 1024^2 8-bit table (the glTF viewer's size) in at most 3 s wall;
    a list of points as fast as the same points by --size."""
    rows = []
    gltf = made(binary, folder, ["--kind", "dfg"] + FIVE[0][1])
    wall, cpu, _ = timed(binary, ["--check", gltf, "--kind", "dfg", "--preset", "gltf-sample-viewer"], runs)
    rows.append(f"| check of the 1024^2 8-bit glTF table, `--preset gltf-sample-viewer` | {wall:.2f} s | {cpu:.2f} s | "
                f"target 3 s wall: {'met' if wall <= 3 else 'not met'} |")
    size_wall, size_cpu, _ = timed(binary, ["--kind", "dfg", "--size", "256"], runs)
    rows.append(f"| `lut --kind dfg --size 256` (made at 1e-10, not written) | {size_wall:.2f} s | {size_cpu:.2f} s | the peer |")
    csv = made(binary, folder, ["--kind", "dfg", "--size", "256", "--format", "csv"])
    wall, cpu, _ = timed(binary, ["--check", csv, "--kind", "dfg"], runs)
    rows.append(f"| check of the same 256^2 points, the CSV `--format csv` writes | {wall:.2f} s | {cpu:.2f} s | "
                f"{wall / size_wall:.2f}x the peer's wall |")
    six = os.path.join(folder, "points-6.csv")
    with open(csv) as f, open(six, "w") as g:
        header = None
        for line in f:
            if line.startswith("#"):
                continue
            cells = line.rstrip("\n").split(",")
            if header is None:
                header = cells
                g.write("mu,r,A,B\n")
                continue
            v = dict(zip(header, cells))
            g.write(f"{float(v['mu']):.6f},{float(v['r']):.6f},{float(v['A']):.6f},{float(v['B']):.6f}\n")
    wall, cpu, _ = timed(binary, ["--check", six, "--kind", "dfg"], runs)
    rows.append(f"| check of 256^2 points printed at `%.6f` (every coordinate's rounding measured) | {wall:.2f} s | {cpu:.2f} s | "
                f"{wall / size_wall:.2f}x the peer's wall |")
    return rows

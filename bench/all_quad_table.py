#!/usr/bin/env python3
"""The all-quad table of bench/RESULTS.md: `petersen quad --all-quad` per mesh, before and after.

For each mesh and each setting (--all-quad alone, and with --max-corner-deviation 30, which
leaves many triangles to split), every binary given is run with --stats-json, and one Markdown
row is printed per mesh and setting: the triangles left by the pairing, the vertices all_quad
added by each binary (or "refused"), the certified minimum (added_vertices_minimum, from the
binary that reports it), the split quads' median and 95th-percentile corner deviation, and each
binary's all_quad_seconds and total. Beside them, two baselines:

- subdivide everything: one new vertex per edge and per face, every n-gon cut into n quads
  around its centre (Catmull-Clark's topology); its added vertex count is exactly E + F of the
  input (mesh_edges + faces_in of the stats);
- MeshLab (--meshlab PATH of meshlabserver, 2020.09 as Debian 12 ships it): its only filter that
  makes every face a quad is "Tri to Quad by 4-8 Subdivision" (one new vertex per triangle, the
  mesh kept as triangles paired by faux edges); "Tri to Quad by smart triangle pairing" pairs
  without splitting and has no pure-quad option, and meshlabserver writes faux-edge pairs as
  triangles, so its leftovers cannot be counted from the file. The column is the 4-8 filter's
  added vertices (written vertices minus the input's) and its wall time. It needs an OpenGL
  context even headless: run under xvfb-run (QT_QPA_PLATFORM=offscreen fails in GLEW).

Usage:
  bench/all_quad_table.py --binary before=/work/main/build/release/tools/petersen \\
      --binary after=build/release/tools/petersen [--meshlab meshlabserver] \\
      [--meshes /work/shared/meshes] [--max-triangles 1500000] [mesh ...]
"""

import argparse
import gzip
import json
import os
import subprocess
import sys
import tempfile
import time

SETTINGS = [("all-quad", []), ("all-quad, max dev 30", ["--max-corner-deviation", "30"])]


def count_vertices(obj_path):
    """The vertices of an OBJ file."""
    with open(obj_path) as f:
        return sum(1 for line in f if line.startswith("v "))


def run_petersen(binary, mesh, extra, all_quad=True):
    """The stats of one run, or {'refused': message}."""
    with tempfile.TemporaryDirectory() as tmp:
        stats_path = os.path.join(tmp, "stats.json")
        out = os.path.join(tmp, "out.obj")
        started = time.monotonic()
        flags = ["--all-quad"] if all_quad else []
        run = subprocess.run([binary, "quad", mesh, out, "--stats-json", stats_path] + flags + extra,
                             capture_output=True, text=True)
        wall = time.monotonic() - started
        if run.returncode != 0:
            return {"refused": (run.stderr.strip().splitlines() or ["?"])[-1], "wall": wall}
        with open(stats_path) as f:
            stats = json.load(f)
        stats["wall"] = wall
        return stats


def run_meshlab(meshlabserver, mesh, vertices_in):
    """(added vertices, seconds) of MeshLab's 4-8 subdivision to quads, or (None, why)."""
    script = """<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Tri to Quad by 4-8 Subdivision"/>
</FilterScript>
"""
    with tempfile.TemporaryDirectory() as tmp:
        source = mesh
        if mesh.endswith(".gz"):
            source = os.path.join(tmp, os.path.basename(mesh)[:-3])
            with gzip.open(mesh, "rb") as f, open(source, "wb") as g:
                g.write(f.read())
        script_path = os.path.join(tmp, "quads.mlx")
        with open(script_path, "w") as f:
            f.write(script)
        out = os.path.join(tmp, "out.obj")
        started = time.monotonic()
        run = subprocess.run(["xvfb-run", "-a", meshlabserver, "-i", source, "-o", out, "-s",
                              script_path], capture_output=True, text=True)
        seconds = time.monotonic() - started
        if run.returncode != 0 or not os.path.exists(out):
            return None, (run.stderr.strip().splitlines() or ["failed"])[-1]
        after = count_vertices(out)
        return after - vertices_in, seconds


def cell(value, digits=1):
    if value is None:
        return "–"
    return f"{value:.{digits}f}" if isinstance(value, float) else str(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", action="append", required=True,
                        help="NAME=PATH of a petersen binary (give one per column)")
    parser.add_argument("--meshlab", help="path of meshlabserver, for its column")
    parser.add_argument("--meshes", default="/work/shared/meshes")
    parser.add_argument("--max-triangles", type=int, default=1_500_000)
    parser.add_argument("files", nargs="*", help="meshes (default: every shared mesh)")
    args = parser.parse_args()
    binaries = [b.split("=", 1) for b in args.binary]
    files = args.files or sorted(
        os.path.join(root, name) for root, _, names in os.walk(args.meshes) for name in names
        if name.endswith((".off.gz", ".obj.gz", ".ply.gz")))

    names = [name for name, _ in binaries]
    header = (["mesh", "setting", "left"] + [f"added ({n})" for n in names]
              + ["minimum", "split median / p95"]
              + [f"all-quad s / total s ({n})" for n in names]
              + ["subdivide all", "MeshLab 4-8 added (s)"])
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for mesh in files:
        meshlab = None
        for setting, extra in SETTINGS:
            runs = [run_petersen(path, mesh, extra) for _, path in binaries]
            ran = [r for r in runs if "refused" not in r]
            plain = ran[0] if ran else run_petersen(binaries[0][1], mesh, extra, all_quad=False)
            if plain.get("triangles", 0) > args.max_triangles:
                break
            subdivide = (plain["mesh_edges"] + plain["faces_in"]) if "mesh_edges" in plain else None
            if args.meshlab and meshlab is None:
                added, how = run_meshlab(args.meshlab, mesh, plain.get("vertices", 0))
                meshlab = f"{added} ({how:.1f})" if added is not None else f"fails: {how}"
            left = plain.get("triangles_left")
            reporting = [r for r in ran if "added_vertices_minimum" in r]
            minimum = reporting[-1]["added_vertices_minimum"] if reporting else None
            quality = (f"{reporting[-1].get('split_quality_median', 0):.1f} / "
                       f"{reporting[-1].get('split_quality_p95', 0):.1f}") if reporting else "–"
            row = [os.path.relpath(mesh, args.meshes), setting, cell(left)]
            row += ["refused" if "refused" in r else cell(r.get("added_vertices")) for r in runs]
            row += [cell(minimum), quality]
            row += ["–" if "refused" in r else
                    f"{r.get('all_quad_seconds', 0):.3f} / {r.get('total_seconds', r['wall']):.3f}"
                    for r in runs]
            row += [cell(subdivide), (meshlab or "–") if setting == SETTINGS[0][0] else ""]
            print("| " + " | ".join(row) + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

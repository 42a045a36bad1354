"""petersen.distributed on 1, 2 and 3 local Dask workers: time per stage, and the repair's cost as
the parts grow in number.

    PYTHONPATH=... python3 bench/dask_parts.py --cli build/tools/petersen --triangles 1e7

Generates a closed jittered torus of about --triangles triangles with `petersen generate` (faces
in scan order, so a face range is a patch), then for each worker count runs the pipeline with
one part per worker and with parts of odd sizes (each part leaves a triangle, which the repair
pairs across a cut), and prints one markdown row per run. The in-memory petersen.quadrangulate
of the same file is the reference row.
"""

import argparse
import logging
import math
import os
import pathlib
import subprocess
import tempfile
import time

import numpy as np

import petersen
import petersen.distributed as pd


def generate(cli: str, triangles: float, folder: pathlib.Path) -> pathlib.Path:
    ny = max(3, int(round(math.sqrt(triangles / 6))))
    nx = 3 * ny
    path = folder / f"torus-{2 * nx * ny}.ply"
    if not path.exists():
        subprocess.run([cli, "generate", str(path), "--kind", "jittered-torus", "--nx", str(nx),
                        "--ny", str(ny)], check=True, stdout=subprocess.DEVNULL)
    return path


def odd_bounds(face_count: int, parts: int) -> list:
    """Boundaries of `parts` ranges of odd sizes (an even face count, an even number of parts)."""
    bounds = np.linspace(0, face_count, parts + 1).astype(np.int64) // 2 * 2
    bounds[1:-1:2] += 1
    return bounds.tolist()


def row(label: str, workers: int, stats: dict) -> str:
    return (f"| {label} | {workers} | {stats['parts']} | {stats['total_seconds']:.1f} | "
            f"{stats['parts_seconds']:.1f} | {stats['part_seconds_max']:.1f} | "
            f"{stats['repair_seconds']:.2f} | {stats['write_seconds']:.1f} | "
            f"{stats['part_cut_edges']} | {stats['unpaired_after_parts']} | "
            f"{stats['repair_band_graph_faces']} | {stats['repair_augmenting_paths']} | "
            f"{stats['repair_matching_seconds']:.3f} | {stats['triangles_left']} |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default=os.environ.get("PETERSEN_CLI", "build/tools/petersen"))
    parser.add_argument("--triangles", type=float, default=1e7)
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2, 3])
    parser.add_argument("--folder", default=None, help="where the meshes go (default: a temp dir)")
    args = parser.parse_args()
    from distributed import Client, LocalCluster

    with tempfile.TemporaryDirectory() as scratch:
        folder = pathlib.Path(args.folder or scratch)
        path = generate(args.cli, args.triangles, folder)
        out = folder / "quads.ply"
        mesh = petersen.read_mesh(str(path))
        clock = time.perf_counter()
        reference = petersen.quadrangulate(mesh.V, mesh.F, objective="pairs")
        print(f"{path.name}: {len(mesh.F)} triangles; in memory (read not counted): "
              f"{time.perf_counter() - clock:.1f} s, {reference.stats['pairs']} pairs")
        del mesh, reference
        print("| part sizes | workers | parts | total s | parts s | slowest part s | repair s | "
              "write s | cut adjacencies | unpaired after parts | repair band graph faces | "
              "augmenting paths | repair matching s | left |")
        print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
        for workers in args.workers:
            with LocalCluster(n_workers=workers, processes=True, threads_per_worker=1,
                              dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
                    Client(cluster) as client:
                face_count = pd.read_layout(str(path)).face_count
                for label, parts in (("even", workers), ("even", 2 * workers),
                                     ("odd", odd_bounds(face_count, 2 * workers))):
                    # The repair's figures below are those of objective pairs.
                    stats = pd.quadrangulate(str(path), str(out), client, parts=parts,
                                             objective="pairs")
                    print(row(label, workers, stats), flush=True)


if __name__ == "__main__":
    main()

"""The objectives' end-to-end time, side by side in one run: `petersen quad IN OUT` with the default
(quads), pairs and quality, against `gzip -dc IN` (reading the file is the floor).

    python3 bench/quads_speed.py PETERSEN MESH [MESH ...]

Each command runs three times, one after the other for every mesh; the best wall time counts.
Prints a Markdown table: seconds, and the default's ratio to pairs and to gzip -dc.
"""

import os
import subprocess
import sys
import tempfile
import time


def best_of(command, runs=3):
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        best = min(best, time.perf_counter() - start)
    return best


def main():
    petersen, meshes = sys.argv[1], sys.argv[2:]
    print("| mesh | `gzip -dc` | quads (default) | pairs | quality | quads ÷ pairs | quads ÷ gzip |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "out.ply")
        for mesh in meshes:
            gzip = best_of(["sh", "-c", f"gzip -dc '{mesh}' > /dev/null"])
            seconds = {o: best_of([petersen, "quad", mesh, out, "--objective", o])
                       for o in ("quads", "pairs", "quality")}
            name = os.path.basename(mesh).split(".")[0]
            print(f"| {name} | {gzip:.3f} | {seconds['quads']:.3f} | {seconds['pairs']:.3f} | "
                  f"{seconds['quality']:.3f} | {seconds['quads'] / seconds['pairs']:.2f}× | "
                  f"{seconds['quads'] / gzip:.1f}× |", flush=True)


if __name__ == "__main__":
    main()

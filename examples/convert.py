#!/usr/bin/env python3
"""Convert a mesh with both objectives, compare the quads' shapes, and draw both.

    python3 examples/convert.py [MESH] [--out DIR] [--algorithm auto] [--all-quad]

MESH defaults to the bundled examples/plate-genus2.off. Converts it twice: objective "pairs" (the
algorithm's pairing, fastest) and objective "quality" (the certified minimum total worst-corner
deviation). Prints, for each, the pairs, the triangles left and the quads' worst-corner deviation
from 90 degrees (median, 95th percentile, share of non-convex quads), then writes
DIR/<mesh>-<objective>.png for each.
"""

import argparse
import pathlib

import numpy as np

import petersen


def convert(mesh, algorithm, objective, all_quad):
    # The algorithm is the pairs objective's: the cost objectives run the minimum-cost matching.
    result = petersen.quadrangulate(mesh.V, mesh.F, objective=objective,
                                    algorithm=algorithm if objective == "pairs" else "auto",
                                    all_quad=all_quad)
    cost = petersen.quad_quality(result.V, result.quads)
    return result, cost


def figures(cost):
    if len(cost) == 0:
        return "no quads"
    return (f"median {np.median(cost):5.1f} deg, p95 {np.percentile(cost, 95):5.1f} deg, "
            f"non-convex {100 * np.mean(cost > 90):4.1f} %")


def main():
    here = pathlib.Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", default=str(here / "plate-genus2.off"))
    parser.add_argument("--out", default="out")
    parser.add_argument("--algorithm", default="auto", choices=petersen.ALGORITHMS,
                        help="for the objective pairs")
    parser.add_argument("--all-quad", action="store_true", help="split the triangles left too")
    args = parser.parse_args()

    mesh = petersen.read_mesh(args.mesh)
    name = pathlib.Path(args.mesh).name.split(".")[0]
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    print(f"{args.mesh}: {len(mesh.V)} vertices, {len(mesh.F)} faces")
    for objective in ("pairs", "quality"):
        result, cost = convert(mesh, args.algorithm, objective, args.all_quad)
        s = result.stats
        print(f"{objective:7s} pairs {s['pairs']:7d}  triangles left {s['triangles_left']:5d}  "
              f"added vertices {s['added_vertices']:4d}  quads {figures(cost)}  "
              f"({s['total_seconds']:.3f} s)")
        picture = out / f"{name}-{objective}.png"
        petersen.render(
            picture, result.V, result.faces, first_added_vertex=len(mesh.V),
            caption=[f"{name} by {s['algorithm']}: {s['pairs']} pairs, "
                     f"{s['triangles_left']} triangles left",
                     f"{len(cost)} quads, worst corner {figures(cost)}"])
        print(f"       drawn in {picture}")


if __name__ == "__main__":
    main()

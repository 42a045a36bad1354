#!/usr/bin/env python3
"""Convert a mesh with two settings, compare the quads' shapes, and draw both.

    python3 examples/convert.py [MESH] [--out DIR] [--first ps] [--second lrs] [--all-quad]

MESH defaults to the bundled examples/plate-genus2.off. Prints, for each setting, the pairs, the
triangles left and the quads' worst-corner deviation from 90 degrees (median, 95th percentile,
share of non-convex quads), then writes DIR/<mesh>-<setting>.png for each.
"""

import argparse
import pathlib

import numpy as np

import petersen


def convert(mesh, algorithm, all_quad):
    result = petersen.quadrangulate(mesh.V, mesh.F, algorithm=algorithm, all_quad=all_quad)
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
    parser.add_argument("--first", default="ps", choices=petersen.ALGORITHMS)
    parser.add_argument("--second", default="lrs", choices=petersen.ALGORITHMS)
    parser.add_argument("--all-quad", action="store_true", help="split the triangles left too")
    args = parser.parse_args()

    mesh = petersen.read_mesh(args.mesh)
    name = pathlib.Path(args.mesh).name.split(".")[0]
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    print(f"{args.mesh}: {len(mesh.V)} vertices, {len(mesh.F)} faces")
    for algorithm in (args.first, args.second):
        result, cost = convert(mesh, algorithm, args.all_quad)
        s = result.stats
        print(f"{algorithm:6s} pairs {s['pairs']:7d}  triangles left {s['triangles_left']:5d}  "
              f"added vertices {s['added_vertices']:4d}  quads {figures(cost)}  "
              f"({s['total_seconds']:.3f} s)")
        picture = out / f"{name}-{algorithm}.png"
        petersen.render(
            picture, result.V, result.faces, first_added_vertex=len(mesh.V),
            caption=[f"{name} by {algorithm}: {s['pairs']} pairs, "
                     f"{s['triangles_left']} triangles left",
                     f"{len(cost)} quads, worst corner {figures(cost)}"])
        print(f"       drawn in {picture}")


if __name__ == "__main__":
    main()

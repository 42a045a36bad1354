"""The same conversion at every size: in memory, out of core and on a Dask LocalCluster, for each
option set of the front door, on a closed plate and on an open grid with holes.

    python3 bench/every_size.py --cli build/release/tools/petersen \
        --check build/release/tests/partition/petersen_check_quads --triangles 1e7

(with the petersen package importable, as scripts/bench --quads makes it). For each mesh and
option set it runs `petersen quad` in memory (the reference: its certified optimum), `petersen
quad --memory-limit` and `petersen.distributed.quadrangulate` on --workers local workers, checks
each output against the input with the independent checker, and prints one markdown row per run:
wall time, peak memory (the CLI's, from /usr/bin/time), what the certificate says, the total cost
and its excess over the in-memory run's. An option set a path refuses is printed as refused, with
the first line of its message.
"""

import argparse
import json
import logging
import math
import os
import pathlib
import subprocess
import tempfile
import time

OPTION_SETS = (
    ("default", []),
    ("--objective quality", ["--objective", "quality"]),
    ("--max-corner-deviation 30 --all-quad", ["--max-corner-deviation", "30", "--all-quad"]),
    ("--sharp-angle 30", ["--sharp-angle", "30"]),
)


def dask_options(flags):
    """The keyword arguments of petersen.distributed.quadrangulate for the CLI's flags."""
    options, i = {}, 0
    while i < len(flags):
        key = flags[i][2:].replace("-", "_")
        if i + 1 < len(flags) and not flags[i + 1].startswith("--"):
            value = flags[i + 1]
            options[key] = value if key == "objective" else float(value)
            i += 2
        else:
            options[key] = True
            i += 1
    return options


def generate(cli, kind, triangles, folder):
    path = folder / f"{kind}-{triangles:g}.ply"
    if path.exists():
        return path
    n = int(triangles)
    if kind == "plate":
        command = ["--kind", "streamed-plate", "--triangles", str(n)]
    else:  # an open jittered grid with one hole per 5,000 triangles, about n triangles
        ny = int(math.sqrt(n / 2.5))
        command = ["--kind", "open-grid", "--nx", str(ny * 5 // 4), "--ny", str(ny), "--holes",
                   str(n // 5000)]
    subprocess.run([cli, "generate", str(path), *command], check=True, stdout=subprocess.DEVNULL)
    return path


def timed_cli(cli, args, stats_path):
    """Runs `cli args` under /usr/bin/time -v; (seconds, peak GiB, stats or None, error text)."""
    clock = time.perf_counter()
    run = subprocess.run(["/usr/bin/time", "-v", cli, *args, "--stats-json", str(stats_path)],
                         capture_output=True, text=True)
    seconds = time.perf_counter() - clock
    peak = 0.0
    for line in run.stderr.splitlines():
        if "Maximum resident set size" in line:
            peak = int(line.split()[-1]) / 2**20
    if run.returncode != 0:
        message = [l for l in run.stderr.splitlines() if l and not l.startswith("\t")]
        return seconds, peak, None, message[0] if message else f"exit {run.returncode}"
    return seconds, peak, json.loads(stats_path.read_text()), ""


def checked(check, source, output):
    run = subprocess.run([check, str(source), str(output)], capture_output=True, text=True)
    return "passed" if run.returncode == 0 else "FAILED: " + (run.stderr.strip() or "?")


def certificate(stats):
    if "all_quad_certified" in stats:
        if stats.get("all_quad_certified"):
            return "fewest midpoints certified"
        if stats.get("all_quad_parts_certified"):
            return "fewest per part, certified per part"
    if stats.get("optimality_certified"):
        return "optimum certified"
    if "lower_bound" in stats:
        return f"within gap {stats.get('gap', 0):.1f}° ({100 * stats.get('gap_relative', 0):.3f} %)"
    if stats.get("maximum_certified") or stats.get("perfect_certified"):
        return "maximum certified, cost not"
    return "per part"


def row(mesh, label, path, seconds, peak, stats, error, check, reference):
    if stats is None:
        return f"| {mesh} | {label} | {path} | refused: {error} | | | | | |"
    # With --all-quad the measure is the vertices added (the pairing is the cheapest maximum);
    # every path names its all-quad certificate then, and every path counts added_vertices.
    key = "added_vertices" if "all_quad_certified" in stats else "objective_total"
    total = stats.get(key)
    excess = ""
    if total is not None and reference and reference.get(key):
        base = reference[key]
        excess = f"{100 * (total - base) / base:+.3f} %".replace("-0.000", "+0.000")
    memory = "" if peak is None else f"{peak:.2f}"
    shown = "" if total is None else f"{total:.6g}" + (" added" if key == "added_vertices" else "°")
    return (f"| {mesh} | {label} | {path} | {seconds:.1f} | {memory} | {certificate(stats)} | "
            f"{shown} | {excess} | {check} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", default="build/release/tools/petersen")
    parser.add_argument("--check", default="build/release/tests/partition/petersen_check_quads")
    parser.add_argument("--triangles", type=float, default=1e7)
    parser.add_argument("--workers", type=int, default=3)
    parser.add_argument("--memory-limit", default="1G")
    parser.add_argument("--meshes", nargs="+", default=["plate", "open-grid"])
    parser.add_argument("--option-sets", nargs="+", type=int, default=range(len(OPTION_SETS)),
                        help="which option sets to run, by index (default: all)")
    parser.add_argument("--folder", default=None, help="where the meshes go (default: a temp dir)")
    args = parser.parse_args()
    import petersen.distributed as pd
    from distributed import Client, LocalCluster

    print("| mesh | options | path | wall s | peak GiB | certificate | total | excess over "
          "in memory | output check |")
    print("|---|---|---|---:|---:|---|---:|---:|---|")
    with tempfile.TemporaryDirectory() as scratch, \
            LocalCluster(n_workers=args.workers, processes=True, threads_per_worker=1,
                         dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        folder = pathlib.Path(args.folder or scratch)
        out, stats_path = folder / "out.ply", folder / "stats.json"
        for mesh in args.meshes:
            source = generate(args.cli, mesh, args.triangles, folder)
            for label, flags in (OPTION_SETS[i] for i in args.option_sets):
                base = ["quad", str(source), str(out), *flags]
                seconds, peak, reference, error = timed_cli(args.cli, base, stats_path)
                check = checked(args.check, source, out) if reference else ""
                print(row(mesh, label, "in memory", seconds, peak, reference, error, check, None),
                      flush=True)
                seconds, peak, stats, error = timed_cli(
                    args.cli, [*base, "--memory-limit", args.memory_limit], stats_path)
                check = checked(args.check, source, out) if stats else ""
                print(row(mesh, label, f"out of core, {stats['parts'] if stats else '?'} parts",
                          seconds, peak, stats, error, check, reference), flush=True)
                clock = time.perf_counter()
                try:
                    stats = pd.quadrangulate(str(source), str(out), client,
                                             parts=2 * args.workers, **dask_options(flags))
                    error = ""
                except (TypeError, ValueError) as e:
                    stats, error = None, str(e).splitlines()[0]
                seconds = time.perf_counter() - clock
                check = checked(args.check, source, out) if stats else ""
                print(row(mesh, label, f"Dask, {args.workers} workers, {2 * args.workers} parts",
                          seconds, None, stats, error, check, reference), flush=True)
            os.remove(source)


if __name__ == "__main__":
    main()

"""The two tables of bench/RESULTS.md's "The default" section, from the rows bench/quad_recovery.py
printed (scripts/bench --quads writes them to bench/out/quads-recovery.md and quads-scans.md).

    python3 bench/recovery_tables.py bench/out/quads-recovery.md bench/out/quads-scans.md

Recovery: one row per model, each cell "random / short" diagonal, the default's triangles left in
brackets, then the counts the bullets quote: the runs where the default gives back at least
Blender's share (the better of its defaults and limits off), the medians, the worst run and the
runs under 99 %. Models whose name starts with one of --held-out are marked "(held out)". Scans:
regular vertices, triangles left and the worst corner per operator.
"""

import argparse
import statistics

# The operators' labels as quad_recovery.py's OPERATORS print them (it imports bpy, so it is not
# imported here).
BLENDER_40 = "Blender, defaults (40°, 40°)"
BLENDER_OFF = "Blender, limits off"
DEFAULT = "petersen add-on, defaults"
PAIRS = "petersen, Pairs"
QUALITY = "petersen, Quality"


def table_rows(path):
    """The cells of each Markdown table row of `path` that holds a percentage."""
    with open(path, encoding="utf-8") as f:
        return [[c.strip() for c in line.split("|")[1:-1]]
                for line in f if line.startswith("| ") and "%" in line]


def recovery(path, held_out):
    models = {}
    for model, quads, rule, operator, back, left, _ in table_rows(path):
        entry = models.setdefault(model, {"quads": quads})
        entry.setdefault(rule, {})[operator] = (float(back.rstrip(" %")), left)
    lines, shares = [], {op: [] for op in (BLENDER_40, BLENDER_OFF, DEFAULT, PAIRS, QUALITY)}
    ahead, runs, behind = 0, 0, []
    for model, entry in models.items():
        def pair(op, entry=entry):
            return f"{entry['random'][op][0]:.1f} / {entry['short'][op][0]:.1f}"
        left = f"({entry['random'][DEFAULT][1]} / {entry['short'][DEFAULT][1]})"
        name = model + (" (held out)" if model.split("-")[0] in held_out else "")
        lines.append(f"| {name} | {entry['quads']} | {pair(BLENDER_40)} | {pair(BLENDER_OFF)} | "
                     f"**{pair(DEFAULT)}** {left} | {pair(PAIRS)} | {pair(QUALITY)} |")
        for rule in ("random", "short"):
            for op in shares:
                shares[op].append(entry[rule][op][0])
            blender = max(entry[rule][BLENDER_40][0], entry[rule][BLENDER_OFF][0])
            runs += 1
            if entry[rule][DEFAULT][0] >= blender:
                ahead += 1
            else:
                behind.append(f"{model} {rule}")
    medians = ", ".join(f"{op} {statistics.median(v):.1f} %" for op, v in shares.items())
    lines.append("")
    lines.append(f"Default at least Blender's share on {ahead} of {runs} runs (behind: "
                 f"{', '.join(behind) or 'none'}); medians: {medians}; the default's worst "
                 f"{min(shares[DEFAULT]):.1f} %, under 99 % on "
                 f"{sum(s < 99 for s in shares[DEFAULT])} runs.")
    return lines


def scans(path):
    meshes = {}
    for mesh, operator, regular, left, median, p95, _ in table_rows(path):
        meshes.setdefault(mesh, {})[operator] = (regular, left, median, p95)
    lines = []
    for mesh, v in meshes.items():
        lines.append(f"| {mesh} | {v[BLENDER_40][0]} / {v[BLENDER_OFF][0]} | {v[PAIRS][0]} / "
                     f"{v[QUALITY][0]} / **{v[DEFAULT][0]}** | {v[BLENDER_40][1]} / "
                     f"{v[BLENDER_OFF][1]} / **{v[DEFAULT][1]}** | {v[QUALITY][2]} / "
                     f"**{v[DEFAULT][2]}** | {v[QUALITY][3]} / **{v[DEFAULT][3]}** |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("recovery", help="quad_recovery.py's rows for the quad models")
    parser.add_argument("scans", nargs="?", help="quad_recovery.py --scans' rows")
    parser.add_argument("--held-out", nargs="*", default=["homer", "cheburashka"])
    args = parser.parse_args()
    print("| model | quads + own triangles | Blender 40°/40° | Blender off | **petersen default** "
          "(triangles left) | pairs | quality |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    print("\n".join(recovery(args.recovery, set(args.held_out))))
    if args.scans:
        print()
        print("| scan | regular vertices: Blender 40° / off | petersen pairs / quality / "
              "**default** | triangles left: Blender 40° / off / **default** | worst corner "
              "median: quality / **default** | p95: quality / **default** |")
        print("|---|---:|---:|---:|---:|---:|")
        print("\n".join(scans(args.scans)))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""docs/cli.md checked against the CLI itself:
cli_reference_test.py PETERSEN CLI_MD EXAMPLE_MESH [--without TEXT].

Every option `petersen SUB --help` lists must have a row of its own in an option table of the
section of docs/cli.md on SUB (from its `## \\`petersen SUB` heading to the next `## `): `--name`
in the row's first cell. Every exit code measured below, by running the binary on each kind of
bad command line of each subcommand, must have a row in the exit-code table (`| CODE | when | subcommands |`) that names the subcommand or says "every
subcommand". Prints each miss and exits 1 if there is one. --without TEXT checks docs/cli.md
with the lines containing TEXT left out: how ctest shows that the check fails when a line goes."""

import re
import subprocess
import sys
import tempfile
from pathlib import Path

petersen, cli_md, example = sys.argv[1], Path(sys.argv[2]), sys.argv[3]
doc = cli_md.read_text()
if len(sys.argv) == 6 and sys.argv[4] == "--without":
    doc = "".join(line for line in doc.splitlines(True) if sys.argv[5] not in line)
misses = []


def section(sub):
    match = re.search(r"^## `petersen " + sub + r"\b.*?(?=^## |\Z)", doc, re.M | re.S)
    return match.group(0) if match else ""


def help_options(sub):
    text = subprocess.run([petersen, sub, "--help"], capture_output=True, text=True,
                          check=True).stdout
    names = re.findall(r"^\s+(?:-\w,)?(--[\w-]+)", text, re.M)
    return [n for n in names if n != "--help"]


for sub in ["info", "quad", "generate", "match", "render"]:
    body = section(sub)
    if not body:
        misses.append(f"docs/cli.md has no section `petersen {sub}`")
    first_cells = "\n".join(re.findall(r"^\|([^|]*)\|", body, re.M))
    for option in help_options(sub):
        if not re.search(r"`" + re.escape(option) + r"(?![\w-])", first_cells):
            misses.append(f"petersen {sub} {option}: no row in docs/cli.md's table of {sub}")

rows = {}
for code, subcommands in re.findall(r"^\| (\d+) \|[^|]*\|([^|]*)\|$", doc, re.M):
    rows[int(code)] = subcommands

with tempfile.TemporaryDirectory() as work:
    w = Path(work)
    (w / "path.txt").write_text("0 1\n1 2\n2 3\n3 4\n")  # 5 nodes: no perfect matching
    out = str(w / "out.obj")
    cases = {
        "info": [[example], [], [example, "--bogus"], [example, "more"], [str(w / "none.off")]],
        "quad": [[example, out], [example], [example, out, "--bogus"],
                 [example, out, "--algorithm", "blossom"], [example, out, "--threads", "abc"],
                 [example, out, "--view", "1,2"], [str(w / "none.off"), out],
                 [example, str(w / "no" / "x.obj")]],
        "generate": [[out], [], [out, "--bogus"], [out, "--kind", "donut"], [out, "--nx", "abc"],
                     [str(w / "x.stl")]],
        "match": [[str(w / "path.txt"), str(w / "m.txt")], [], [str(w / "path.txt")],
                  [str(w / "path.txt"), str(w / "m.txt"), "--bogus"],
                  [str(w / "path.txt"), str(w / "m.txt"), "--objective", "x"],
                  [str(w / "path.txt"), str(w / "m.txt"), "--seed", "abc"],
                  [str(w / "none.txt"), str(w / "m.txt")],
                  [str(w / "path.txt"), str(w / "m.txt"), "--require-perfect"]],
        "render": [[example, str(w / "p.png")], [example], [example, str(w / "p.png"), "--bogus"],
                   [example, str(w / "p.png"), "--width", "10"],
                   [example, str(w / "p.png"), "--width", "abc"],
                   [example, str(w / "p.png"), "--view", "1,2"],
                   [str(w / "none.off"), str(w / "p.png")]],
    }
    measured = []
    for sub, arg_lists in cases.items():
        measured += [(sub, args) for args in arg_lists + [["--help"]]]
    measured += [("", []), ("", ["--version"]), ("", ["--bogus"])]
    for sub, args in measured:
        command = [petersen] + ([sub] if sub else []) + args
        code = subprocess.run(command, capture_output=True).returncode
        shown = " ".join(["petersen"] + command[1:])
        if code not in rows:
            misses.append(f"exit code {code} of `{shown}`: no row in docs/cli.md's exit codes")
        elif "every subcommand" not in rows[code] and not (sub and f"`{sub}`" in rows[code]):
            misses.append(f"exit code {code} of `{shown}`: its row does not name `{sub}`")
        print(f"{code:3d}  {shown}")

for miss in misses:
    print("MISSING:", miss)
sys.exit(1 if misses else 0)

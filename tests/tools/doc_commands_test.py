#!/usr/bin/env python3
"""Runs every shell example of README.md and docs/cli.md as written:
doc_commands_test.py PETERSEN_DIR REPO.

Each ```sh block is run by bash (-e -u -o pipefail) in one scratch folder that holds a copy of the
repository's examples/, in the order of the files, with PETERSEN_DIR first on PATH, so that later
blocks see what earlier ones wrote. Blocks that set the machine up are not run here, since they are
what made the binary under test: those calling scripts/ (run and test), creating a venv or running
pip (scripts/test installs the module that way), or `cmake --install` (scripts/test-consumer).
Fails when a block fails, or when the examples leave anything beside examples/ and out/."""

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

petersen_dir, repo = sys.argv[1], Path(sys.argv[2])
SETUP = re.compile(r"^(\./scripts/|scripts/|/usr/bin/python3 -m venv|\.venv/bin/pip|cmake --install)",
                   re.M)
failed = 0
with tempfile.TemporaryDirectory() as work:
    shutil.copytree(repo / "examples", Path(work) / "examples")
    env = dict(os.environ, PATH=petersen_dir + os.pathsep + os.environ["PATH"])
    for doc in ["README.md", "docs/cli.md"]:
        text = (repo / doc).read_text()
        for match in re.finditer(r"^```sh\n(.*?)^```", text, re.M | re.S):
            block = match.group(1)
            line = text[: match.start()].count("\n") + 2
            if SETUP.search(block):
                print(f"not run here (sets the machine up): {doc}:{line}")
                continue
            run = subprocess.run(["bash", "-euo", "pipefail", "-c", block], cwd=work, env=env,
                                 capture_output=True, text=True)
            if run.returncode != 0:
                failed += 1
                print(f"FAILED: {doc}:{line} (exit {run.returncode})\n{block}{run.stderr}")
            else:
                print(f"ran: {doc}:{line}")
    left = sorted(p.name for p in Path(work).iterdir() if p.name not in ("examples", "out"))
    if left:
        failed += 1
        print("FAILED: the examples wrote outside out/:", " ".join(left))
sys.exit(1 if failed else 0)

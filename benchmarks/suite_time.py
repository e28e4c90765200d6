"""Where CI's time goes: the steps of ``.ci/run`` on a fresh clone of HEAD, timed one by one,
with the test suite's durations by file and by test and the Numba compiles inside its tests.

A fresh clone has what CI has: empty Numba caches beside the engine's sources and an empty
sarlink cache, so every kernel and every plain engine function compiles once, as on CI. The
clone installs its environment (``make .venv/bin/sarlink``, from pip's cache where the machine
has one), then runs the steps of ``make test`` (``make -j2 browser lint``, then the README's
pytest command with ``--durations=0`` and the test session's compile log,
``SARLINK_COMPILE_LOG``) and ``make docs``. The time pytest spends before its first test (the
kernels compiled at the session's start, ``tests/conftest.py``, and the workers' start) is its
wall time less the time it reports. Run from the repository's root::

    python benchmarks/suite_time.py --out benchmarks/results/suite-time.md

``--logs DIR`` keeps the steps' logs there (``commit.txt``, ``times.txt``, ``pytest.log``,
``compile.log``, ...);
``--summarize DIR`` writes the results file from such logs without running anything.
"""

from __future__ import annotations

import argparse
import os
import re
import shlex
import subprocess
import tempfile
import time
from collections import defaultdict
from pathlib import Path

import results_file

ROOT = Path(__file__).resolve().parents[1]
_DURATION = re.compile(r"^(\d+\.\d+)s (call|setup|teardown)\s+(\S+)", re.MULTILINE)
_REPORTED = re.compile(r" in (\d+\.\d+)s")


def test_command(clone: Path) -> list[str]:
    """``make test``'s pytest command, as ``make -n`` prints it, with every test's duration."""
    printed = subprocess.run(["make", "-n", "test"], cwd=clone, check=True, capture_output=True,
                             text=True).stdout.splitlines()
    line = next(line for line in printed if line.split(" ", 1)[0].endswith("/pytest"))
    return [*shlex.split(line), "--durations=0"]


def run(logs: Path) -> None:
    """Clone HEAD into a temporary folder, run CI's steps there, keep their logs in ``logs``."""
    with tempfile.TemporaryDirectory(prefix="sarlink-ci-") as tmp:
        clone = Path(tmp) / "sarlink"
        subprocess.run(["git", "clone", "-q", str(ROOT), str(clone)], check=True)
        (logs / "commit.txt").write_text(subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"], cwd=clone, check=True,
            capture_output=True, text=True).stdout)
        env = {**os.environ, "SARLINK_COMPILE_LOG": str(logs / "compile.log")}
        steps = [("install", ["make", ".venv/bin/sarlink"], "install.log"),
                 ("browser and lint", ["make", "-j2", "browser", "lint"], "lint.log"),
                 ("pytest", test_command(clone), "pytest.log"),
                 ("docs", ["make", "docs"], "docs.log")]
        (logs / "compile.log").unlink(missing_ok=True)
        with (logs / "times.txt").open("w") as times:
            for name, command, log in steps:
                start = time.monotonic()
                with (logs / log).open("w") as out:
                    subprocess.run(command, cwd=clone, env=env, stdout=out,
                                   stderr=subprocess.STDOUT, check=True)
                times.write(f"{name}\t{time.monotonic() - start:.0f}\n")
                times.flush()


def summary(logs: Path) -> str:
    """The results file's body from the logs of a run."""
    steps = [line.split("\t") for line in (logs / "times.txt").read_text().splitlines()]
    seconds = {name: float(s) for name, s in steps}
    text = (logs / "pytest.log").read_text()
    reported = float(_REPORTED.findall(text)[-1])
    durations = [(float(s), phase, test) for s, phase, test in _DURATION.findall(text)]
    by_file: dict[str, float] = defaultdict(float)
    for s, _, test in durations:
        by_file[test.split("::")[0]] += s
    compiles = [line.split("\t") for line in (logs / "compile.log").read_text().splitlines()]
    compiled = sum(float(c[3]) for c in compiles)
    total = sum(seconds.values())
    lines = ["| step | wall (s) |", "|---|---|"]
    lines += [f"| {name} | {s:.0f} |" for name, s in seconds.items()]
    before = seconds["pytest"] - reported
    commit = (logs / "commit.txt").read_text().strip()
    lines += [f"| **all of `.ci/run`** | **{total:.0f}** |", "",
              f"On a fresh clone of commit {commit}. pytest: {seconds['pytest']:.0f} s "
              f"wall, of which {before:.0f} s before its first test (the kernels compiled at "
              f"the session's start and the workers' start) and {reported:.0f} s of tests; "
              f"the tests' own durations sum to {sum(d[0] for d in durations):.0f} s over the "
              f"workers, {compiled:.0f} s of which are Numba compiles in the tests' own "
              f"processes ({len(compiles)} compiles; those of the sweeps' worker processes "
              f"are not in the log).", "",
              "The test files that take longest (seconds, setup and calls summed):", "",
              "| test file | s |", "|---|---|"]
    lines += [f"| {f} | {s:.0f} |" for f, s in sorted(by_file.items(), key=lambda x: -x[1])[:20]]
    lines += ["", "The tests that take longest:", "", "| test | phase | s |", "|---|---|---|"]
    lines += [f"| `{t}` | {p} | {s:.1f} |" for s, p, t in sorted(durations, reverse=True)[:25]]
    lines += ["", "The longest compiles in the tests' processes:", "",
              "| test | what compiled | s |", "|---|---|---|"]
    lines += [f"| `{c[1]}` | {c[2]} | {float(c[3]):.1f} |"
              for c in sorted(compiles, key=lambda c: -float(c[3]))[:15]]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, help="write the results here (markdown)")
    parser.add_argument("--logs", type=Path, help="keep the steps' logs in this folder")
    parser.add_argument("--summarize", type=Path, metavar="DIR",
                        help="write the results from the logs in DIR; run nothing")
    args = parser.parse_args()
    if args.summarize:
        logs = args.summarize
    else:
        logs = args.logs or Path(tempfile.mkdtemp(prefix="sarlink-ci-logs-"))
        logs.mkdir(parents=True, exist_ok=True)
        run(logs.resolve())
    body = summary(logs)
    print(body)
    if args.out:
        results_file.write(args.out, "Where CI's time goes", body)


if __name__ == "__main__":
    main()

"""Writing a results file: every file under ``benchmarks/results/`` opens with the same header.

A measured number means little without how, when, where and on which code it was measured,
so each benchmark writes its file through :func:`write`, which puts the command that ran it,
the date, the host (CPU model, cores, Python, load average) and the commit above the body.
The commit is ``git rev-parse --short HEAD`` with ``+dirty`` when a tracked file outside
``benchmarks/results/`` differs from it (a results file written earlier changes no timing),
taken when the benchmark imports this module, as it starts: an edit made while it runs is not
what it measured.
"""

from __future__ import annotations

import datetime
import os
import platform
import shlex
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
"""The repository."""


def _git(*args: str) -> str:
    """The output of a git command run in the repository, or '' where git cannot answer."""
    try:
        return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def commit() -> str:
    """The checked-out commit, ``+dirty`` when the code differs from it, or 'unknown'."""
    rev = _git("rev-parse", "--short", "HEAD")
    if not rev:
        return "unknown"
    changed = _git("status", "--porcelain", "--untracked-files=no", "--", ".",
                   ":(exclude)benchmarks/results")
    return rev + ("+dirty" if changed else "")


COMMIT = commit()
"""The commit the running benchmark started on."""


def cpu_model() -> str:
    """The CPU's model name (Linux's /proc/cpuinfo), else what :mod:`platform` knows."""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def command() -> str:
    """The command that is running, as typed from the repository's root."""
    script = Path(sys.argv[0]).resolve()
    shown = script.relative_to(ROOT) if script.is_relative_to(ROOT) else script
    return shlex.join(["python", str(shown), *sys.argv[1:]])


def header(title: str) -> str:
    """The opening of a results file: its title, then command, date, host and commit."""
    now = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    load = f", load average {os.getloadavg()[0]:.1f}" if hasattr(os, "getloadavg") else ""
    return "\n".join([
        f"# {title}",
        "",
        f"- command: `{command()}`",
        f"- date: {now}",
        f"- host: {cpu_model()}, {os.cpu_count()} cores, Python {platform.python_version()}"
        f"{load}",
        f"- commit: {COMMIT}",
        "",
        ""])


def write(path: Path, title: str, body: str) -> None:
    """Write ``body`` to ``path`` under the header, making its folder if needed."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(header(title) + body.strip("\n") + "\n", encoding="utf-8")
    print(f"written to {path}")

"""The import graph's contracts (pyproject.toml, ``[tool.importlinter]``): layered subpackages,
the engine's plug-ins between its seam and its kernel, and no cycle among a package's modules.

``make lint`` runs them too; here the suite fails on a violation, and a copy of the package
with one upward import shows that the contracts catch it.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
LINT = Path(sys.executable).with_name("lint-imports")


def _lint(src: Path) -> subprocess.CompletedProcess[str]:
    """``lint-imports`` on the package ``sarlink`` found in ``src``, with the repository's
    contracts and no cache (nothing is written beside the sources)."""
    env = {**os.environ, "PYTHONPATH": str(src)}
    return subprocess.run([str(LINT), "--no-cache", "--no-logo", str(ROOT / "pyproject.toml")],
                          cwd=src, env=env, capture_output=True, text=True, check=False)


def test_the_import_graph_keeps_every_contract() -> None:
    out = _lint(ROOT / "src")
    assert out.returncode == 0, out.stdout + out.stderr
    assert "0 broken" in out.stdout


def test_an_import_of_a_higher_layer_breaks_the_layers(tmp_path: Path) -> None:
    """The configuration imports the command line: a layer above every other."""
    shutil.copytree(ROOT / "src" / "sarlink", tmp_path / "sarlink",
                    ignore=shutil.ignore_patterns("__pycache__"))
    base = tmp_path / "sarlink" / "config" / "base.py"
    base.write_text(base.read_text() + "\nimport sarlink.cli.common  # noqa: E402\n")
    out = _lint(tmp_path)
    assert out.returncode == 1
    assert "sarlink's subpackages are layered BROKEN" in out.stdout
    assert "sarlink.config.base -> sarlink.cli.common" in out.stdout

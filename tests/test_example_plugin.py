"""The example plug-in package (examples/plugin) as a user installs it: ``pip install`` puts
it where Python finds it, and sarlink finds its two planners through its entry points."""

from __future__ import annotations

import importlib.util
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from sarlink.planners.registry import PLANNERS
from sarlink.testing import check_planner, check_rule

ROOT = Path(__file__).resolve().parents[1]


def _installer() -> list[str]:
    """pip, or uv's pip where the environment has no pip (``make`` creates it with uv)."""
    if importlib.util.find_spec("pip") is not None:
        return [sys.executable, "-m", "pip", "install", "--quiet"]
    uv = shutil.which("uv") or str(ROOT / ".tools" / "bin" / "uv")
    return [uv, "pip", "install", "--quiet", "--python", sys.executable]


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """``pip install examples/plugin`` into a folder of its own (not into this environment)."""
    target = tmp_path_factory.mktemp("site")
    subprocess.run([*_installer(), "--no-deps", "--target", str(target),
                    str(ROOT / "examples" / "plugin")], check=True)
    return target


def _sarlink(target: Path, *args: str) -> str:
    env = {**os.environ, "PYTHONPATH": str(target)}
    return subprocess.run([str(Path(sys.executable).parent / "sarlink"), *args], env=env,
                          check=True, capture_output=True, text=True).stdout


@pytest.mark.parametrize("command", ["plugins", "planners"])
def test_sarlink_plugins_lists_the_installed_plug_ins(installed: Path, command: str) -> None:
    data = json.loads(_sarlink(installed, command, "--json"))
    listed = {p["name"]: p for p in data["planners"]}
    for name, kind in (("rays", "route"), ("tether", "rule")):
        assert listed[name]["kind"] == kind
        assert listed[name]["origin"] == f"sarlink-example-plugin 0.1.0 (entry point {name})"
        assert not listed[name]["paper"]
    assert {r["name"] for r in data["radios"]} >= {"disc", "shadowing"}
    assert data["broken"] == []


@pytest.mark.usefixtures("fresh_registries")
@pytest.mark.parametrize("name", ["rays", "tether"])
def test_each_plug_in_simulates_by_name_and_keeps_the_contract(
        installed: Path, name: str, monkeypatch: pytest.MonkeyPatch) -> None:
    out = json.loads(_sarlink(installed, "simulate", "--planner", name, "--drones", "4",
                              "--rc", "500", "--td", "600", "--json"))
    assert out["planner"] == name and out["drones"] == 4
    monkeypatch.syspath_prepend(str(installed))
    monkeypatch.setattr(PLANNERS, "_loaded", False)
    check_planner(name, drones=(1, 5), runs=1, horizon=900.0, rc=500.0)
    if name == "tether":
        check_rule(name, runs=1, horizon=900.0)

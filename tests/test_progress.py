"""Progress as a log shows it (sarlink.progress) and the compile stage's notice
(sarlink.execution, sarlink.compile_times)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from sarlink import compile_times, execution
from sarlink.execution import sweep
from sarlink.progress import PlainLines
from test_experiments import small


def test_plain_lines_start_every_tenth_and_end() -> None:
    out = io.StringIO()
    now = [0.0]
    lines = PlainLines("runs", stream=out, clock=lambda: now[0])
    task = lines.add_task("sweep (2 points): CovB", total=30)
    for _ in range(30):
        now[0] += 2.0
        lines.advance(task, 1)
    text = out.getvalue().splitlines()
    assert text[0] == "sweep (2 points): CovB: 0% (0/30 runs, 0 s)"
    assert text[1:] == [*(f"sweep: {10 * k}% ({3 * k}/30 runs, {6 * k} s)" for k in range(1, 10)),
                        "sweep: done (30/30 runs, 60 s)"]


def test_a_resumed_task_starts_where_it_stands() -> None:
    out = io.StringIO()
    lines = PlainLines("runs", stream=out)
    task = lines.add_task("sweep", total=10, completed=10)
    assert out.getvalue().startswith("sweep: done (10/10 runs")
    lines.advance(task, 0)
    assert len(out.getvalue().splitlines()) == 1


def test_the_estimate_takes_this_machine_s_record(monkeypatch: pytest.MonkeyPatch,
                                                  tmp_path: Path) -> None:
    monkeypatch.setattr(compile_times, "_file", lambda: tmp_path / "seconds.json")
    parts = [("kernel", "covb", "disc"), ("kernel", "conb", "disc"), ("mtsp",)]
    typical = compile_times.TYPICAL
    assert compile_times.compile_estimate(parts, 1) == 2 * typical["kernel"] + typical["GA"]
    assert compile_times.compile_estimate(parts, 8) == max(typical.values())
    compile_times.record_compile(("kernel", "covb", "disc"), 100.0)
    assert compile_times.compile_estimate(parts, 2) == 100.0
    assert compile_times.describe_parts(parts) == "kernels of covb and conb, the GA"
    # mtsp-conb flies ConB's kernel: one name for one kernel
    assert compile_times.describe_parts([("kernel", "mtsp-conb", "disc"), ("ranges", "mtsp",
                                          "disc")]) == "kernel of conb, the staircase"


def test_a_kernel_forming_a_chain_is_a_part_of_its_own() -> None:
    """``on_detect = relay`` compiles its own kernel (``CHAIN``): its part ends in
    :data:`~sarlink.compile_times.CHAIN_PART`, which is no relay strategy."""
    chain = compile_times.CHAIN_PART
    parts = [("kernel", "covb", "disc", chain), ("kernel", "covb", "disc", "tree", chain),
             ("kernel", "covb", "disc", "tree")]
    assert [compile_times.part_relays(p) for p in parts] == [None, "tree", "tree"]
    assert compile_times.describe_parts(parts) == (
        "kernels of covb forming a chain, covb with relays (tree) forming a chain and covb "
        "with relays (tree)")


def test_a_sweep_says_what_it_compiles_before_it_does(
        monkeypatch: pytest.MonkeyPatch, tmp_path: Path,
        capsys: pytest.CaptureFixture[str]) -> None:
    """With everything compiled a sweep says nothing of compiling; told that nothing is, it
    announces its parts with an estimate and counts them off."""
    monkeypatch.setattr(compile_times, "_file", lambda: tmp_path / "seconds.json")
    experiment = small(runs=2, grid={"planner": ["covb", "conb"], "rc": [500.0]})
    sweep(experiment, tmp_path / "first", workers=2)  # compiles, on a fresh machine
    capsys.readouterr()
    sweep(experiment, tmp_path / "warm", workers=2)
    assert "compiling" not in capsys.readouterr().err
    monkeypatch.setattr(execution, "_compiled", lambda part: False)
    sweep(experiment, tmp_path / "cold", workers=2)
    err = capsys.readouterr().err.splitlines()
    assert err[0].startswith("compiling the engine (kernels of covb and conb), once per "
                             "machine: about ")
    assert err[1].startswith("compiling the engine: 50% (1/2 parts, ")
    assert err[2].startswith("compiling the engine: done (2/2 parts, ")
    assert any(line.endswith("done (4/4 runs, " + line.split(", ")[-1]) for line in err[3:])
    assert set(compile_times._record()) == {"kernel covb", "kernel conb"}

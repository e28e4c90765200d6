"""Progress as a log shows it (sarlink.progress) and the compile stage's notice
(sarlink.execution, sarlink.compile_times)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sarlink import Mission, compile_times, execution
from sarlink.compile_times import Part
from sarlink.execution import sweep
from sarlink.progress import PlainLines
from sarlink.simulation import prepare
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
    parts = [Part("kernel", "covb"), Part("kernel", "conb"), Part("mtsp")]
    typical = compile_times.TYPICAL
    assert compile_times.compile_estimate(parts, 1) == 2 * typical["kernel"] + typical["GA"]
    assert compile_times.compile_estimate(parts, 8) == max(typical.values())
    compile_times.record_compile(Part("kernel", "covb"), 100.0)
    assert compile_times.compile_estimate(parts, 2) == 100.0
    assert compile_times.describe_parts(parts) == "kernels of covb and conb, the GA"
    # mtsp-conb flies ConB's kernel: one name for one kernel
    assert compile_times.describe_parts([Part("kernel", "mtsp-conb"), Part("ranges", "mtsp")]
                                        ) == "kernel of conb, the staircase"


def test_each_seam_of_a_mission_names_its_own_kernel() -> None:
    parts = [Part("kernel", "covb", chain=True), Part("kernel", "covb", relays="tree", chain=True),
             Part("kernel", "covb", relays="tree"), Part("kernel", "conb", energy=True),
             Part("kernel", "covb", target="walk", many=True)]
    assert compile_times.describe_parts(parts) == (
        "kernels of covb forming a chain, covb with relays (tree) forming a chain, covb "
        "with relays (tree), conb on batteries and covb with a moving target (walk) with "
        "several targets")


SEAMS = {"relays": st.sampled_from([0, 1]), "on_detect": st.sampled_from(["continue", "relay"]),
         "battery_wh": st.sampled_from([None, 100.0]),
         "motion": st.sampled_from(["still", "walk", "drift"]), "count": st.sampled_from([1, 2])}


@settings(max_examples=30, deadline=None)
@given(planner=st.sampled_from(["covb", "conb", "concov", "parallel"]), radio=st.sampled_from(
    ["disc", "shadowing"]), seams=st.fixed_dictionaries(SEAMS))
def test_a_mission_s_part_is_the_kernel_it_flies(planner: str, radio: str,
                                                 seams: dict[str, object]) -> None:
    """The part a sweep compiles before its runs is the kernel object its runs call (the
    engine's memo of kernels; neither is compiled here)."""
    if seams["count"] == 2 and seams["on_detect"] == "relay":
        seams["on_detect"] = "continue"  # several targets take no chain
    if seams["count"] == 2:
        seams["relays"] = 0  # nor relays
    mission = Mission.build(planner=planner, radio=radio, drones=3, **seams)
    assert Part.kernel_of(mission).kernel() is prepare(mission).kernel


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

"""The table of mission flags (sarlink.cli.flags): every command's every mission flag, given a
bad value, fails with one line that names the flag as the user typed it (issue 26)."""

from __future__ import annotations

from pathlib import Path
from typing import Literal, get_origin

import pytest
import typer
from typer.testing import CliRunner

from sarlink.cli import app
from sarlink.cli.flags import FLAGS, Flag, flags_of
from sarlink.config import Mission, param_groups

runner = CliRunner()
COMMANDS = typer.main.get_command(app).commands  # type: ignore[attr-defined]
REQUIRED = {"design": ["--td", "100", "--ps", "0.9"]}
"""Options a command cannot run without, beside the flag under test."""


def _out_of_range(flag: Flag) -> str:
    """A value the mission rejects, read from the model's own field (not from the table)."""
    if flag.param is None:
        return "no-such-reading" if flag.name == "--reading" else "/no/such/mission.toml"
    model = type(getattr(Mission(), param_groups()[flag.param]))
    field = model.model_fields[flag.param]
    if get_origin(field.annotation) is Literal or flag.type is str:
        return "no-such-value"
    for bound in field.metadata:
        low = getattr(bound, "ge", None)
        if low is not None:
            return str(low - 1)
        low = getattr(bound, "gt", None)
        if low is not None:
            return str(low)
    raise AssertionError(f"{flag.name}: no bad value known")


CASES = [(command, flag) for command in sorted(COMMANDS) for flag in flags_of(command)]


@pytest.mark.parametrize(("command", "flag"), CASES,
                         ids=[f"{c} {f.name}" for c, f in CASES])
def test_a_bad_value_names_the_flag_typed(command: str, flag: Flag, tmp_path: Path) -> None:
    bad = [_out_of_range(flag)]
    if flag.type in (int, float):
        bad.append("not-a-number")
    for value in bad:
        args = [command, *REQUIRED.get(command, []), flag.name, value]
        if command == "replay":
            args += ["--out", str(tmp_path / "r.html")]
        out = runner.invoke(app, args)
        assert out.exit_code == 2, (args, out.output)
        lines = out.output.strip().splitlines()
        assert len(lines) == 1 and lines[0].startswith("error:"), (args, out.output)
        assert flag.name in lines[0], (args, lines[0])
        others = {f.name for f in FLAGS} - {flag.name}
        named = [name for name in others if f"{name} (" in lines[0] or f"'{name}'" in lines[0]]
        assert not named, (args, lines[0])


@pytest.mark.parametrize("command", ["replay", "design"])
def test_flags_named_otherwise_in_the_mission_are_named_as_typed(command: str) -> None:
    """The drift that issue 26 found: replay --td reported --horizon, replay and design
    --shadowing-sigma reported --sigma."""
    args = [command, *REQUIRED.get(command, []), "--shadowing-sigma", "31"]
    out = runner.invoke(app, args)
    assert "--shadowing-sigma (channel.sigma)" in out.output and "--sigma" not in out.output
    if command == "replay":
        out = runner.invoke(app, ["replay", "--td", "0"])
        assert "--td (timing.horizon)" in out.output and "--horizon" not in out.output


def test_every_command_that_takes_mission_flags_takes_them_from_the_table() -> None:
    """A command's options in the Mission panel are exactly its rows, and no command declares
    a mission parameter's flag of its own."""
    assert {c for flag in FLAGS for c in flag.commands} <= set(COMMANDS)
    mission_params = {"--" + name.replace("_", "-") for name in param_groups()}
    for name, command in COMMANDS.items():
        rows = {flag.name for flag in flags_of(name)}
        panel = {opt for p in command.params if getattr(p, "rich_help_panel", None) == "Mission"
                 for opt in p.opts}
        assert panel == rows, name
        own = {opt for p in command.params for opt in p.opts} - rows
        assert own & mission_params <= OWN_MEANING.get(name, set()), name


OWN_MEANING = {"design": {"--planner"}, "export": {"--altitude"}, "summarize": {"--rc"}}
"""Options named like a mission parameter that mean something else: design's --planner
chooses the planners to compare (a field of the request); export's --altitude is the flight
height written into the drones' files, not the radio model's channel.altitude; summarize's
--rc evaluates stored runs at a range they were not flown at (their notification staircase)."""


def test_the_table_declares_each_flag_once_with_its_parameter_s_range() -> None:
    names = [flag.name for flag in FLAGS]
    assert len(names) == len(set(names))
    by_name = {flag.name: flag for flag in FLAGS}
    assert by_name["--td"].param == "horizon" and by_name["--td"].range == "> 0"
    assert by_name["--p-miss"].range == "[0, 1]"
    assert by_name["--look"].range == "one of per-pass, per-period"
    assert "(> 0)" in runner.invoke(app, ["simulate", "--help"]).output

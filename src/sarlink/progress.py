"""Progress shown while work runs: bars in a terminal, plain lines in a log.

A reproduction or a sweep runs for minutes; its user watches either a terminal, where rich's
live bars redraw in place, or a log file (``make demo > demo.log``, a CI job, a cluster's
batch system), where redrawn bars would be lost or garbled. :func:`progress` gives the one or
the other behind the same calls, the plain kind writing a line to standard error at the start,
at every tenth of the way and at the end of each task.
"""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from types import TracebackType
from typing import Protocol, TextIO

from rich.progress import (
    BarColumn,
    MofNCompleteColumn,
    Progress,
    ProgressColumn,
    Task,
    TaskID,
    TextColumn,
    TimeElapsedColumn,
    TimeRemainingColumn,
)
from rich.text import Text

__all__ = ["Bars", "PlainLines", "progress"]


class Bars(Protocol):
    """What work reports its progress to (the calls of :class:`rich.progress.Progress` that
    sarlink uses)."""

    def __enter__(self) -> Bars: ...

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None: ...

    def add_task(self, description: str, *, total: float | None = ..., completed: int = ...
                 ) -> TaskID: ...

    def advance(self, task_id: TaskID, advance: float = ...) -> None: ...


@dataclass
class _Line:
    description: str
    total: float
    done: float
    start: float
    shown: int = -1  # tenths of the way last written


@dataclass
class PlainLines:
    """Progress as lines of text, for a log: one when a task starts (with its whole
    description), one at every tenth of its total and one when it is complete (with the
    description up to its first parenthesis or colon)."""

    unit: str
    stream: TextIO = field(default_factory=lambda: sys.stderr)
    clock: Callable[[], float] = time.perf_counter
    _tasks: list[_Line] = field(default_factory=list)

    def __enter__(self) -> PlainLines:
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        return None

    def add_task(self, description: str, *, total: float | None = None, completed: int = 0
                 ) -> TaskID:
        line = _Line(description, float(total or 0), float(completed), self.clock())
        self._tasks.append(line)
        self._write(line)
        return TaskID(len(self._tasks) - 1)

    def advance(self, task_id: TaskID, advance: float = 1) -> None:
        line = self._tasks[task_id]
        line.done += advance
        self._write(line)

    def _write(self, line: _Line) -> None:
        tenths = 10 if line.total <= 0 else int(10 * line.done / line.total)
        if tenths == line.shown:
            return
        first = line.shown < 0
        line.shown = tenths
        seconds = self.clock() - line.start
        count = (f"{line.done:,.0f}/{line.total:,.0f} {self.unit}" if line.total > 0
                 else f"{line.done:,.0f} {self.unit}")
        state = ("done" if tenths >= 10
                 else f"{100 * line.done / line.total:.0f}%")
        name = line.description if first else _short(line.description)
        print(f"{name}: {state} ({count}, {seconds:.0f} s)", file=self.stream, flush=True)


def _short(description: str) -> str:
    """The description up to its first parenthesis or colon: said whole once, then short."""
    for mark in (" (", ":"):
        description = description.split(mark, 1)[0]
    return description


class _PerSecond(ProgressColumn):
    def __init__(self, unit: str) -> None:
        super().__init__()
        self.unit = unit

    def render(self, task: Task) -> Text:
        speed = task.finished_speed or task.speed
        return Text(f"? {self.unit}/s" if speed is None else f"{speed:,.0f} {self.unit}/s",
                    style="progress.data.speed")


def progress(enabled: bool, unit: str, *, rate: bool = True) -> Bars:
    """Bars counting ``unit`` (``"runs"``, ``"parts"``): live in a terminal, :class:`PlainLines`
    when standard output is not one, nothing unless ``enabled``. ``rate`` adds the units per
    second and the time left (the time taken otherwise)."""
    if enabled and not sys.stdout.isatty():
        return PlainLines(unit)
    columns: list[str | ProgressColumn] = [
        TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TextColumn(unit)]
    columns += [_PerSecond(unit), TimeRemainingColumn()] if rate else [TimeElapsedColumn()]
    return Progress(*columns, disable=not enabled)

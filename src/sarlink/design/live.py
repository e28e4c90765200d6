"""The answer as it sharpens: the best candidate so far and its interval, after every round.

A coordinator watching a design can stop it once the answer is good enough. In a terminal a
live table redraws in place; in a log (a file, a CI job) a line is written per round. Both go
to standard error, away from the answer.
"""

from __future__ import annotations

import sys
import time
from types import TracebackType
from typing import TextIO

from rich.console import Console
from rich.live import Live
from rich.table import Table

from sarlink.design.search import Snapshot

__all__ = ["LiveView"]


class LiveView:
    """Shows a design's :class:`Snapshot` after each round and the runs simulated within it;
    ``show`` False: nothing."""

    def __init__(self, show: bool = True, stream: TextIO | None = None) -> None:
        self.stream = sys.stderr if stream is None else stream
        self.show = show
        self.started = time.monotonic()
        self.simulated = 0
        self.snapshot: Snapshot | None = None
        terminal = show and self.stream.isatty()
        self._live = (Live(self._table(), console=Console(file=self.stream),
                           auto_refresh=False) if terminal else None)

    def __enter__(self) -> LiveView:
        if self._live is not None:
            self._live.__enter__()
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        if self._live is not None:
            self._live.__exit__(kind, error, trace)

    def runs(self, simulated: int) -> None:
        """Runs simulated so far (within a round, as chunks finish)."""
        self.simulated = simulated
        if self._live is not None:
            self._live.update(self._table(), refresh=True)

    def round(self, snapshot: Snapshot) -> None:
        """Where the search stands after a round."""
        self.snapshot = snapshot
        if self._live is not None:
            self._live.update(self._table(), refresh=True)
        elif self.show:
            print(f"design {time.monotonic() - self.started:7.1f} s: {self._best()}; "
                  f"{snapshot.decided}/{snapshot.opened} candidates decided, "
                  f"{snapshot.used:,} runs used, {self.simulated:,} simulated",
                  file=self.stream, flush=True)

    def _best(self) -> str:
        s = self.snapshot
        if s is None or s.best is None:
            return "no runs yet"
        e = s.best
        return (f"best so far {s.label} with {e.drones} drones, P_s = {e.p:.3f} "
                f"[{e.lo:.3f}, {e.hi:.3f}] from {e.runs:,} runs ({e.verdict.value})")

    def _table(self) -> Table:
        table = Table(title="design", title_justify="left", show_header=False, box=None)
        table.add_column(justify="right", style="dim")
        table.add_column()
        s = self.snapshot
        table.add_row("elapsed", f"{time.monotonic() - self.started:.0f} s")
        table.add_row("best so far", self._best())
        if s is not None:
            table.add_row("candidates", f"{s.decided}/{s.opened} decided")
            table.add_row("runs", f"{s.used:,} used, {self.simulated:,} simulated")
        return table

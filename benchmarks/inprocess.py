"""A sweep's workers in the benchmark's own process, for benchmarks that time a sweep's CPU.

:func:`sarlink.execution.sweep_all` takes any ``pool`` with ``results``; this one runs every
job here, one after the other, so that the CPU time measured is that of the work, without a
worker's start-up. Plug-ins registered in code are not handed on: a benchmark using it
registers none.
"""

from __future__ import annotations

from sarlink import execution


class InProcess:
    """Workers that run every job in this process, one after the other."""

    def results(self, jobs):  # type: ignore[no-untyped-def]
        for call, job in zip(execution._calls(jobs), jobs, strict=True):
            yield job, execution._run_chunk(*call)

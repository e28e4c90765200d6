"""sarlink.env speed: agent-steps per second, one process, CPU time.

An agent-step is one agent's observation, action and reward in one step of the environment
(a step of the engine at which drones decide; the engine runs the steps between at its own
speed). Random continuous actions (NumPy draws: the spaces' ``sample`` would time
gymnasium), the paper's square with r_c = 500 m, 10 drones, runs of seed 0 until the
notification or the 4000 s horizon. Three ways: PettingZoo's parallel API
(dicts of arrays per agent), the AEC form (agents in turn, PettingZoo's wrapper), and the
batched form (``BatchEnv``, arrays in and out, 16 missions per call). For scale, the same
runs flown by ``simulate`` (CovB's decisions inside the kernel). Run with

    python benchmarks/bench_env.py --out benchmarks/results/env.md
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

import results_file
from sarlink import Mission, simulate
from sarlink.env import BatchEnv, env, parallel_env


def parallel(mission: Mission, runs: int) -> tuple[int, float]:
    e = parallel_env(mission)
    e.reset(seed=0)  # compiles (or loads) the kernels, outside the timing
    e.step({agent: np.zeros(2) for agent in e.agents})
    rng = np.random.default_rng(0)
    agent_steps, start = 0, time.process_time()
    for run in range(runs):
        e.reset(seed=0, options={"run": run})
        while e.agents:
            agent_steps += len(e.agents)
            e.step(dict(zip(e.agents, rng.uniform(-1, 1, (len(e.agents), 2)), strict=True)))
    return agent_steps, time.process_time() - start


def aec(mission: Mission, runs: int) -> tuple[int, float]:
    e = env(mission)
    e.reset(seed=0)  # compiles (or loads) the kernels, outside the timing
    e.step(np.zeros(2))
    rng = np.random.default_rng(0)
    agent_steps, start = 0, time.process_time()
    for run in range(runs):
        e.reset(seed=0, options={"run": run})
        for _agent in e.agent_iter():
            *_, terminated, truncated, _ = e.last()
            agent_steps += 1
            e.step(None if terminated or truncated else rng.uniform(-1, 1, 2))
    return agent_steps, time.process_time() - start


def batched(mission: Mission, runs: int, batch: int = 16) -> tuple[int, float]:
    batch = min(batch, runs)
    b = BatchEnv(mission, batch=batch)
    b.reset(seed=0)  # compiles (or loads) the kernels, outside the timing
    b.step(np.zeros((batch, b.drones, 2)))
    rng = np.random.default_rng(0)
    agent_steps, start = 0, time.process_time()
    for first in range(0, runs, batch):
        step = b.reset(seed=0, first_run=first)
        live = ~(step.terminated | step.truncated)
        while live.any():
            agent_steps += int(live.sum()) * b.drones
            step = b.step(rng.uniform(-1, 1, (batch, b.drones, 2)))
            live &= ~(step.terminated | step.truncated)
    return agent_steps, time.process_time() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=16, help="a multiple of 16")
    parser.add_argument("--out", type=Path)
    args = parser.parse_args()
    mission = Mission.build(planner="covb", drones=10, rc=500.0)
    simulate(mission, 0, 0)
    start = time.process_time()
    for run in range(args.runs):
        simulate(mission, 0, run)
    engine = (time.process_time() - start) / args.runs
    rows = []
    for name, fn in (("parallel", parallel), ("AEC", aec), ("batched (16)", batched)):
        steps, seconds = fn(mission, args.runs)
        rows.append(f"| {name} | {steps:,} | {seconds:.2f} | {steps / seconds / 1e3:.1f} |")
        print(rows[-1], flush=True)
    text = "\n".join([
        "Random continuous actions (NumPy draws), 10 drones, r_c = 500 m, runs 0.. of seed 0 "
        "until "
        "notification or the 4000 s horizon; one process, CPU time.",
        "",
        "| form | agent-steps | CPU s | k agent-steps/s |",
        "|---|---|---|---|",
        *rows,
        "",
        f"For scale: `simulate` flies one such run (CovB, decisions in the kernel) in "
        f"{engine * 1e3:.1f} ms CPU.",
        ""])
    print(text)
    if args.out:
        results_file.write(args.out, "Environment benchmark", text)


if __name__ == "__main__":
    main()

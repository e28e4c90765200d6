"""Tune a linear policy on sarlink.env with CMA-ES and compare it with CovB and ConB on P_s.

Every drone turns to ``tanh(W @ observation + b)`` (a direction; the environment scales it to
unit length) when it decides. CMA-ES (the ``cma`` package) tunes ``W`` and ``b`` to maximise the
mission's reward (notification, sooner is better) on training runs; the tuned policy and the
paper's CovB and ConB are then compared on other runs by P_s, the fraction of runs whose BS is
notified within the horizon, as ``sarlink sweep`` reports it. A few minutes on one core:

    pip install "sarlink[rl]" cma
    python examples/learn_policy.py
"""

from __future__ import annotations

import argparse

import cma
import numpy as np

from sarlink import Mission, simulate
from sarlink.env import BatchEnv

NEIGHBOURS = 2


def fly(batch: BatchEnv, theta: np.ndarray, seed: int, first_run: int
        ) -> tuple[float, list[bool]]:
    """Mean reward of the linear policy ``theta`` over a batch of runs, and which runs
    notified the BS."""
    width = batch.observation_space.shape[0]
    w, b = theta[:2 * width].reshape(2, width), theta[2 * width:]
    step = batch.reset(seed=seed, first_run=first_run)
    total = np.zeros(batch.batch)
    while not np.all(step.terminated | step.truncated):
        step = batch.step(np.tanh(step.observations @ w.T + b))
        total += step.rewards[:, 0]  # a team reward: every drone gets the same
    results = batch.results()
    return float(total.mean()), [r is not None and r.t_notify is not None for r in results]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--drones", type=int, default=6)
    parser.add_argument("--rc", type=float, default=500.0)
    parser.add_argument("--horizon", type=float, default=1000.0, help="t_d, s")
    parser.add_argument("--runs", type=int, default=8, help="training runs per candidate")
    parser.add_argument("--generations", type=int, default=15)
    parser.add_argument("--popsize", type=int, default=8)
    parser.add_argument("--test-runs", type=int, default=48, help="runs of the comparison")
    args = parser.parse_args()

    mission = Mission.build(planner="covb", drones=args.drones, rc=args.rc,
                            horizon=args.horizon)  # covb: the drones decide every t_s
    train = BatchEnv(mission, batch=args.runs, neighbours=NEIGHBOURS)
    width = train.observation_space.shape[0]
    es = cma.CMAEvolutionStrategy(np.zeros(2 * width + 2), 0.5,
                                  {"popsize": args.popsize, "seed": 1, "verbose": -9})
    for generation in range(args.generations):
        candidates = es.ask()
        rewards = [fly(train, np.asarray(x), seed=1, first_run=0)[0] for x in candidates]
        es.tell(candidates, [-r for r in rewards])
        print(f"generation {generation + 1}: best reward {max(rewards):.3f}", flush=True)

    test = BatchEnv(mission, batch=args.test_runs, neighbours=NEIGHBOURS)
    _, notified = fly(test, np.asarray(es.result.xfavorite), seed=2, first_run=0)
    print(f"\nP_s on {args.test_runs} runs of seed 2 (N = {args.drones}, r_c = {args.rc:g} m, "
          f"t_d = {args.horizon:g} s):")
    print(f"  linear policy (CMA-ES)  {np.mean(notified):.3f}")
    for planner in ("covb", "conb"):
        m = mission.replace(planner=planner)
        p_s = np.mean([simulate(m, 2, run).notified() for run in range(args.test_runs)])
        print(f"  {planner:<23} {p_s:.3f}")


if __name__ == "__main__":
    main()

"""sarlink's ``drift`` target motion against OpenDrift's own Leeway model, on the same constant
wind and current (docs/model.md, Drift).

OpenDrift (PyPI ``opendrift``) cannot share the project's environment (its dependencies
conflict with the lock), so it is installed into a venv of its own (``.opendrift``, ignored by git):

    python3 -m venv .opendrift && .opendrift/bin/pip install opendrift

and this script runs its OpenDrift side there, as a subprocess (``--opendrift-python``): that
side seeds ``--elements`` elements of one Leeway class at one point (on the equator, where a
metre east is a metre east everywhere near it), drifts them for ``--hours`` hours in steps of
``--dt`` seconds under ``reader_constant`` forcing (no land), and prints each element's final
displacement east and north in metres (pyproj's geodesic from the seed point, the geodesic
OpenDrift moves its elements along) and the CPU seconds of ``run``. The sarlink side starts as
many targets at the origin and steps them by the ``drift`` hooks alone (no drones:
:func:`sarlink.engine.target_motion.drift.drift_targets`), in the same steps. The comparison:
the centroid after the drift and the spread (standard deviation) along and across the wind,
each with its sampling error, and the CPU cost per target-step of each. Writes
``benchmarks/results/drift.md``. Run with

    python benchmarks/drift_opendrift.py --elements 5000 --hours 24
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import results_file

RESULTS = Path(__file__).resolve().parent / "results" / "drift.md"
OPENDRIFT_PYTHON = ".opendrift/bin/python"
OBJECT_TYPE = {"PIW-1": 1}  # OBJECTPROP.DAT's row numbers


def opendrift_side(args: argparse.Namespace) -> None:
    """Run OpenDrift's Leeway (in OpenDrift's venv) and print the displacements as JSON."""
    import datetime
    import logging
    from importlib.metadata import version

    import pyproj
    from opendrift.models.leeway import Leeway
    from opendrift.readers import reader_constant

    np.random.seed(args.seed)  # noqa: NPY002  (OpenDrift draws from the global generator)
    model = Leeway(loglevel=logging.ERROR)
    model.add_reader(reader_constant.Reader({
        "x_wind": args.wind[0], "y_wind": args.wind[1],
        "x_sea_water_velocity": args.current[0], "y_sea_water_velocity": args.current[1],
        "land_binary_mask": 0}))
    start = datetime.datetime(2026, 1, 1)
    model.seed_elements(lon=0.0, lat=0.0, number=args.elements, time=start,
                        object_type=OBJECT_TYPE[args.object])
    cpu = time.process_time()
    model.run(duration=datetime.timedelta(hours=args.hours), time_step=args.dt,
              time_step_output=datetime.timedelta(hours=args.hours))
    cpu = time.process_time() - cpu
    lon = model.result.lon.isel(time=-1).values
    lat = model.result.lat.isel(time=-1).values
    azimuth, _, distance = pyproj.Geod(ellps="WGS84").inv(
        np.zeros_like(lon), np.zeros_like(lat), lon, lat)
    az = np.radians(azimuth)
    print(json.dumps({"version": version("opendrift"), "cpu": cpu,
                      "east": (distance * np.sin(az)).tolist(),
                      "north": (distance * np.cos(az)).tolist()}))


def sarlink_side(args: argparse.Namespace, steps: int) -> tuple[np.ndarray, float]:
    """The displacements ``(K, 2)`` of sarlink's drift and its CPU seconds per target-step."""
    from sarlink.engine.target_motion.drift import STATE, drift_params, drift_targets, start

    tp = drift_params(args.object, tuple(args.wind), tuple(args.current))
    drift_targets(np.zeros((1, 2)), np.array([[1.0, 0.0, 0.0]]), 0.0, args.dt, 1, tp,
                  np.random.default_rng(0))  # compile or load
    rng = np.random.default_rng(args.seed)
    xy, state = np.zeros((args.elements, 2)), np.zeros((args.elements, STATE))
    for i in range(args.elements):
        start(xy[i], state[i], tp, rng)
    cpu = time.process_time()
    drift_targets(xy, state, 0.0, args.dt, steps, tp, rng)
    cpu = time.process_time() - cpu
    return xy, cpu / (args.elements * steps)


def spreads(d: np.ndarray, wind: tuple[float, float]) -> tuple[float, float]:
    """Standard deviations of the displacements along and across the wind."""
    w = math.hypot(*wind)
    ux, uy = wind[0] / w, wind[1] / w
    return float((d @ [ux, uy]).std(ddof=1)), float((d @ [uy, -ux]).std(ddof=1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--elements", type=int, default=5000)
    parser.add_argument("--hours", type=float, default=24.0)
    parser.add_argument("--dt", type=float, default=600.0, help="time step, s")
    parser.add_argument("--object", default="PIW-1", choices=sorted(OBJECT_TYPE))
    parser.add_argument("--wind", type=float, nargs=2, default=[8.0, 6.0],
                        help="east, north, m/s")
    parser.add_argument("--current", type=float, nargs=2, default=[0.2, -0.1],
                        help="east, north, m/s")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--opendrift-python", default=OPENDRIFT_PYTHON)
    parser.add_argument("--opendrift-side", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.opendrift_side:
        opendrift_side(args)
        return
    steps = round(args.hours * 3600 / args.dt)
    side = [a for a in sys.argv[1:] if not a.startswith("--opendrift-python")]
    run = subprocess.run([args.opendrift_python, __file__, "--opendrift-side", *side],
                         capture_output=True, text=True, check=True)
    od = json.loads(run.stdout.strip().splitlines()[-1])
    theirs = np.column_stack([od["east"], od["north"]])
    ours, our_cost = sarlink_side(args, steps)
    k = args.elements
    c_ours, c_theirs = ours.mean(axis=0), theirs.mean(axis=0)
    off = float(np.linalg.norm(c_ours - c_theirs) / np.linalg.norm(c_theirs))
    c_se = math.sqrt(float(ours.var(axis=0, ddof=1).sum() + theirs.var(axis=0, ddof=1).sum())
                     / k) / float(np.linalg.norm(c_theirs))
    s_ours, s_theirs = spreads(ours, args.wind), spreads(theirs, args.wind)
    their_cost = od["cpu"] / (k * steps)
    rows = [
        "| | sarlink `drift` | OpenDrift `Leeway` | sarlink / OpenDrift |",
        "|---|---|---|---|",
        f"| centroid east, north (km) | {c_ours[0] / 1e3:.3f}, {c_ours[1] / 1e3:.3f} | "
        f"{c_theirs[0] / 1e3:.3f}, {c_theirs[1] / 1e3:.3f} | off by {100 * off:.2f} % of "
        f"OpenDrift's distance (sampling error {100 * c_se:.2f} %) |",
        *(f"| spread {axis} the wind, std (km) | {s_ours[i] / 1e3:.3f} | {s_theirs[i] / 1e3:.3f} "
          f"| {s_ours[i] / s_theirs[i]:.3f} (sampling error {math.sqrt(1 / (k - 1)):.3f}) |"
          for i, axis in enumerate(("along", "across"))),
        f"| CPU per target-step (µs) | {1e6 * our_cost:.3f} | {1e6 * their_cost:.2f} | "
        f"{our_cost / their_cost:.4f} |",
    ]
    verdict = ("within" if off <= 0.05 and all(abs(a / b - 1) <= 0.10
                                                for a, b in zip(s_ours, s_theirs, strict=True))
               else "NOT within")
    body = f"""
- forcing: wind ({args.wind[0]:g}, {args.wind[1]:g}) m/s and current ({args.current[0]:g}, \
{args.current[1]:g}) m/s (east, north), constant
- {k} elements of {args.object} on each side, {args.hours:g} h in steps of {args.dt:g} s, seed \
{args.seed} on each side (different generators: the two samples are independent)
- OpenDrift {od['version']}, run by this script as a subprocess in its own venv \
(`{args.opendrift_python}`: it cannot be installed beside sarlink's lock), `Leeway` with \
`reader_constant` and no land; displacements geodesic, from a seed point on the equator
- sarlink: the `drift` hooks alone (`drift_targets`, no drones)
- cost: CPU time of the stepping, OpenDrift's `run` (its readers, its bookkeeping, its output) \
against sarlink's compiled hooks

{chr(10).join(rows)}

The centroid and the spreads are {verdict} the issue's bounds (centroid within 5 %, spread
within 10 %). The sampling error of a spread ratio is about `sqrt(1 / (K - 1))` for two
independent normal samples of K elements; the centroid's is the standard error of the
difference of the two means, over OpenDrift's distance.
"""
    results_file.write(RESULTS, "sarlink's drift against OpenDrift's Leeway", body)


if __name__ == "__main__":
    main()

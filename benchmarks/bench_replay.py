"""Replay pages: file size and smoothness of sarlink's canvas page against Plotly's frames.

A full 4000 s ConB run of 22 drones at r_c = 500 m is drawn both ways, with what the replay
shows: drones coloured by mode, the links with the BS's component apart, 60 s trails. Plotly
gets one animation frame per step (its way to animate) with its slider and play button, and
its library inlined so that the file works offline like sarlink's. Both pages are opened from
disk in headless Chromium (software rendering) and stepped through frames as fast as the
browser shows them (one step per animation frame). Also measured: the comparison pages.

    pip install -e ".[bench]"   # Plotly, only for this comparison
    python benchmarks/bench_replay.py --out benchmarks/results/replay.md
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import results_file
from browser import chromium, open_page
from sarlink import Mission, RunResult, replay, simulate
from sarlink.engine.codes import Mode
from sarlink.playback import compare

PLANNERS = ["covb", "conb", "concov", "mtsp", "mtsp-conb"]
TRAIL = 60
COLOURS = ["#0072B2", "#E69F00", "#8c8c8c", "#CC79A7", "#009E73"]

STEP_SCRIPT = """
const [step, kind, done] = arguments;
const gd = document.querySelector('.plotly-graph-div');
const frame = () => new Promise(resolve => requestAnimationFrame(resolve));
(async () => {
  await frame();
  const t0 = performance.now();
  if (kind === 'plotly') {
    await Plotly.animate(gd, [String(step)], {mode: 'immediate',
      frame: {duration: 0, redraw: true}, transition: {duration: 0}});
  } else {
    sarlinkReplay.seek(step);
  }
  const work = performance.now() - t0;
  await frame();
  done([performance.now() - t0, work]);
})();
"""
"""One step, timed from an animation frame to the next one after the step's work."""


def _segments(points: np.ndarray, pairs: list[tuple[int, int]]) -> tuple[list, list]:
    xs: list[float | None] = []
    ys: list[float | None] = []
    for i, j in pairs:
        xs += [points[i, 0], points[j, 0], None]
        ys += [points[i, 1], points[j, 1], None]
    return xs, ys


def plotly_page(result: RunResult, mission: Mission, path: Path, every: int) -> None:
    """The run as a Plotly figure with a frame (and a slider step) every ``every`` steps."""
    import plotly.io as pio

    traj = result.trajectory
    assert traj is not None
    n = traj.positions.shape[1]
    bs = np.array(mission.area.bs_xy)
    frames = []
    for k in range(0, len(traj.t), every):
        nodes = np.vstack([traj.positions[k], bs, result.target])
        route = np.append(traj.bs_route[k], True)
        i, j = np.nonzero(np.triu(traj.links[k][: n + 1, : n + 1], 1))
        pairs = list(zip(i.tolist(), j.tolist(), strict=True))
        green = _segments(nodes, [(a, b) for a, b in pairs if route[a] and route[b]])
        grey = _segments(nodes, [(a, b) for a, b in pairs if not (route[a] and route[b])])
        lo = max(0, k - TRAIL)
        tx: list[float | None] = []
        ty: list[float | None] = []
        for d in range(n):
            tx += [*traj.positions[lo:k + 1, d, 0].round(1).tolist(), None]
            ty += [*traj.positions[lo:k + 1, d, 1].round(1).tolist(), None]
        frames.append({"name": str(k), "data": [
            {"x": tx, "y": ty},
            {"x": grey[0], "y": grey[1]},
            {"x": green[0], "y": green[1]},
            {"x": traj.positions[k, :, 0].round(1).tolist(),
             "y": traj.positions[k, :, 1].round(1).tolist(),
             "marker": {"color": [COLOURS[m] for m in traj.mode[k]],
                        "line": {"color": ["#d62728" if w else "#fff" for w in traj.knows[k]],
                                 "width": 2}}},
        ]})
    line = {"type": "scatter", "mode": "lines", "hoverinfo": "skip"}
    data = [
        {**line, "line": {"color": "rgba(0,114,178,0.5)", "width": 1.5}, **frames[0]["data"][0]},
        {**line, "line": {"color": "#b5b5b5", "width": 1}, **frames[0]["data"][1]},
        {**line, "line": {"color": "#2ca02c", "width": 2.5}, **frames[0]["data"][2]},
        {"type": "scatter", "mode": "markers", "marker": {"size": 10}, **frames[0]["data"][3]},
    ]
    size = mission.area.size
    rc = mission.channel.rc
    layout = {
        "width": 800, "height": 850, "showlegend": False,
        "xaxis": {"range": [0, size]}, "yaxis": {"range": [0, size], "scaleanchor": "x"},
        "shapes": [{"type": "circle", "x0": bs[0] - rc, "x1": bs[0] + rc, "y0": bs[1] - rc,
                    "y1": bs[1] + rc, "line": {"dash": "dash"}}],
        "updatemenus": [{"type": "buttons", "buttons": [
            {"label": "Play", "method": "animate",
             "args": [None, {"frame": {"duration": 16, "redraw": True}}]}]}],
        "sliders": [{"steps": [{"label": f["name"], "method": "animate",
                                "args": [[f["name"]], {"mode": "immediate",
                                                       "frame": {"duration": 0, "redraw": True}}]}
                               for f in frames]}],
    }
    fig = {"data": data, "layout": layout, "frames": frames}
    path.write_text(pio.to_html(fig, include_plotlyjs=True, full_html=True, validate=False,
                                auto_play=False), encoding="utf-8")


def measure(driver, path: Path, kind: str, steps: list[int]) -> dict[str, float]:
    start = time.perf_counter()
    if kind == "plotly":
        driver.get(path.resolve().as_uri())
    else:
        open_page(driver, path)
    load = time.perf_counter() - start
    print(f"{path.name}: loaded in {load:.1f} s, stepping", file=sys.stderr, flush=True)
    timed = np.array([driver.execute_async_script(STEP_SCRIPT, k, kind) for k in steps])
    return {"MB": path.stat().st_size / 1e6, "load s": load,
            "ms per shown frame": float(np.median(timed[:, 0])),
            "ms of work per frame": float(np.median(timed[:, 1]))}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=50, help="frames stepped per page")
    parser.add_argument("--out", type=Path, default=None, help="write the Markdown table here")
    args = parser.parse_args()
    assert len(Mode) <= len(COLOURS)
    mission = Mission.build(planner="conb", drones=22, rc=500.0)
    result = simulate(mission, seed=1, run=1, trajectory=True)
    stride = 10 * ((len(result.trajectory.t) - 1) // (10 * args.steps))
    steps = [k * stride for k in range(1, args.steps + 1)]
    rows = []
    with tempfile.TemporaryDirectory() as folder, chromium() as driver:
        here = Path(folder)
        canvas = replay(result, mission).write(here / "canvas.html")
        rows.append(("sarlink canvas page, every step",
                     measure(driver, canvas, "canvas", steps)))
        for every in (1, 10):
            plotly = here / f"plotly{every}.html"
            plotly_page(result, mission, plotly, every)
            name = "every step" if every == 1 else f"every {every}th step"
            rows.append((f"Plotly frames, {name}", measure(driver, plotly, "plotly", steps)))
        sizes = []
        for drones in (10, 22):
            page = compare(Mission.build(drones=drones, rc=500.0), PLANNERS, seed=1, run=0)
            path = page.write(here / f"compare{drones}.html")
            sizes.append((drones, measure(driver, path, "canvas", steps)))
    lines = [
        "Headless Chromium (software rendering).",
        "",
        f"One full run: ConB, N = 22, r_c = 500 m, seed 1, run 1, {len(result.trajectory.t)} "
        f"steps. Each page is stepped through {args.steps} frames {stride} steps apart, each "
        "step from one animation frame of the browser to the next after its work (at best "
        "16.7 ms at 60 frames per second): *ms per shown frame* is that wall time, *ms of "
        "work* the script's part of it (medians). Load: opening the file until the first "
        "frame is drawn.",
        "",
        "| page | file (MB) | load (s) | ms per shown frame | ms of work per frame |",
        "|---|---|---|---|---|",
    ]
    for name, m in rows:
        lines.append(f"| {name} | {m['MB']:.2f} | {m['load s']:.1f} | "
                     f"{m['ms per shown frame']:.1f} | {m['ms of work per frame']:.1f} |")
    lines += ["", f"Side by side ({', '.join(PLANNERS)}; seed 1, run 0, r_c = 500 m):", "",
              "| drones per panel | file (MB) | load (s) | ms per shown frame |",
              "|---|---|---|---|"]
    for drones, m in sizes:
        lines.append(f"| {drones} | {m['MB']:.2f} | {m['load s']:.1f} | "
                     f"{m['ms per shown frame']:.1f} |")
    text = "\n".join(lines) + "\n"
    print(text)
    if args.out is not None:
        results_file.write(args.out, "Replay benchmark", text)


if __name__ == "__main__":
    main()

"""Radio models written outside sarlink, with effects a test can predict.

``CUT`` is the disc with every link to the BS cut: nobody ever reaches the BS. ``HALF`` and
``FULL`` are the disc whose nominal range (what ConB predicts with) is its first parameter
times r_c: ``FULL`` is the disc itself. ``IMPOSTOR`` is ``CUT`` under the built-in name
``disc``. All four share their hooks, the cut being their second parameter, so that a rule
flies one compiled kernel under any of them.
"""

from __future__ import annotations

from functools import partial

import numpy as np
from numba import njit

from sarlink import Mission, Params, RadioModel


@njit
def disc(p: Params, rp: np.ndarray, m: int, mp: int) -> np.ndarray:
    """The disc's squared ranges, with every link to the BS (node ``m - 2``) cut if
    ``rp[1]`` is set: no squared distance is at most -1."""
    thr2 = np.zeros((m, mp))
    thr2[:, :m] = p.rc * p.rc
    if rp[1] != 0.0:
        bs = m - 2
        thr2[bs, :] = -1.0
        thr2[:, bs] = -1.0
    return thr2


@njit
def steady(thr2: np.ndarray, p: Params, rp: np.ndarray, k: int,
           rng: np.random.Generator) -> None:
    pass


@njit
def scaled(p: Params, rp: np.ndarray) -> float:
    return p.rc * rp[0]


def factor(value: float, cut: bool, mission: Mission) -> list[float]:
    """The radio's parameters: the nominal range's factor and whether the BS's links are cut
    (a module-level function, so that the model can be sent to worker processes)."""
    return [value, 1.0 if cut else 0.0]


CUT = RadioModel("cut-bs", disc, steady, scaled, static=True, params=partial(factor, 1.0, True))
HALF = RadioModel("half-nominal", disc, steady, scaled, static=True,
                  params=partial(factor, 0.5, False))
FULL = RadioModel("full-nominal", disc, steady, scaled, static=True,
                  params=partial(factor, 1.0, False))
IMPOSTOR = RadioModel("disc", disc, steady, scaled, static=True,
                      params=partial(factor, 1.0, True))

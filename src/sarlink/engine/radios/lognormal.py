"""The paper's radio: log-normal shadowing (Eq. 13), and the disc (Eq. 4) as its case
``sigma = 0``.

A link exists where the path loss plus a fade ``S`` stays within the budget of the range r_c,
``10 n log10(d / r_c) + S <= 0``, ``S = sigma * z`` with ``z`` standard normal per link
(``readings.shadow_calibration = mean-area`` shifts every ``S`` so that the mean link area is
the disc's: :func:`fade_bias`),
drawn independently of r_c, so the draws of a run are the same at every range. How ``z``
changes is ``readings.shadowing``: drawn anew each coherence time (``period``;
``channel.coherence``, default t_s), once per run (``run``), or every step as a Gauss-Markov
process in the distance flown (``correlated``, Gudmundson's exponential correlation
``exp(-x / d_c)``, ``channel.decorrelation``): each flying end of a link moves ``V dt`` per
step, so ``z`` keeps ``rho = exp(-k V dt / d_c)`` of itself, ``k`` the link's drone ends (the
BS-target link never changes); the state ``z`` of pair ``(a, b)`` lives in row ``m + a`` of
the threshold array, past the rows the links read. With ``sigma = 0``
nothing is drawn and every threshold is ``r_c²`` for the whole run: the disc, whose links
never change (a settled team may then jump to the horizon). The two cases are one model, so
that they compile into one kernel. Planners predict with the shadow-free range r_c.

Both models are registered here, by :func:`~sarlink.engine.radios.register_radio` as a plug-in
model is; they alone declare ``range_free`` (the range scan redraws exactly these fades).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from sarlink.engine.hooks import RadioModel
from sarlink.engine.params import SHADOW_CORRELATED, SHADOW_RUN, Params
from sarlink.engine.radios.registry import register_radio

_LN10 = math.log(10.0)


def fade_bias(sigma: float, pathloss_exponent: float, calibration: str) -> float:
    """What to add to every fade's exponent ``-S ln10 / 5n`` for ``readings.shadow_calibration``.

    ``median``: nothing, r_c is the range the path loss alone reaches, so half of the fades
    reach beyond it. ``mean-area``: ``-(sigma ln10 / 5n)² / 2``, as the squared range's
    factor ``exp(-S ln10 / 5n)`` is log-normal with that half-variance: the mean link area is
    then ``pi r_c²``, the disc's (Section 2: "a multihop link to the BS *on average*").
    """
    if calibration == "median":
        return 0.0
    spread = sigma * _LN10 / (5.0 * pathloss_exponent)
    return -0.5 * spread * spread


@njit(cache=True, error_model="numpy")
def disc_ranges(rc: float, m: int, mp: int) -> np.ndarray:
    """Squared link ranges ``rc²`` among the ``m`` nodes; none to the padding."""
    thr2 = np.zeros((m, mp))
    thr2[:, :m] = rc * rc
    return thr2


@njit(cache=True, error_model="numpy")
def draw_shadowing(thr2: np.ndarray, p: Params, rng: np.random.Generator) -> None:
    """Redraw the per-link squared range: ``10 n log10(d/rc) + S <= 0  <=>  d² <= rc² 10^(-S/5n)``.

    With ``S = 0`` the factor is exactly 1, so ``sigma = 0`` is the disc model bit for bit.
    """
    m = thr2.shape[0]
    rc2 = p.rc * p.rc
    scale = -_LN10 / (5.0 * p.pathloss_exponent)
    for a in range(m):
        for b in range(a + 1, m):
            s = p.sigma * rng.standard_normal()
            v = rc2 * math.exp(scale * s + p.fade_bias)
            thr2[a, b] = v
            thr2[b, a] = v


@njit(cache=True, inline="always", error_model="numpy")
def init(p: Params, rp: np.ndarray, m: int, mp: int) -> np.ndarray:
    """The shadow-free ranges ``r_c²``; the fades are drawn from step 0 (:func:`update`).
    Correlated fades keep their normal state in ``m`` more rows."""
    thr2 = disc_ranges(p.rc, m, mp)
    if p.sigma > 0.0 and p.shadowing == SHADOW_CORRELATED:
        state = np.zeros((2 * m, mp))
        state[:m] = thr2
        return state
    return thr2


@njit(cache=True, error_model="numpy")
def drift_shadowing(thr2: np.ndarray, p: Params, rng: np.random.Generator, first: bool) -> None:
    """One step of the correlated fades: ``z <- rho z + sqrt(1 - rho²) e`` (``z = e`` at the
    first step), ``rho`` by the number of drone ends of the link, then the ranges."""
    m = thr2.shape[0] // 2
    n = m - 2
    rc2 = p.rc * p.rc
    scale = -_LN10 / (5.0 * p.pathloss_exponent)
    moved = p.speed * p.dt / p.decorrelation
    for a in range(m):
        for b in range(a + 1, m):
            ends = (1 if a < n else 0) + (1 if b < n else 0)
            e = rng.standard_normal()
            if first:
                z = e
            else:
                rho = math.exp(-ends * moved)
                z = rho * thr2[m + a, b] + math.sqrt(1.0 - rho * rho) * e
            thr2[m + a, b] = z
            v = rc2 * math.exp(scale * p.sigma * z + p.fade_bias)
            thr2[a, b] = v
            thr2[b, a] = v


@njit(cache=True, inline="always", error_model="numpy")
def update(thr2: np.ndarray, p: Params, rp: np.ndarray, k: int, rng: np.random.Generator) -> None:
    """New fades by ``readings.shadowing`` (none with ``sigma = 0``)."""
    if p.sigma == 0.0:
        return
    if p.shadowing == SHADOW_CORRELATED:
        drift_shadowing(thr2, p, rng, k == 0)
    elif k == 0 or (p.shadowing != SHADOW_RUN and k % p.coherence_steps == 0):
        draw_shadowing(thr2, p, rng)


@njit(cache=True, inline="always", error_model="numpy")
def nominal(p: Params, rp: np.ndarray) -> float:
    """The shadow-free range: a drone cannot foresee fading."""
    return p.rc


@njit(cache=True, inline="always", error_model="numpy")
def static(p: Params, rp: np.ndarray) -> bool:
    """Whether the links never change after step 0: the disc, ``sigma = 0``, or one fade per
    link for the run."""
    return p.sigma == 0.0 or p.shadowing == SHADOW_RUN


DISC = register_radio(RadioModel("disc", init, update, nominal, static=static, range_free=True))
"""Eq. 4: linked within r_c (the model above with ``sigma = 0``: one kernel for both)."""
SHADOWING = register_radio(RadioModel("shadowing", init, update, nominal, static=static,
                                      range_free=True))
"""Eq. 13: log-normal fades per link, changing as ``readings.shadowing`` says (every
coherence time, once per run, or correlated over the distance flown)."""

"""Mission flags shared by the commands that fly one mission (``simulate``, ``replay``)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from sarlink.config import READINGS

Drones = Annotated[int | None, typer.Option(help="number of drones N_m")]
Rc = Annotated[float | None, typer.Option(help="communication range r_c, m")]
Seed = Annotated[int, typer.Option(help="experiment seed", min=0)]
Run = Annotated[int, typer.Option(help="run index within the experiment", min=0)]
Alpha = Annotated[float | None, typer.Option(help="ConCov coverage weight")]
Nr = Annotated[int | None, typer.Option(help="mTSP-ConB: drones flying the plan")]
Td = Annotated[float | None, typer.Option(help="target duration t_d = horizon, s")]
R = Annotated[float | None, typer.Option(help="sensing range r, m")]
PMiss = Annotated[float | None, typer.Option(help="miss probability per look")]
Look = Annotated[str | None, typer.Option(help="per-pass or per-period")]
Sigma = Annotated[float | None, typer.Option(help="shadowing sigma, dB")]
PathlossExponent = Annotated[float | None, typer.Option(help="path-loss exponent n")]
Stop = Annotated[str | None, typer.Option(help="end the run at: horizon, detected, notified")]
OnDetect = Annotated[str | None, typer.Option(
    help="after learning where the target is: continue (the paper) or report (fly to the BS)")]
Reading = Annotated[str | None, typer.Option(
    help=f"a named reading of what the paper leaves open ({', '.join(READINGS)}; "
         "docs/model.md); it overrides the config's [readings], flags override both")]
Config = Annotated[Path | None, typer.Option(help="mission TOML; flags override it")]

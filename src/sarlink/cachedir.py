"""Where sarlink keeps what it computes once and reuses: mTSP plans and compiled kernels."""

from __future__ import annotations

import os
from pathlib import Path


def cache_root() -> Path:
    """``$SARLINK_CACHE_DIR`` if the variable is set, else ``$XDG_CACHE_HOME/sarlink``
    (``~/.cache/sarlink`` by default)."""
    root = os.environ.get("SARLINK_CACHE_DIR")
    if root:
        return Path(root)
    xdg = os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache"
    return Path(xdg) / "sarlink"

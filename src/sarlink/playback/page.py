"""The replay page: one HTML file with its script, style and data inlined, for offline use.

The template, script and style are plain files beside this module (``page.html``,
``replay.js``, ``replay.css``), so that each can be read and linted as what it is.
"""

from __future__ import annotations

import json
from html import escape
from importlib.metadata import version
from importlib.resources import files
from string import Template
from typing import Any

__all__ = ["render"]


def _asset(name: str) -> str:
    return files("sarlink.playback").joinpath(name).read_text(encoding="utf-8")


def _script_safe(data: Any) -> str:
    """JSON that cannot end the ``<script>`` element holding it."""
    return json.dumps(data, separators=(",", ":"), allow_nan=False).replace("<", "\\u003c")


def render(title: str, document: dict[str, Any]) -> str:
    """The page showing ``document`` (``{"modes": ..., "panels": [...]}``)."""
    return Template(_asset("page.html")).substitute(
        title=escape(title), version=version("sarlink"), style=_asset("replay.css"),
        script=_asset("replay.js"), data=_script_safe({"title": title, **document}),
    )

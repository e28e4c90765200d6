"""The validated base of every configuration model, and the one error they raise."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, Self

from pydantic import BaseModel, ConfigDict, ValidationError

__all__ = ["Checked", "ConfigError"]


class ConfigError(ValueError):
    """A configuration value is invalid; the message names the field and the allowed range."""


class Checked(BaseModel):
    """A frozen, strict model whose constructors from data raise :class:`ConfigError`."""

    model_config = ConfigDict(
        frozen=True, extra="forbid", validate_default=True, allow_inf_nan=False
    )

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> Self:
        """Build from nested ``{field: value}`` data; errors name the field."""
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            raise ConfigError(_describe(exc)) from None

    @classmethod
    def from_toml(cls, path: str | Path) -> Self:
        """Build from a TOML file whose tables mirror the model's fields."""
        with open(path, "rb") as fh:
            try:
                data = tomllib.load(fh)
            except tomllib.TOMLDecodeError as exc:
                raise ConfigError(f"{path}: {exc}") from None
        return cls.from_dict(data)


def _describe(exc: ValidationError) -> str:
    """One readable line per error: ``team.drones: Input should be greater than or equal to 1``."""
    lines = []
    for err in exc.errors():
        loc = ".".join(str(p) for p in err["loc"])
        msg = err["msg"].removeprefix("Value error, ")
        got = err.get("input")
        suffix = "" if isinstance(got, dict) or got is None else f" (got {got!r})"
        lines.append(f"{loc}: {msg}{suffix}" if loc else f"{msg}")
    return "; ".join(lines)

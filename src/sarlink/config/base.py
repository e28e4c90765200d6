"""The validated base of every configuration model, and the one error they raise."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any, Self

from pydantic import BaseModel, ConfigDict, ValidationError
from pydantic_core import ErrorDetails

__all__ = ["Checked", "ConfigError", "read_toml"]


class ConfigError(ValueError):
    """A configuration value is invalid; the message names the field and the allowed range."""


class Checked(BaseModel):
    """A frozen, strict model whose constructors from data raise :class:`ConfigError`."""

    model_config = ConfigDict(
        frozen=True, extra="forbid", validate_default=True, allow_inf_nan=False
    )

    @classmethod
    def from_dict(cls, data: dict[str, Any], folder: Path | None = None) -> Self:
        """Build from nested ``{field: value}`` data; errors name the field. Files the data
        names (a mission's area and prior) are read relative to ``folder``."""
        try:
            return cls.model_validate(data, context={"folder": folder})
        except ValidationError as exc:
            raise ConfigError(_describe(cls, exc)) from None

    @classmethod
    def from_toml(cls, path: str | Path) -> Self:
        """Build from a TOML file whose tables mirror the model's fields; errors name the file."""
        return cls.from_file_data(path, read_toml(path))

    @classmethod
    def from_file_data(cls, path: str | Path, data: dict[str, Any]) -> Self:
        """Build from the data of the file ``path``; errors start with the file's name."""
        try:
            return cls.from_dict(data, Path(path).parent)
        except ConfigError as exc:
            raise ConfigError(f"{path}: {exc}") from None


def read_toml(path: str | Path) -> dict[str, Any]:
    """The tables of a TOML file, or a :class:`ConfigError` saying why there are none."""
    try:
        with open(path, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise ConfigError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise ConfigError(f"{path} is a folder; a TOML file is expected") from None
    except tomllib.TOMLDecodeError as exc:
        raise ConfigError(f"{path}: not valid TOML: {exc}") from None
    except UnicodeDecodeError:
        raise ConfigError(f"{path}: not a TOML file (TOML is UTF-8 text)") from None
    except OSError as exc:
        raise ConfigError(f"{path}: cannot be read ({exc.strerror})") from None


def _describe(model: type[BaseModel], exc: ValidationError) -> str:
    """One readable clause per error: ``team.drones: Input should be greater than or equal to 1``.

    A missing field says what it is; an unknown one lists the fields allowed where it stands.
    """
    lines = []
    for err in exc.errors():
        loc = ".".join(str(p) for p in err["loc"])
        msg = err["msg"].removeprefix("Value error, ")
        got = err.get("input")
        suffix = "" if isinstance(got, dict) or got is None else f" (got {got!r})"
        hint = _hint(model, err)
        lines.append(f"{loc}: {msg}{hint}{suffix}" if loc else f"{msg}")
    return "; ".join(lines)


def _hint(model: type[BaseModel], err: ErrorDetails) -> str:
    """What a missing field means, or which fields are allowed beside an unknown one."""
    if err["type"] not in ("missing", "extra_forbidden"):
        return ""
    owner = model
    for part in err["loc"][:-1]:
        field = owner.model_fields.get(str(part))
        inner = field.annotation if field is not None else None
        if not (isinstance(inner, type) and issubclass(inner, BaseModel)):
            return ""
        owner = inner
    fields = owner.model_fields
    if err["type"] == "missing":
        description = fields[str(err["loc"][-1])].description
        return f" ({description})" if description else ""
    return f"; allowed here: {', '.join(fields)}"

"""How the command line fails: one line on stderr naming what was wrong, never a traceback.

Usage errors (a bad option, value, file or folder) exit with status 2, other failures with 1.
:func:`user_errors` reports the errors a command expects; :class:`Guarded`, the command group of
the ``sarlink`` app, turns Typer's usage errors into one line too, prints warnings as one line,
and catches anything unexpected, with ``--debug`` (or ``SARLINK_DEBUG=1``) to see the traceback.
"""

from __future__ import annotations

import errno
import os
import sys
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any, NoReturn

import typer
from rich.console import Console
from rich.markup import escape
from typer.core import TyperGroup

from sarlink.config import ConfigError

__all__ = ["USAGE", "Guarded", "describe_os_error", "err_console", "fail", "user_errors"]

USAGE = 2
"""Exit status of a usage error: the user can fix the command line or an input file."""
FAILURE = 1
"""Exit status of any other failure (a full disk, a bug)."""

err_console = Console(stderr=True, soft_wrap=True)
"""Errors stay one line each, also when stderr is a pipe or a log (rich would wrap at 80)."""

_Context = Any
"""Click's context, which Typer vendors under a private name."""

_OS_REASONS = {
    errno.ENOENT: ("no such file or folder", USAGE),
    errno.EISDIR: ("is a folder, where a file is expected", USAGE),
    errno.ENOTDIR: ("a part of the path is a file, where a folder is expected", USAGE),
    errno.EEXIST: ("exists already, and is not what is expected there", USAGE),
    errno.EACCES: ("permission denied", USAGE),
    errno.EPERM: ("operation not permitted", USAGE),
    errno.EROFS: ("read-only file system", USAGE),
    errno.ENAMETOOLONG: ("the name is too long", USAGE),
    errno.ENOSPC: ("no space left on the device", FAILURE),
    errno.EDQUOT: ("disk quota exceeded", FAILURE),
}


def fail(message: str, status: int = USAGE) -> NoReturn:
    """Print ``error: message`` on stderr and exit with ``status``."""
    err_console.print(f"[bold red]error:[/] {escape(message)}", highlight=False)
    raise typer.Exit(status)


_ERRNO_OF: dict[type[OSError], int] = {
    FileNotFoundError: errno.ENOENT, IsADirectoryError: errno.EISDIR,
    NotADirectoryError: errno.ENOTDIR, FileExistsError: errno.EEXIST,
    PermissionError: errno.EACCES,
}
"""The error number of an OSError raised by sarlink itself, with a message instead."""


def describe_os_error(exc: OSError) -> tuple[str, int]:
    """One line for a failed file operation, naming the path, and its exit status."""
    code = exc.errno if exc.errno is not None else _ERRNO_OF.get(type(exc), 0)
    reason, status = _OS_REASONS.get(code, (exc.strerror or str(exc), FAILURE))
    if exc.errno is None:  # raised by sarlink, with a message of its own
        text = str(exc)
    elif exc.filename is None:
        text = reason
    else:
        also = f" -> {exc.filename2}" if exc.filename2 is not None else ""
        text = f"{exc.filename}{also}: {reason}"
    if status == FAILURE:
        text += "; what was finished is kept: free some space and run the same command again"
    return text, status


@contextmanager
def user_errors() -> Iterator[None]:
    """Report configuration and file mistakes as one line and exit, with no traceback."""
    try:
        yield
    except ConfigError as exc:
        fail(str(exc))
    except OSError as exc:
        fail(*describe_os_error(exc))


def _show_warning(message: Warning | str, category: type[Warning], filename: str, lineno: int,
                  file: Any = None, line: str | None = None) -> None:
    err_console.print(f"[yellow]warning:[/] {escape(str(message))}", highlight=False)


def _debug(ctx: _Context) -> bool:
    return bool(ctx.params.get("debug")) or os.environ.get("SARLINK_DEBUG", "") not in ("", "0")


class Guarded(TyperGroup):
    """The ``sarlink`` group: every failure of a command is one line on stderr."""

    def parse_args(self, ctx: _Context, args: list[str]) -> list[str]:
        if not args:  # no_args_is_help: Typer prints the help
            return super().parse_args(ctx, args)
        try:
            return super().parse_args(ctx, args)
        except typer.TyperException as exc:
            _usage(exc)

    def invoke(self, ctx: _Context) -> Any:
        with warnings.catch_warnings():
            warnings.showwarning = _show_warning
            try:
                return super().invoke(ctx)
            except (typer.Exit, typer.Abort, KeyboardInterrupt):
                raise
            except BrokenPipeError:  # the reader went away (`sarlink ... | head`)
                _reader_gone()
            except typer.TyperException as exc:  # a subcommand's options did not parse
                if getattr(exc, "exit_code", USAGE) != USAGE or not hasattr(exc, "ctx"):
                    raise
                _usage(exc)
            except Exception as exc:
                if _debug(ctx):
                    raise
                fail(f"unexpected {type(exc).__name__}: {exc}. This is a bug in sarlink or an "
                     "input it does not check yet; run the command again with --debug "
                     "(sarlink --debug ...) for the traceback, and report it", FAILURE)


def _reader_gone() -> NoReturn:
    """Stop quietly when stdout's reader has closed the pipe, as Python's documentation
    advises (Note on SIGPIPE): the rest of the output goes to ``os.devnull``, so that the
    interpreter's last flush does not fail again."""
    os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    raise typer.Exit(FAILURE)


def _usage(exc: typer.TyperException) -> NoReturn:
    """Typer's usage error as one line, with where to find the command's options."""
    message = exc.format_message() if hasattr(exc, "format_message") else str(exc)
    ctx = getattr(exc, "ctx", None)
    command = ctx.command_path if ctx is not None else "sarlink"
    fail(f"{' '.join(message.split())} (see `{command} --help`)")

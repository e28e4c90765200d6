"""A digest of the kernel's helper modules, recorded in the kernel module to guard Numba's cache.

Numba keys a cached function on its own file only: after an edit to a helper in another file,
a cached kernel would run the old helper's machine code. The kernel module records the digest
of every engine module it imports, directly or not
(:data:`sarlink.engine.kernel.SOURCE_DIGEST`); a test fails while it is out of date, and
recording it edits the kernel's file, which makes Numba recompile.

``python -m sarlink.engine.fingerprint`` prints the digest, ``--write`` records it.
"""

from __future__ import annotations

import ast
import hashlib
import re
import sys
from pathlib import Path

ENGINE = Path(__file__).resolve().parent
KERNEL = ENGINE / "kernel.py"
_PACKAGE = "sarlink.engine"
_RECORD = re.compile(r'^SOURCE_DIGEST = "[0-9a-f]*"$', re.MULTILINE)


def _engine_imports(path: Path) -> set[Path]:
    """The engine modules (files beside ``path``) that ``path`` imports."""
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if not isinstance(node, ast.ImportFrom) or node.module is None:
            continue
        module = node.module
        if module == _PACKAGE:
            found |= {path.parent / f"{alias.name}.py" for alias in node.names}
        elif module.startswith(_PACKAGE + "."):
            found.add(path.parent / f"{module.removeprefix(_PACKAGE + '.')}.py")
    return {p for p in found if p.exists()}


def helper_modules(kernel: Path = KERNEL) -> list[Path]:
    """Every engine module the kernel depends on, but the kernel's own, in name order."""
    seen: set[Path] = set()
    todo = [kernel]
    while todo:
        for module in _engine_imports(todo.pop()) - seen:
            seen.add(module)
            todo.append(module)
    return sorted(seen - {kernel})


def source_digest(kernel: Path = KERNEL) -> str:
    """SHA-256 (16 hex digits) of the kernel's helper modules, by name and content."""
    digest = hashlib.sha256()
    for path in helper_modules(kernel):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def write() -> None:
    """Record the current digest in the kernel module."""
    text = KERNEL.read_text()
    if not _RECORD.search(text):
        raise RuntimeError(f"{KERNEL} has no SOURCE_DIGEST line to update")
    KERNEL.write_text(_RECORD.sub(f'SOURCE_DIGEST = "{source_digest()}"', text, count=1))


if __name__ == "__main__":
    if sys.argv[1:] == ["--write"]:
        write()
    print(source_digest())

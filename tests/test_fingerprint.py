"""Numba's cache guard: the kernel records the digest of the helper modules it compiles in."""

from __future__ import annotations

import shutil
from pathlib import Path

from sarlink.engine import kernel
from sarlink.engine.fingerprint import ENGINE, helper_modules, source_digest


def test_the_kernel_records_the_digest_of_its_helpers() -> None:
    """Fails after an edit to a helper module until the digest is recorded again, which edits
    the kernel's file and so makes Numba recompile instead of running stale machine code."""
    assert kernel.SOURCE_DIGEST == source_digest(), (
        "an engine module changed: run `python -m sarlink.engine.fingerprint --write`")


def test_every_module_the_kernel_compiles_in_is_covered() -> None:
    names = {p.stem for p in helper_modules()}
    assert {"graph", "radio", "rules", "motion", "records", "sensing", "params",
            "geometry", "codes"} <= names
    assert "kernel" not in names and "run" not in names  # the wrapper is not compiled in


def test_a_one_character_edit_to_any_helper_changes_the_digest(tmp_path: Path) -> None:
    copy = tmp_path / "engine"
    shutil.copytree(ENGINE, copy, ignore=shutil.ignore_patterns("__pycache__"))
    before = source_digest(copy / "kernel.py")
    assert before == source_digest()
    for module in helper_modules(copy / "kernel.py"):
        text = module.read_text()
        module.write_text(text + " ")
        assert source_digest(copy / "kernel.py") != before, module.name
        module.write_text(text)
    assert source_digest(copy / "kernel.py") == before

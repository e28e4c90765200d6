"""The README and the guide pages describe what is; measurements and history live elsewhere.

A guide page (README.md, docs/*.md) that carries an ISO date, a commit hash or a work-log
reference ("session 17", "issue 22", "#22") is a lab notebook in the wrong place: measured
numbers belong in the results file their benchmark writes (benchmarks/results/*.md), history
in CHANGELOG.md. Generated reports (docs/results/**) and the changelog are not guide pages.
The README is a front door: its first runnable example comes within its first 40 lines.
"""

from __future__ import annotations

import ast
import re
import tomllib
from pathlib import Path

import pytest
import yaml

ROOT = Path(__file__).resolve().parent.parent
GUIDE_PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
"""README.md and the top-level pages of docs/ (not docs/results/, not docs/api/)."""

FIRST_EXAMPLE_BY_LINE = 40

ISO_DATE = re.compile(r"\b(?:19|20)\d\d-(?:0[1-9]|1[0-2])-(?:0[1-9]|[12]\d|3[01])\b")
COMMIT = re.compile(r"(?<![\w/])(?=[0-9a-f]*\d)(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}(?![\w/])")
"""7 to 40 lowercase hex digits with at least one digit and one letter: a git hash's shape
(not a folder of a path, such as a results folder's mission hash)."""
WORK_LOG = re.compile(r"\b(?:sessions?|issues?|stops?)\s+\d+|(?<![\w&#/])#\d{2,}\b",
                      re.IGNORECASE)
"""'session 17', 'issues 22-23', 'stop 38', '#22' (not an HTML entity or a URL's anchor)."""

CHANGE_TYPES = ("Added", "Changed", "Deprecated", "Removed", "Fixed", "Security")
RELEASE = re.compile(r"## \[(\d+)\.(\d+)\.(\d+)\] - (\d{4}-\d{2}-\d{2})")


def work_log_traces(text: str) -> list[str]:
    """Every ISO date, commit hash and work-log reference in ``text``, with its line."""
    found = []
    for number, line in enumerate(text.splitlines(), 1):
        for pattern in (ISO_DATE, COMMIT, WORK_LOG):
            found += [f"line {number}: {m.group(0)!r}" for m in pattern.finditer(line)]
    return found


@pytest.mark.parametrize("page", GUIDE_PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_guide_page_has_no_dates_commits_or_work_log(page: Path) -> None:
    traces = work_log_traces(page.read_text(encoding="utf-8"))
    assert not traces, (f"{page.relative_to(ROOT)} carries history or dated measurements "
                        f"(move them to benchmarks/results/ or CHANGELOG.md): {traces}")


@pytest.mark.parametrize(("text", "trace"), [
    ("measured 2026-11-27 on a quiet host", "2026-11-27"),
    ("on commit a23015c (the link passes)", "a23015c"),
    (f"against {'5c5ff3d1' * 5}", "5c5ff3d1" * 5),
    ("since session 12 the kernels", "session 12"),
    ("(issue 23)", "issue 23"),
    ("Sessions 11 to 17 built", "Sessions 11"),
    ("stop 38 landed", "stop 38"),
    ("as #22 asks", "#22"),
])
def test_work_log_traces_are_found(text: str, trace: str) -> None:
    assert [t.split(": ", 1)[1] for t in work_log_traces(text)] == [repr(trace)]


@pytest.mark.parametrize("text", [
    "colour #1f77b4, 4000 s, 1,050 tests", "the seed 2024 and 0.95", "decimal 1234567",
    "a fence (.plan)", "[the model](model.md#readings-what-the-paper-leaves-open-readings)",
    "&#8212; an entity", "the deadbeef word", "t_d = 2000 s in 12 steps",
    "points/3f2a9c0e1b7d4a65/runs-000000-000025.parquet",
])
def test_ordinary_text_is_not_a_work_log_trace(text: str) -> None:
    assert work_log_traces(text) == []


def _fenced_blocks(text: str) -> list[tuple[int, str, str]]:
    """Each fenced code block: the line its fence opens on (1-based), its language, its code."""
    blocks, lines, start = [], text.splitlines(), None
    for number, line in enumerate(lines, 1):
        if line.startswith("```") and start is None:
            start, language = number, line[3:].strip()
        elif line.startswith("```") and start is not None:
            blocks.append((start, language, "\n".join(lines[start:number - 1])))
            start = None
    return blocks


def test_readme_first_runnable_example_is_within_40_lines() -> None:
    python = [b for b in _fenced_blocks((ROOT / "README.md").read_text(encoding="utf-8"))
              if b[1] == "python"]
    assert python, "README.md has no Python example"
    line, _, code = python[0]
    assert line <= FIRST_EXAMPLE_BY_LINE, f"README's first Python example starts at line {line}"
    ast.parse(code)  # it is Python, not a sketch
    assert "import sarlink" in code


def test_readme_set_up_is_the_two_make_commands() -> None:
    shell = [b for b in _fenced_blocks((ROOT / "README.md").read_text(encoding="utf-8"))
             if b[1] == "sh"]
    commands = [line.split("#")[0].strip() for line in shell[0][2].splitlines()]
    assert commands == ["make demo", "make test"]


def _pyproject_version() -> str:
    with (ROOT / "pyproject.toml").open("rb") as f:
        return str(tomllib.load(f)["project"]["version"])


def test_changelog_follows_keep_a_changelog() -> None:
    lines = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8").splitlines()
    assert lines[0] == "# Changelog"
    versions = [line for line in lines if line.startswith("## ")]
    assert versions[0] == "## [Unreleased]", "the first section is [Unreleased]"
    releases = []
    for heading in versions[1:]:
        match = RELEASE.fullmatch(heading)
        assert match, f"not a release heading '## [X.Y.Z] - YYYY-MM-DD': {heading!r}"
        assert ISO_DATE.fullmatch(match[4]), f"not a date: {heading!r}"
        releases.append((tuple(int(g) for g in match.groups()[:3]), match[4]))
    assert releases == sorted(releases, reverse=True), "releases are listed newest first"
    assert _pyproject_version() in {".".join(map(str, v)) for v, _ in releases}, \
        "pyproject.toml's version has a section"
    section, items = None, 0
    for line in [*lines[1:], "## end"]:
        if line.startswith(("## ", "### ")) and section is not None:
            assert items, f"{section!r} lists nothing"
            section, items = None, 0
        if line.startswith("### "):
            assert line[4:] in CHANGE_TYPES, f"unknown type of change: {line!r}"
            section = line
        elif section is not None and line.startswith("- "):
            items += 1
        elif section is not None and line.strip():
            assert line.startswith("  "), f"not an item or its continuation: {line!r}"


def test_citation_file_is_valid_cff() -> None:
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert cff["cff-version"] == "1.2.0"
    assert {"message", "title", "authors"} <= cff.keys()
    assert all("name" in a or "family-names" in a for a in cff["authors"])
    assert str(cff["version"]) == _pyproject_version()
    paper = cff["preferred-citation"]
    assert paper["type"] == "article" and paper["doi"].startswith("10.")
    assert all("family-names" in a for a in paper["authors"])

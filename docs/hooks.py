"""MkDocs hooks for the documentation site (mkdocs.yml): the README as the home page, the
changelog and benchmark tables the pages link to, and links that stay valid under
``mkdocs build --strict``.

Pages are written to be read on the repository too, so their links are repository paths: the
README links ``docs/model.md``, ``docs/architecture.md`` links ``../benchmarks/results/...``.
The site holds ``docs/`` at its root and the README, ``CHANGELOG.md`` and
``benchmarks/results/*.md`` beside it;
each link is rewritten from the repository's layout to the site's. Generated reports under
``docs/results/`` link files that are not committed beside every copy (the replay page); such
a link is shown as its text.
"""

from __future__ import annotations

import posixpath
import re
from pathlib import Path
from typing import Any

from mkdocs.structure.files import File, Files
from mkdocs.structure.pages import Page

ROOT = Path(__file__).resolve().parent.parent
"""The repository."""
EXTRA = ("README.md", "CHANGELOG.md",
         *(f"benchmarks/results/{p.name}"
           for p in sorted((ROOT / "benchmarks/results").glob("*.md"))))
"""Repository files outside docs/ that the site renders: the README (as the home page), the
changelog and the benchmark tables the pages link to."""

_LINK = re.compile(r"(!?)\[([^\]]*)\]\(([^()\s]+)\)")


def _site_path(repo_path: str) -> str:
    """Where a repository file is in the site."""
    if repo_path == "README.md":
        return "index.md"
    return repo_path.removeprefix("docs/")


def _repo_path(page: File) -> str:
    """Where a page's source is in the repository."""
    if page.src_uri == "index.md":
        return "README.md"
    return page.src_uri if page.src_uri in EXTRA else f"docs/{page.src_uri}"


def on_files(files: Files, config: Any) -> Files:
    """Add the README as index.md and the benchmark tables, from outside docs/."""
    for repo_path in EXTRA:
        files.append(File.generated(config, _site_path(repo_path),
                                    abs_src_path=str(ROOT / repo_path)))
    return files


def on_page_markdown(markdown: str, page: Page, config: Any, files: Files) -> str:
    """Rewrite each relative link from the repository's layout to the site's."""
    source = _repo_path(page.file)
    generated_report = source.startswith("docs/results/")

    def rewrite(match: re.Match[str]) -> str:
        bang, text, target = match.groups()
        if re.match(r"[a-z]+:", target) or target.startswith(("#", "/")):
            return match[0]
        path, hash_, anchor = target.partition("#")
        repo = posixpath.normpath(posixpath.join(posixpath.dirname(source), path))
        site = _site_path(repo)
        here = posixpath.dirname(page.file.src_uri)
        if generated_report and files.get_file_from_path(site) is None \
                and not (ROOT / repo).exists():
            return text
        relative = posixpath.relpath(site, here or ".") + ("/" if path.endswith("/") else "")
        return f"{bang}[{text}]({relative}{hash_}{anchor})"

    return _LINK.sub(rewrite, markdown)

"""What the benchmarks share: their JSON in ``reports/``, and the tracked docs' sections.

Every benchmark writes its results to ``reports/bench_<name>.json`` (:func:`write_json`).
One that quotes its figures in a tracked doc rewrites that doc's section only when run
with ``--update-docs`` (:func:`add_update_docs`); without it :func:`update_section` says
which section would change and touches nothing.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
REPORTS = ROOT / "reports"


def json_path(name: str) -> Path:
    """Return ``reports/bench_<name>.json``."""
    return REPORTS / f"bench_{name}.json"


def _shown(path: Path) -> str:
    path = Path(path).resolve()
    return str(path.relative_to(ROOT)) if path.is_relative_to(ROOT) else str(path)


def write_json(name: str, result, *, path=None, indent: int = 1) -> Path:
    """Write ``result`` to ``path`` (default :func:`json_path` of ``name``); return it."""
    path = Path(path) if path is not None else json_path(name)
    path.write_text(json.dumps(result, indent=indent, default=float) + "\n")
    print(f"wrote {_shown(path)}")
    return path


def add_update_docs(parser) -> None:
    """Give an argparse parser the ``--update-docs`` flag."""
    parser.add_argument(
        "--update-docs",
        action="store_true",
        help="rewrite the tracked docs' sections these results change (default: only "
        "say which would change)",
    )


def update_section(path, begin: str, end: str, body: str, *, update: bool) -> bool:
    """Put ``body`` between the markers ``begin`` and ``end`` of ``path`` if ``update``.

    Without ``update`` nothing is written: prints whether the section would change.
    Returns whether it differs from ``body``.
    """
    path = Path(path)
    text = path.read_text()
    if begin not in text or end not in text:
        raise SystemExit(f"{path} has no {begin} ... {end} markers")
    block = f"{begin}\n{body}\n{end}"
    pattern = re.escape(begin) + ".*?" + re.escape(end)
    new = re.sub(pattern, lambda m: block, text, count=1, flags=re.S)
    if new == text:
        print(f"{_shown(path)}: section {begin} unchanged")
        return False
    if update:
        path.write_text(new)
        print(f"updated {_shown(path)}: section {begin}")
    else:
        print(f"{_shown(path)}: section {begin} would change (--update-docs rewrites it)")
    return True

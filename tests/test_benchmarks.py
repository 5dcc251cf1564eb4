"""Every benchmark writes its JSON to reports/ and rewrites tracked docs only when asked."""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
#: Benchmarks kept by their own owners (the renderer hosts, the material tables).
OTHERS = {"bench_material", "bench_blender", "bench_three_material"}
BENCHMARKS = sorted(p for p in (ROOT / "benchmarks").glob("bench_*.py") if p.stem not in OTHERS)


def _calls(tree: ast.AST) -> set[str]:
    """The ``_reports.<name>`` functions a module calls."""
    return {
        node.func.attr
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and isinstance(node.func.value, ast.Name)
        and node.func.value.id == "_reports"
    }


def _mentions_docs(tree: ast.AST) -> bool:
    """Whether the code (not a docstring) builds a path under docs/ or to README.md."""
    return any(
        isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and (node.value in ("docs", "README.md") or node.value.startswith("docs/"))
        and "\n" not in node.value
        for node in ast.walk(tree)
    )


@pytest.mark.parametrize("path", BENCHMARKS, ids=lambda p: p.stem)
def test_benchmark_writes_json_and_docs_only_when_asked(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    calls = _calls(tree)
    assert "write_json" in calls, f"{path.name} writes no reports/bench_*.json"
    if _mentions_docs(tree) or "update_section" in calls:
        assert {"add_update_docs", "update_section"} <= calls, (
            f"{path.name} names a tracked doc: it rewrites it only with --update-docs"
        )
        assert "write_text" not in {
            n.func.attr
            for n in ast.walk(tree)
            if isinstance(n, ast.Call)
            and isinstance(n.func, ast.Attribute)
            and "DOC" in ast.unparse(n.func.value)
        }, f"{path.name} writes a doc itself"


def test_update_section_touches_nothing_without_update_docs(tmp_path, capsys):
    spec = importlib.util.spec_from_file_location("_reports", ROOT / "benchmarks" / "_reports.py")
    reports = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(reports)
    doc = tmp_path / "doc.md"
    doc.write_text("intro\n<!-- b -->\nold\n<!-- e -->\nrest\n")
    before = doc.read_bytes()
    assert reports.update_section(doc, "<!-- b -->", "<!-- e -->", "new", update=False)
    assert doc.read_bytes() == before
    assert "would change" in capsys.readouterr().out
    assert reports.update_section(doc, "<!-- b -->", "<!-- e -->", "new", update=True)
    assert doc.read_text() == "intro\n<!-- b -->\nnew\n<!-- e -->\nrest\n"
    assert not reports.update_section(doc, "<!-- b -->", "<!-- e -->", "new", update=False)

"""Every benchmark writes its JSON to reports/ and rewrites tracked docs only when asked."""

from __future__ import annotations

import ast
import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
BENCHMARKS = sorted((ROOT / "benchmarks").glob("bench_*.py"))
#: Files under docs/ the benchmarks only read (their input, not a doc they rewrite).
INPUTS = {"films.toml"}


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


def _is_docs(node: ast.AST) -> bool:
    return (
        isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and (node.value in ("docs", "README.md") or node.value.startswith("docs/"))
        and "\n" not in node.value
        and node.value.removeprefix("docs/") not in INPUTS
    )


def _inputs(tree: ast.AST) -> set[int]:
    """The ``"docs"`` of ``... / "docs" / "films.toml"`` (:data:`INPUTS`): read, not written."""
    return {
        id(node.left.right)
        for node in ast.walk(tree)
        if isinstance(node, ast.BinOp)
        and isinstance(node.right, ast.Constant)
        and node.right.value in INPUTS
        and isinstance(node.left, ast.BinOp)
    }


def _mentions_docs(tree: ast.AST) -> bool:
    """Whether the code (not a docstring) builds a path under docs/ or to README.md."""
    inputs = _inputs(tree)
    return any(_is_docs(node) and id(node) not in inputs for node in ast.walk(tree))


def _doc_names(tree: ast.Module) -> set[str]:
    """The module's constants naming a path under docs/ (``PICTURE = ROOT / "docs" / ...``)."""
    inputs = _inputs(tree)
    return {
        target.id
        for node in tree.body
        if isinstance(node, ast.Assign)
        and any(_is_docs(n) and id(n) not in inputs for n in ast.walk(node.value))
        for target in node.targets
        if isinstance(target, ast.Name)
    }


def _unguarded_doc_writes(tree: ast.Module) -> list[str]:
    """Calls that write (a ``write``/``png``/``save`` function) a path of :func:`_doc_names`
    outside an ``if`` on ``update_docs``: a picture under docs/ written unasked."""
    names = _doc_names(tree)
    found = []

    def visit(node: ast.AST, guarded: bool) -> None:
        if isinstance(node, ast.If) and "update_docs" in ast.unparse(node.test):
            for child in node.body:
                visit(child, True)
            for child in node.orelse:
                visit(child, guarded)
            return
        if isinstance(node, ast.Call) and not guarded:
            func = (
                node.func.attr if isinstance(node.func, ast.Attribute) else ast.unparse(node.func)
            )
            used = {
                n.id
                for arg in (*node.args, *(k.value for k in node.keywords))
                for n in ast.walk(arg)
                if isinstance(n, ast.Name)
            }
            if any(w in func.lower() for w in ("write", "png", "save")) and used & names:
                found.append(ast.unparse(node))
        for child in ast.iter_child_nodes(node):
            visit(child, guarded)

    visit(tree, False)
    return found


@pytest.mark.parametrize("path", BENCHMARKS, ids=lambda p: p.stem)
def test_benchmark_writes_json_and_docs_only_when_asked(path):
    tree = ast.parse(path.read_text(encoding="utf-8"))
    calls = _calls(tree)
    assert "write_json" in calls, f"{path.name} writes no reports/bench_*.json"
    if _mentions_docs(tree) or "update_section" in calls:
        assert "add_update_docs" in calls, (
            f"{path.name} names a tracked doc: it rewrites it only with --update-docs"
        )
        assert not _unguarded_doc_writes(tree), (
            f"{path.name} writes under docs/ without --update-docs: {_unguarded_doc_writes(tree)}"
        )
        assert "write_text" not in {
            n.func.attr
            for n in ast.walk(tree)
            if isinstance(n, ast.Call)
            and isinstance(n.func, ast.Attribute)
            and "DOC" in ast.unparse(n.func.value)
        }, f"{path.name} writes a doc itself"


def test_an_unguarded_picture_write_is_found():
    source = """
PICTURE = ROOT / "docs" / "gallery" / "x.png"
FILMS = ROOT / "docs" / "films.toml"
def main(args):
    films = read_films(FILMS)
    {write}
    print(f"{{PICTURE}}")
"""
    unguarded = ast.parse(source.format(write="_png(image, PICTURE)"))
    assert _unguarded_doc_writes(unguarded) == ["_png(image, PICTURE)"]
    assert _mentions_docs(unguarded)
    guarded = "if args.update_docs:\n        images.write_image(PICTURE, image)"
    assert not _unguarded_doc_writes(ast.parse(source.format(write=guarded)))
    assert not _mentions_docs(ast.parse('FILMS = ROOT / "docs" / "films.toml"'))


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

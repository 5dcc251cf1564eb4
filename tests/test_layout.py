"""The package's layout is its pipeline: no module imports from a later stage.

Stages in order (README, *How it is built*): the shared leaves ``cache`` and ``io``;
``physics``; ``colour`` (with ``registry``, which looks matrices up in colorimetry);
``lut``; ``config``; ``export``; ``render``; ``cli``. Every import is checked, lazy ones inside
functions included. The evaluation code (the report, the stability cases, the GPU harness, the
test colour sets) is the top-level ``evaluation`` package beside ``benchmarks/``, outside the
shipped package: nothing in ``ocio_thinfilm`` imports it (``cli/report.py`` loads it from a
checkout), and it imports ``ocio_thinfilm``, never the other way round.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "ocio_thinfilm"
STAGES = ["cache", "io", "physics", "colour", "registry", "lut", "config", "export", "render",
          "cli"]
RANK = {name: rank for rank, name in enumerate(STAGES)}
RANK.update(cache=0, io=0, colour=3, registry=3)  # leaves; registry beside colorimetry


def _stage(dotted: str) -> str:
    parts = dotted.split(".")
    assert parts[0] == "ocio_thinfilm", dotted
    return parts[1] if len(parts) > 1 else ""


def _modules():
    return sorted(p for p in PACKAGE.rglob("*.py") if p.name != "__main__.py")


def _imports(path: Path):
    """(line, imported module) of every ``ocio_thinfilm`` import in ``path``."""
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0 \
                and node.module.startswith("ocio_thinfilm"):
            if node.module == "ocio_thinfilm":
                for alias in node.names:
                    yield node.lineno, f"ocio_thinfilm.{alias.name}"
            else:
                yield node.lineno, node.module
        elif isinstance(node, ast.ImportFrom) and node.level:
            raise AssertionError(f"{path}:{node.lineno}: relative import (use absolute ones)")
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("ocio_thinfilm"):
                    yield node.lineno, alias.name


def _imports_evaluation(path: Path) -> list[int]:
    """Lines of ``path`` that import the top-level ``evaluation`` package."""
    tree = ast.parse(path.read_text())
    names = [(node.lineno, node.module) for node in ast.walk(tree)
             if isinstance(node, ast.ImportFrom) and node.module and node.level == 0]
    names += [(node.lineno, alias.name) for node in ast.walk(tree)
              if isinstance(node, ast.Import) for alias in node.names]
    return [line for line, name in names if name.split(".")[0] == "evaluation"]


@pytest.mark.parametrize("path", _modules(), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_no_module_imports_a_later_stage(path):
    rel = path.relative_to(PACKAGE).with_suffix("")
    source = rel.parts[0] if rel.parts[0] != "__init__" else ""
    if source in ("", "__version__"):
        return
    for line, target in _imports(path):
        stage = _stage(target)
        if stage in ("", "__version__"):
            continue
        assert RANK[stage] <= RANK[source], (
            f"{rel}.py:{line} imports {target}: stage {stage!r} comes after {source!r}")


def test_every_stage_is_known_and_the_check_can_fail(tmp_path):
    packages = {p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    leaves = {p.stem for p in PACKAGE.glob("*.py") if p.stem not in ("__init__", "__main__")}
    assert packages | leaves == set(STAGES)
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from ocio_thinfilm.render import frames\n")
    assert list(_imports(bad)) == [(2, "ocio_thinfilm.render")]
    assert RANK[_stage("ocio_thinfilm.render")] > RANK["lut"]


def test_the_shipped_package_never_imports_the_evaluation_code(tmp_path):
    """Only ``cli/report.py`` reaches ``evaluation`` (from a checkout, after checking that
    it is there); a module that imports it would fail from a wheel."""
    offenders = {str(p.relative_to(PACKAGE)): _imports_evaluation(p) for p in _modules()}
    offenders = {k: v for k, v in offenders.items() if v and k != "cli/report.py"}
    assert offenders == {}
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from evaluation.colours import object_colours\n")
    assert _imports_evaluation(bad) == [2]

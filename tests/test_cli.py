"""The command line: ``--help``, ``demo`` and bad arguments, run as subprocesses.

References used: OpenImageIO reading the written PNG back, colour-science
(``colour.sd_to_XYZ``, ``colour.XYZ_to_RGB``) recomputing the colour ``demo`` prints,
and the documented CLI contract (exit code 2 and a one-line error, no traceback).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def run(args, cwd, console_script=False):
    env = dict(os.environ)
    env["PYTHONPATH"] = str(ROOT) + os.pathsep + env.get("PYTHONPATH", "")
    if console_script:
        exe = shutil.which("ocio-thinfilm")
        if exe is None:
            pytest.skip("console script ocio-thinfilm not installed (pip install -e .)")
        cmd = [exe, *args]
    else:
        cmd = [sys.executable, "-m", "ocio_thinfilm", *args]
    return subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


def test_help(tmp_path):
    """Reference: argparse's contract -- exit 0, usage on stdout, the demo command listed."""
    p = run(["--help"], tmp_path)
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith("usage: ocio-thinfilm")
    assert "demo" in p.stdout
    p = run(["demo", "--help"], tmp_path)
    assert p.returncode == 0 and "--out" in p.stdout and "--thickness" in p.stdout


@pytest.fixture(scope="module")
def demo_run(tmp_path_factory):
    out_dir = tmp_path_factory.mktemp("demo")
    p = run(["demo", "--out", "strip.png"], out_dir, console_script=True)
    return p, out_dir / "strip.png"


def test_demo_writes_a_readable_png(demo_run):
    """Reference: OpenImageIO reads the PNG back; its content follows from the
    physics: t = 0 (left edge) is black in both halves (Eq. 7: R = 0), the clip
    (top) and the clamp (bottom) differ, everything is in [0, 1]."""
    import OpenImageIO as oiio

    p, png = demo_run
    assert p.returncode == 0, p.stderr
    assert png.exists()
    buf = oiio.ImageBuf(str(png))
    assert not buf.has_error, buf.geterror()
    spec = buf.spec()
    assert (spec.width, spec.height, spec.nchannels) == (1024, 96, 3)
    assert spec.format == oiio.TypeDesc("uint8")
    pix = buf.get_pixels(oiio.FLOAT)
    assert pix.shape == (96, 1024, 3)
    assert np.all((pix >= 0) & (pix <= 1))
    assert np.all(pix[:, 0] < 1.5 / 255)
    top, bottom = pix[:48], pix[48:]
    assert np.all(top == top[:1]) and np.all(bottom == bottom[:1])
    assert np.abs(top[0] - bottom[0]).max() > 0.05
    assert pix[0].std(axis=0).min() > 0.05  # a strip of colours, not a flat field


def test_demo_prints_the_soap_film_colour(demo_run, colour):
    """Reference: colour.sd_to_XYZ of Eq. 7 at t' = 1.33 * 300 nm (numpy, 1 nm) and
    colour.XYZ_to_RGB to linear sRGB, against the printed values (4 decimals)."""
    p, _ = demo_run
    assert p.returncode == 0, p.stderr

    def printed(label):
        m = re.search(label + r"\s+\[\s*([-\d.e]+)\s+([-\d.e]+)\s+([-\d.e]+)\s*\]", p.stdout)
        assert m, p.stdout
        return np.array([float(v) for v in m.groups()])

    wl = np.arange(360.0, 781.0)
    R = np.sin(2 * np.pi * 1.33 * 300.0 / wl) ** 2
    XYZ = (
        colour.sd_to_XYZ(
            colour.SpectralDistribution(R, wl),
            colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"],
            colour.SDS_ILLUMINANTS["D65"],
            method="Integration",
        )
        / 100
    )
    np.testing.assert_allclose(printed(r"XYZ \(D65, Y_white = 1\)"), XYZ, atol=1.5e-3)
    cs = colour.RGB_COLOURSPACES["sRGB"].copy()
    cs.use_derived_transformation_matrices(True)
    rgb = colour.XYZ_to_RGB(XYZ, cs, illuminant=np.array([0.3127, 0.329]))
    np.testing.assert_allclose(printed("linear sRGB, unclipped"), rgb, atol=3e-3)
    clipped = printed("constant-lightness clip")
    assert np.all((clipped >= 0) & (clipped <= 1))
    lum = colour.RGB_COLOURSPACES["sRGB"].matrix_RGB_to_XYZ[1]
    assert clipped @ lum == pytest.approx(XYZ[1], abs=2e-3)  # lightness kept
    assert re.search(r"sRGB-encoded\s+#[0-9A-F]{6}\b", p.stdout)


@pytest.mark.parametrize(
    "args,needle",
    [
        (["demo", "--thickness", "-5", "--out", "x.png"], "--thickness"),
        (["demo", "--thickness", "abc"], "--thickness"),
        (["demo", "--thickness", "nan", "--out", "x.png"], "--thickness"),
        (["no-such-command"], "no-such-command"),
        (["demo", "--out", "/proc/forbidden/x.png"], "/proc/forbidden"),
    ],
)
def test_bad_arguments_exit_2_with_one_line_error(tmp_path, args, needle):
    """Reference: the CLI contract -- exit code 2, the error on one line of stderr
    (after argparse's usage line for syntax errors), naming the culprit, no
    traceback, and nothing written."""
    p = run(args, tmp_path)
    assert p.returncode == 2, (p.stdout, p.stderr)
    lines = [line for line in p.stderr.splitlines() if line.strip()]
    assert "Traceback" not in p.stderr
    errors = [line for line in lines if "error:" in line]
    assert len(errors) == 1, p.stderr
    assert errors[0].startswith("ocio-thinfilm")
    assert needle in errors[0]
    assert all(line.startswith("usage:") or line is errors[0] for line in lines), p.stderr
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize("value", ["-5", "nan", "inf"])
def test_physics_errors_name_the_parameter_and_the_cli_its_option(tmp_path, value, capsys):
    """The numeric core names its Python parameter (a ParameterError, a ValueError);
    ``demo`` names the option for the same mistake, with the same detail."""
    from ocio_thinfilm.checks import ParameterError
    from ocio_thinfilm.cli import demo
    from ocio_thinfilm.cli import main as cli

    with pytest.raises(ParameterError) as raised:
        demo.soap_film_colour(float(value))
    message = str(raised.value)
    assert raised.value.parameter == "thickness" and message.startswith("thickness must be")
    assert cli.main(["demo", "--thickness", value, "--out", str(tmp_path / "x.png")]) == 2
    err = capsys.readouterr().err.strip()
    assert err == f"ocio-thinfilm demo: error: --{message}", err
    assert list(tmp_path.iterdir()) == []


def test_the_numeric_core_raises_parameter_errors():
    """Every argument check of the numeric core names its parameter the same way."""
    from ocio_thinfilm import checks
    from ocio_thinfilm.checks import ParameterError
    from ocio_thinfilm.colour import compress
    from ocio_thinfilm.lut import tables
    from ocio_thinfilm.physics import sampling, spectra

    cases = [
        (lambda: spectra.optical_thickness(300.0, -1.0), "n"),
        (lambda: sampling.wavelength_grid(400, 700, -5), "step"),
        (lambda: sampling.check_wavelengths([500, 400]), "wavelengths"),
        (lambda: checks.as_count("layers", 0), "layers"),
        (lambda: compress.compression_curve(0.5, threshold=1.5), "threshold"),
        (lambda: tables.check_size(1, what="film_size"), "film_size"),
    ]
    for call, parameter in cases:
        with pytest.raises(ParameterError) as raised:
            call()
        assert raised.value.parameter == parameter, raised.value
        assert str(raised.value).startswith(parameter + " ")


def test_building_the_parser_imports_no_colour_science(tmp_path):
    """Every command builds the whole parser: its help texts must not compute anything
    (importing colour-science costs about a second on a cold cache)."""
    import subprocess
    import sys

    code = (
        "import sys; from ocio_thinfilm.cli.main import build_parser; build_parser(); "
        "print(sorted(m for m in ('colour', 'PyOpenColorIO', 'OpenImageIO') if m in sys.modules))"
    )
    env = {**__import__("os").environ, "OCIO_THINFILM_CACHE": "0"}
    done = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path
    )
    assert done.returncode == 0, done.stderr
    assert "'colour'" not in done.stdout, done.stdout


def _sub_parsers(parser, prefix=()):
    """(command words, parser) of every sub-command, nested ones included."""
    import argparse

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield (*prefix, name), sub
                yield from _sub_parsers(sub, (*prefix, name))


def test_every_command_help_has_a_description():
    """``ocio-thinfilm X --help`` says what X does (``demo --help`` had no text), and the
    spectra option says it writes T too (it did not)."""
    from ocio_thinfilm.cli.main import build_parser

    commands = dict(_sub_parsers(build_parser()))
    assert ("demo",) in commands and ("export", "film") in commands
    for words, sub in commands.items():
        assert sub.description and len(sub.description) > 20, words
    film_help = commands[("export", "film")].format_help()
    assert "transmittance" in " ".join(film_help.split())

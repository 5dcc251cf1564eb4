"""``ocio-thinfilm export view``: display LUTs applied by independent consumers.

Each file is written to a temporary directory and applied to the *raw* pixel values
of its input space by a consumer that is not our code: colour-science's
``read_LUT(...).apply`` (trilinear 3D interpolation, its own .cube / .csp / .spi
parsers), OpenColorIO's ``FileTransform`` on a raw config, and ffmpeg's ``lut3d``
filter where ffmpeg is installed. The expected colour is computed independently:
the input values from colour-science (``XYZ_to_RGB`` with a Bradford adaptation,
``log_encoding_ACEScct``), the expected output from the analytic clip
(``clip.clip_RGB`` of the XYZ -> display-linear RGB), and the file's display code
values are decoded with colour-science's sRGB EOTF (BT.1886 gamma 2.4 for Rec.2020)
before ΔE2000 in XYZ (D65).

Thresholds. The target for ACEScct -> sRGB / Constant-Lightness Clip at 65^3:
ΔE2000 p99 1.0, max 3.0 on object colours inside AP1, in-gamut colours p99 0.5
(measured: p99 0.61-0.68, max 2.0-2.2, in-gamut p99 0.25-0.36; the in-gamut max,
≈ 2, is colours within one grid cell of the gamut boundary near white, where every
view bends towards white). The other displays, consumers and input spaces are
held to their measured values with a margin of about 1.5x (these tests print them:
``pytest -s tests/test_export_view.py``), so a regression of the shaper or the
writers fails.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from evaluation.colours import object_colours
from evaluation.shaders import log_encoding
from evaluation.views import apply_lut_files, colour_science_rgb, decode_display
from ocio_thinfilm import registry
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.colour import clip, colorimetry, compress
from ocio_thinfilm.export import view as export_view

CLC = "Constant-Lightness Clip"
CLS = "Constant-Lightness Compress"
FFMPEG = shutil.which("ffmpeg")


# --------------------------------------------------------------------------- #
# Independent helpers
# --------------------------------------------------------------------------- #
def _expected_XYZ(XYZ, display, view=CLC):
    rgb = colorimetry.XYZ_to_RGB(XYZ, display)
    if view == CLC:
        out = clip.clip_RGB(rgb, display)
    elif view == CLS:
        out = compress.compress_RGB(rgb, display)
    elif view == "Channel Clamp":
        out = np.clip(rgb, 0.0, 1.0)
    else:
        raise ValueError(view)
    return colorimetry.RGB_to_XYZ(out, display)


def _dE(code, XYZ, display, view=CLC):
    got = colorimetry.RGB_to_XYZ(decode_display(code, display), display)
    return colorimetry.delta_E2000(got, _expected_XYZ(XYZ, display, view))


def _stats(dE):
    return dE.mean(), np.percentile(dE, 99), dE.max()


def _colour_apply(paths, values):
    import colour

    out = np.asarray(values, dtype=np.float64)
    for path in paths:
        out = colour.read_LUT(str(path)).apply(out)
    return out


def ffmpeg_apply(path, values):
    """Apply ``path`` with ffmpeg's lut3d filter to float RGB (planar float32)."""
    rgb = np.asarray(values, dtype=np.float32).reshape(-1, 3)
    n, w = len(rgb), 256
    h = -(-n // w)
    img = np.zeros((w * h, 3), np.float32)
    img[:n] = rgb
    img = img.reshape(h, w, 3)
    planes = np.stack([img[..., 1], img[..., 2], img[..., 0]])  # gbrp plane order
    result = subprocess.run(
        [
            FFMPEG,
            "-v",
            "error",
            "-f",
            "rawvideo",
            "-pix_fmt",
            "gbrpf32le",
            "-s",
            f"{w}x{h}",
            "-i",
            "-",
            "-vf",
            f"lut3d=file={path}",
            "-f",
            "rawvideo",
            "-pix_fmt",
            "gbrpf32le",
            "-",
        ],
        input=planes.astype("<f4").tobytes(),
        capture_output=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stderr.decode()
    out = np.frombuffer(result.stdout, "<f4").reshape(3, h, w)
    return np.stack([out[2], out[0], out[1]], axis=-1).reshape(-1, 3)[:n].astype(np.float64)


# --------------------------------------------------------------------------- #
# Fixtures
# --------------------------------------------------------------------------- #
@pytest.fixture(scope="module")
def object_XYZ():
    return object_colours()


@pytest.fixture(scope="module")
def inside_AP1(object_XYZ):
    """(XYZ, ACEScct values) of the object colours whose ACEScg values are >= 0."""
    import colour

    acescg = colour_science_rgb(object_XYZ, "ACEScg")
    keep = (acescg >= 0).all(axis=1)
    return object_XYZ[keep], colour.models.log_encoding_ACEScct(acescg[keep])


@pytest.fixture(scope="module")
def acescct_luts(tmp_path_factory):
    """ACEScct -> each display's Constant-Lightness Clip at 65^3 in every format."""
    d = tmp_path_factory.mktemp("view")
    files = {}
    for display in clip.DISPLAYS:
        for fmt in ("cube", "csp", "clf", "spi3d"):
            files[display, fmt] = export_view.export_view(
                "ACEScct", display, CLC, d / f"{display.replace(' ', '')}.{fmt}"
            )
        files[display, "cube-resolve"] = export_view.export_view(
            "ACEScct", display, CLC, d / f"{display.replace(' ', '')}-resolve.cube", shaper=True
        )
    return files


# --------------------------------------------------------------------------- #
# The target: ACEScct -> sRGB / Constant-Lightness Clip, 65^3 .cube
# --------------------------------------------------------------------------- #
def test_acescct_srgb_resolve_cube_meets_target_in_colour_science(acescct_luts, inside_AP1):
    XYZ, cct = inside_AP1
    assert len(XYZ) > 10000
    (path,) = acescct_luts["sRGB", "cube-resolve"]
    text = path.read_text()
    assert "LUT_3D_SIZE 65" in text and "LUT_1D_INPUT_RANGE" in text
    assert text.startswith("# ACEScct to sRGB") and "Resolve form" in text.splitlines()[0]
    p99, worst = _resolve_cube_meets_target(path, XYZ, cct, "ACEScct")
    # docs/gamut_map.md quotes these figures: they are what this test measures
    assert _quoted(
        r"applied by colour-science,\s+is within ΔE2000 p99 ([\d.]+) / max ([\d.]+)"
    ) == pytest.approx((p99, worst), abs=0.006)
    # grey ramp: neutral in, neutral out (0.18 stays 0.18, not black)
    g = np.array([0.002, 0.01, 0.05, 0.18, 0.5, 0.9, 1.0])
    grey = _colour_apply([path], np.repeat(colour_acescct(g)[:, None], 3, axis=1))
    white = colorimetry.RGB_to_XYZ(np.ones(3), "sRGB")
    dE_grey = _dE(grey, g[:, None] * white, "sRGB")
    print("grey ramp dE2000", np.round(dE_grey, 3))
    assert dE_grey.max() <= 0.5


def _resolve_cube_meets_target(
    path, XYZ, codes, source, limits=(1.0, 3.0, 0.5), consumer="colour-science"
):
    """ΔE2000 of the .cube applied by ``consumer`` (colour-science, or OCIO's
    FileTransform) to ``codes`` against the analytic clip of ``XYZ`` into sRGB:
    ``limits`` p99, max, in-gamut p99 (the target 1.0, 3.0, 0.5)."""
    apply = _colour_apply if consumer == "colour-science" else apply_lut_files
    code = apply([path], codes)
    dE = _dE(code, XYZ, "sRGB")
    mean, p99, worst = _stats(dE)
    inside = clip.in_gamut(colorimetry.XYZ_to_RGB(XYZ, "sRGB"))
    print(
        f"{source}->sRGB .cube ({consumer}): mean {mean:.3f} p99 {p99:.3f} "
        f"max {worst:.3f}; in gamut p99 {np.percentile(dE[inside], 99):.3f} "
        f"max {dE[inside].max():.3f}"
    )
    assert p99 <= limits[0] and worst <= limits[1]
    assert np.percentile(dE[inside], 99) <= limits[2]
    return p99, worst


#: The camera and grading log spaces (every encoded space of the registry whose codes
#: need a shaper: all but ACEScct) on a lighter
#: sample: one display (sRGB), the clip, the default .cube (their Resolve form: a shaper
#: over the linear gamut), one fit each (~18 s, memoised). Their wide gamuts spread the
#: 65^3 grid over a larger volume than AP1 (and their shaper reaches below 0), so on all
#: object colours they reach p99 / max / in-gamut p99 (measured) DaVinci Intermediate
#: 1.41 / 4.83 / 0.50, LogC4 1.17 / 4.03 / 0.39, S-Log3 1.24 / 3.89 / 0.42, V-Log
#: 1.00 / 3.73 / 0.39, Canon Log 3 1.21 / 4.42 / 0.44, Log3G10 1.31 / 5.51 / 0.46, Apple
#: Log 0.86 / 4.23 / 0.25 against
#: ACEScct's 0.60 / 2.39 / 0.36 (a shaper from 0, as AP1's, measured worse: max 5.4-6.3);
#: held with a margin.
CAMERA_LOGS = [e for e in registry.ENCODED_LIST if not e.plain]
CAMERA_LOG_LIMITS = (1.8, 6.0, 0.6)
#: The same .cube applied by OCIO's FileTransform (tetrahedral, where colour-science
#: interpolates trilinearly): measured p99 / max / in-gamut p99 at most 1.49 / 6.20 /
#: 0.44 (DaVinci Intermediate's p99, Log3G10's max: a very dark blue, linear ~0.001-0.01
#: in REDWideGamutRGB, the widest gamut, where the shaper's 65 nodes are sparsest).
CAMERA_LOG_LIMITS_OCIO = (1.8, 6.5, 0.6)


@pytest.mark.parametrize("encoded", CAMERA_LOGS, ids=lambda e: e.name)
def test_camera_log_srgb_cube_meets_the_target(tmp_path, object_XYZ, encoded):
    """Object colours as codes of the log space (colour-science's encoding of its curve
    and gamut, the Bradford-adapted XYZ -> RGB), through the default .cube applied by
    colour-science and by OCIO's FileTransform, near the analytic clip
    (:data:`CAMERA_LOG_LIMITS`)."""
    (path,) = export_view.export_view(encoded.name, "sRGB", CLC, tmp_path / "view.cube")
    assert "LUT_1D_INPUT_RANGE" in path.read_text()  # the Resolve form (not plain)
    linear = colour_science_rgb(object_XYZ, encoded.gamut.colour_science)
    codes = log_encoding(linear, encoded.curve)
    for consumer, limits in (
        ("colour-science", CAMERA_LOG_LIMITS),
        ("OCIO", CAMERA_LOG_LIMITS_OCIO),
    ):
        _resolve_cube_meets_target(path, object_XYZ, codes, encoded.name, limits, consumer)


def colour_acescct(linear):
    import colour

    return colour.models.log_encoding_ACEScct(linear)


#: The target for every display, format and consumer: dE2000 p99 <= 1.0 and
#: max <= 3.0 (measured p99 0.12-0.61, max 1.8-2.5).
TARGET_P99, TARGET_MAX = 1.0, 3.0
CASES = [
    ("sRGB", fmt, consumer)
    for fmt, consumer in (
        ("cube-resolve", "ocio"),
        ("csp", "colour"),
        ("csp", "ocio"),
        ("clf", "ocio"),
        ("spi3d", "colour"),
        ("spi3d", "ocio"),
    )
]
CASES += [
    (display, fmt, consumer)
    for display in ("Display P3", "Rec.2020")
    for fmt, consumer in (("cube-resolve", "colour"), ("csp", "ocio"), ("clf", "ocio"))
]


@pytest.mark.parametrize("display,fmt,consumer", CASES, ids=lambda v: str(v))
def test_acescct_view_luts_in_independent_consumers(
    acescct_luts, inside_AP1, display, fmt, consumer
):
    XYZ, cct = inside_AP1
    paths = acescct_luts[display, fmt]
    if fmt == "spi3d":  # the companion shaper goes first
        assert [p.suffix for p in paths] == [".spi3d", ".spi1d"]
        paths = paths[::-1]
    code = (_colour_apply if consumer == "colour" else apply_lut_files)(paths, cct)
    mean, p99, worst = _stats(_dE(code, XYZ, display))
    print(f"ACEScct->{display} .{fmt} ({consumer}): mean {mean:.3f} p99 {p99:.3f} max {worst:.3f}")
    assert p99 <= TARGET_P99 and worst <= TARGET_MAX
    if (display, fmt, consumer) == ("sRGB", "cube-resolve", "ocio"):  # quoted in docs
        assert _quoted(r"\(through OCIO ([\d.]+) / ([\d.]+);") == pytest.approx(
            (p99, worst), abs=0.006
        )


def _quoted(pattern):
    """The two numbers docs/gamut_map.md quotes where ``pattern`` matches."""
    import re

    doc = (Path(__file__).resolve().parents[1] / "docs" / "gamut_map.md").read_text()
    match = re.search(pattern, doc)
    assert match, pattern
    return tuple(float(v) for v in match.groups())


@pytest.mark.parametrize("display", clip.DISPLAYS)
def test_compress_display_luts(tmp_path, inside_AP1, display):
    """ACEScct -> the Constant-Lightness Compress view as display LUTs, against the
    analytic compression: the Resolve .cube in colour-science, the .csp in ffmpeg (when
    installed) and OCIO, the plain .cube alike in OCIO and colour-science -- the clip's
    targets for the shaper forms (dE2000 p99 <= 1.0, max <= 3.0)."""
    XYZ, cct = inside_AP1
    name = display.replace(" ", "")
    (resolve,) = export_view.export_view(
        "ACEScct", display, CLS, tmp_path / f"{name}-r.cube", shaper=True
    )
    (csp,) = export_view.export_view("ACEScct", display, CLS, tmp_path / f"{name}.csp")
    (plain,) = export_view.export_view("ACEScct", display, CLS, tmp_path / f"{name}.cube")
    assert "Constant-Lightness Compress" in plain.read_text().splitlines()[0]
    results = {
        "resolve cube (colour)": _colour_apply([resolve], cct),
        "csp (ocio)": apply_lut_files([csp], cct),
    }
    if FFMPEG is not None:
        results["csp (ffmpeg)"] = ffmpeg_apply(csp, cct)
    for what, code in results.items():
        mean, p99, worst = _stats(_dE(code, XYZ, display, CLS))
        print(f"ACEScct->{display} compress {what}: p99 {p99:.3f} max {worst:.3f}")
        assert p99 <= TARGET_P99 and worst <= TARGET_MAX, what
    np.testing.assert_allclose(
        _colour_tetrahedral(plain, cct), apply_lut_files([plain], cct), atol=1e-5
    )


@pytest.mark.skipif(FFMPEG is None, reason="ffmpeg not installed (Debian package ffmpeg)")
@pytest.mark.parametrize("display", clip.DISPLAYS)
def test_acescct_csp_in_ffmpeg(acescct_luts, inside_AP1, display):
    """ffmpeg reads .csp preluts (not the 1D part of a Resolve .cube)."""
    XYZ, cct = inside_AP1
    (path,) = acescct_luts[display, "csp"]
    mean, p99, worst = _stats(_dE(ffmpeg_apply(path, cct), XYZ, display))
    print(f"ACEScct->{display} .csp (ffmpeg): mean {mean:.3f} p99 {p99:.3f} max {worst:.3f}")
    assert p99 <= 1.0 and worst <= 3.0


# --------------------------------------------------------------------------- #
# The plain .cube: what every reader applies alike
# --------------------------------------------------------------------------- #
def _colour_tetrahedral(path, values):
    """colour-science's own .cube reader and its tetrahedral table interpolation."""
    import colour

    lut = colour.read_LUT(str(path))
    return lut.apply(
        np.asarray(values, dtype=np.float64),
        interpolator=colour.algebra.table_interpolation_tetrahedral,
    )


@pytest.mark.parametrize("display", clip.DISPLAYS)
def test_plain_cube_is_one_3d_table_every_reader_applies_alike(acescct_luts, inside_AP1, display):
    """The default ACEScct .cube: LUT_3D_SIZE and the table only (no 1D shaper, no
    DOMAIN lines, which ffmpeg, OpenShot and three.js ignore), its TITLE saying so;
    OCIO, colour-science and ffmpeg (where installed) give the same code values on
    object colours and on the whole grid's cells (tetrahedral in all three; the
    file's 6 decimals are the common source)."""
    (path,) = acescct_luts[display, "cube"]
    text = path.read_text()
    first = text.splitlines()[0]
    assert first.startswith('TITLE "') and "plain 3D LUT over 0..1" in first
    assert "LUT_3D_SIZE 65" in text
    assert not any(k in text for k in ("LUT_1D_SIZE", "LUT_1D_INPUT_RANGE", "DOMAIN_"))
    _, cct = inside_AP1
    rng = np.random.default_rng(3)
    values = np.concatenate([cct, rng.uniform(0.0, 1.0, (20000, 3))])
    by_ocio = apply_lut_files([path], values)
    by_colour = _colour_tetrahedral(path, values)
    gap = {"colour": float(np.abs(by_colour - by_ocio).max())}
    if FFMPEG is not None:
        gap["ffmpeg"] = float(np.abs(ffmpeg_apply(path, values) - by_ocio).max())
    print(f"ACEScct->{display} plain .cube, largest difference from OCIO: {gap}")
    # float32 arithmetic of the same table: far below one 16-bit code value
    assert max(gap.values()) <= 1e-5


#: Measured for the plain ACEScct .cube at 65^3 (its table fitted by lattice regression,
#: the colours inside the display's gamut weighted first) on object colours inside AP1
#: (OCIO, tetrahedral), p99 / max: sRGB 3.08 / 11.19, Display P3 2.01 / 9.55, Rec.2020
#: 0.35 / 6.66, P3-DCI 2.54 / 10.32 (sampled nodes: 4.17 / 8.64, 4.53 / 8.69, 4.70 /
#: 10.02); held with a margin. Colours inside the gamut meet their target (tests
#: below); colours outside it lose (a strict xfail below states it).
PLAIN_LIMITS = {
    "sRGB": (4.0, 13.0),
    "Display P3": (3.0, 11.5),
    "Rec.2020": (0.6, 8.0),
    "P3-DCI": (3.0, 11.5),
}


def _plain_stats(acescct_luts, inside_AP1, display):
    XYZ, cct = inside_AP1
    (path,) = acescct_luts[display, "cube"]
    dE = _dE(apply_lut_files([path], cct), XYZ, display)
    inside = clip.in_gamut(colorimetry.XYZ_to_RGB(XYZ, display))
    return _stats(dE) + (np.percentile(dE[inside], 99), dE[inside].max())


@pytest.mark.parametrize("display", clip.DISPLAYS)
def test_plain_cube_accuracy(acescct_luts, inside_AP1, display):
    mean, p99, worst, in_p99, in_max = _plain_stats(acescct_luts, inside_AP1, display)
    print(
        f"ACEScct->{display} plain .cube (OCIO): mean {mean:.3f} p99 {p99:.3f} "
        f"max {worst:.3f}; inside {display}: p99 {in_p99:.3f} max {in_max:.3f}"
    )
    assert p99 <= PLAIN_LIMITS[display][0] and worst <= PLAIN_LIMITS[display][1]


def _ocio_default_apply(path, values):
    """OCIO's FileTransform at its default interpolation (trilinear for a 3D LUT)."""
    import PyOpenColorIO as ocio

    px = np.ascontiguousarray(np.asarray(values, dtype=np.float32).reshape(-1, 3)).copy()
    t = ocio.FileTransform(str(path))
    ocio.Config.CreateRaw().getProcessor(t).getDefaultCPUProcessor().applyRGB(px)
    return px.astype(np.float64)


#: Hosts as they apply a file by default: ffmpeg's lut3d tetrahedral, OCIO's
#: FileTransform and colour-science's LUT3D.apply trilinear.
DEFAULT_HOSTS = {
    "ffmpeg": lambda path, values: ffmpeg_apply(path, values),
    "ocio": _ocio_default_apply,
    "colour": lambda path, values: _colour_apply([path], values),
}

#: The plain ACEScct -> sRGB .cube with its nodes sampled from the view (no
#: lattice-regression fit), object colours inside AP1 and outside sRGB, p99 / max by
#: host: what the fitted table must not exceed out of gamut.
SAMPLED_OUTSIDE = {"ffmpeg": (5.61, 8.25), "ocio": (6.50, 9.55), "colour": (6.50, 9.55)}
#: Reached by the fitted table (measured, then a margin), (inside p99, inside max,
#: outside p99, outside max); object colours inside AP1 split by the sRGB gamut.
#: Measured: ffmpeg 0.43 / 1.36, 8.30 / 11.19; OCIO and colour-science 0.45 / 2.55,
#: 7.98 / 11.38.
FITTED_REACHED = {
    "ffmpeg": (0.7, 2.0, 9.0, 12.5),
    "ocio": (0.7, 3.0, 9.0, 12.5),
    "colour": (0.7, 3.0, 9.0, 12.5),
}


def _split_stats(code, XYZ, display="sRGB"):
    dE = _dE(code, XYZ, display)
    inside = clip.in_gamut(colorimetry.XYZ_to_RGB(XYZ, display))
    return (
        float(np.percentile(dE[inside], 99)),
        float(dE[inside].max()),
        float(np.percentile(dE[~inside], 99)),
        float(dE[~inside].max()),
    )


@pytest.fixture(scope="module")
def plain_split(acescct_luts, inside_AP1):
    """host -> (inside p99, inside max, outside p99, outside max) of the plain
    ACEScct -> sRGB .cube applied by the host at its default interpolation."""
    XYZ, cct = inside_AP1
    (path,) = acescct_luts["sRGB", "cube"]
    out = {}
    for host, apply in DEFAULT_HOSTS.items():
        if host == "ffmpeg" and FFMPEG is None:
            continue
        out[host] = _split_stats(apply(path, cct), XYZ)
        print(
            f"ACEScct->sRGB plain .cube ({host}): inside sRGB p99 {out[host][0]:.2f} max "
            f"{out[host][1]:.2f}; outside p99 {out[host][2]:.2f} max {out[host][3]:.2f}"
        )
    return out


@pytest.mark.parametrize("host", list(DEFAULT_HOSTS))
def test_plain_cube_colours_inside_the_gamut_in_hosts(plain_split, host):
    """Target for the plain 65^3 ACEScct -> sRGB .cube, as each host applies it by
    default: colours inside sRGB (that need no mapping) within ΔE2000 p99 1.0 / max
    3.0 of the analytic view; the bounds reached in and out of the gamut held too."""
    if host not in plain_split:
        pytest.skip("ffmpeg not installed (Debian package ffmpeg)")
    in_p99, in_max, out_p99, out_max = plain_split[host]
    assert in_p99 <= 1.0 and in_max <= 3.0
    bound = FITTED_REACHED[host]
    assert in_p99 <= bound[0] and in_max <= bound[1]
    assert out_p99 <= bound[2] and out_max <= bound[3]


@pytest.mark.xfail(
    strict=True,
    reason="colours outside sRGB: the fitted table, with the colours inside weighted "
    "first, reaches p99 8.0-8.3 / max 11.2-11.4 against 5.6-6.5 / 8.3-9.6 for sampled "
    "nodes (the weight curve: reports/bench_view_fit.md)",
)
@pytest.mark.parametrize("host", list(DEFAULT_HOSTS))
def test_plain_cube_colours_outside_the_gamut_no_worse(plain_split, host):
    """Target: colours outside sRGB no worse than with the nodes sampled from the view."""
    if host not in plain_split:
        pytest.xfail("ffmpeg not installed")
    _, _, out_p99, out_max = plain_split[host]
    assert out_p99 <= SAMPLED_OUTSIDE[host][0] and out_max <= SAMPLED_OUTSIDE[host][1]


@pytest.fixture(scope="module")
def linear709_luts(tmp_path_factory):
    d = tmp_path_factory.mktemp("rec709")
    source = "Linear Rec.709 (sRGB)"
    return {
        fmt: export_view.export_view(source, "sRGB", CLC, d / f"v.{fmt}")[0]
        for fmt in ("cube", "csp")
    }


#: Linear Rec.709 -> sRGB: the Resolve .cube (its shaper ignored by ffmpeg, so not
#: applied there) and the .csp, by host at its default interpolation. Target: object
#: colours p99 1.5 / max 4.0, colours inside sRGB p99 0.5 / max 2.0. Measured with the
#: fitted table: object colours p99 0.73-0.84 / max 3.76-3.79, inside 0.19-0.20 /
#: 1.64-1.66 (sampled table: 1.18-1.57 / 4.72-5.52 and 0.25 / 1.94-1.97).
LINEAR709_CASES = [("cube", "ocio"), ("cube", "colour"), ("csp", "ffmpeg"), ("csp", "ocio")]


@pytest.mark.parametrize("fmt,host", LINEAR709_CASES, ids=lambda v: str(v))
def test_linear709_display_luts(linear709_luts, object_XYZ, fmt, host):
    if host == "ffmpeg" and FFMPEG is None:
        pytest.skip("ffmpeg not installed (Debian package ffmpeg)")
    code = DEFAULT_HOSTS[host](linear709_luts[fmt], colour_science_rgb(object_XYZ, "ITU-R BT.709"))
    dE = _dE(code, object_XYZ, "sRGB")
    inside = clip.in_gamut(colorimetry.XYZ_to_RGB(object_XYZ, "sRGB"))
    p99, worst = np.percentile(dE, 99), dE.max()
    in_p99, in_max = np.percentile(dE[inside], 99), dE[inside].max()
    print(
        f"Linear Rec.709->sRGB .{fmt} ({host}): object p99 {p99:.3f} max {worst:.3f}; "
        f"inside sRGB p99 {in_p99:.3f} max {in_max:.3f}"
    )
    assert in_p99 <= 0.5 and in_max <= 2.0
    assert p99 <= 1.5 and worst <= 4.0


# --------------------------------------------------------------------------- #
# Other inputs
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize(
    "source,name,limits",
    [
        ("ACEScg", "ACEScg", (1.0, 3.0)),  # measured 0.68 / 2.2
        ("Linear Rec.709 (sRGB)", "ITU-R BT.709", (1.2, 4.0)),  # measured 0.76 / 3.79
        ("CIE-XYZ-D65", None, (2.5, 6.0)),  # measured 1.69 / 4.45
    ],
)
def test_linear_inputs_cube(tmp_path, object_XYZ, source, name, limits):
    (path,) = export_view.export_view(source, "sRGB", CLC, tmp_path / "v.cube", size=65)
    XYZ = object_XYZ
    values = XYZ if name is None else colour_science_rgb(XYZ, name)
    if source == "ACEScg":
        keep = (values >= 0).all(axis=1)
        XYZ, values = XYZ[keep], values[keep]
    mean, p99, worst = _stats(_dE(_colour_apply([path], values), XYZ, "sRGB"))
    print(f"{source}->sRGB .cube (colour-science): mean {mean:.3f} p99 {p99:.3f} max {worst:.3f}")
    assert p99 <= limits[0] and worst <= limits[1]


def test_thin_film_input_is_a_1d_lut_over_thickness(tmp_path):
    """Thickness in um in, sRGB code values out: against the analytic film colour
    clipped analytically."""
    (path,) = export_view.export_view(
        "Thin Film Phase-Change Thickness", "sRGB", CLC, tmp_path / "f.cube"
    )
    assert "LUT_1D_INPUT_RANGE 0.000000 1.500000" in path.read_text()
    t = np.linspace(0.0, 1.5, 1501)
    XYZ = colorimetry.film_XYZ(t * 1000.0, "phase-change")
    for apply in (_colour_apply, apply_lut_files):
        code = apply([path], np.repeat(t[:, None], 3, axis=1))
        mean, p99, worst = _stats(_dE(code, XYZ, "sRGB"))
        print(f"thin film ->sRGB 1D .cube: mean {mean:.3f} p99 {p99:.3f} max {worst:.3f}")
        assert worst <= 0.8  # measured 0.52: the config's film table and clip LUT


def test_channel_clamp_clf_is_the_exact_chain(tmp_path, object_XYZ):
    (path,) = export_view.export_view(
        "Linear Rec.709 (sRGB)", "Display P3", "Channel Clamp", tmp_path / "c.clf"
    )
    text = path.read_text()
    assert "<LUT3D" not in text and "<InputDescriptor>" in text
    code = apply_lut_files([path], colour_science_rgb(object_XYZ, "ITU-R BT.709"))
    assert _dE(code, object_XYZ, "Display P3", "Channel Clamp").max() < 0.01


def test_ctf_holds_the_exact_constant_lightness_chain(tmp_path, inside_AP1):
    XYZ, cct = inside_AP1
    (path,) = export_view.export_view("ACEScct", "sRGB", CLC, tmp_path / "v.ctf")
    assert "FixedFunction" in path.read_text()
    dE = _dE(apply_lut_files([path], cct), XYZ, "sRGB")
    assert np.percentile(dE, 99) <= 0.6 and dE.max() <= 2.0  # the config's own clip LUTs


# --------------------------------------------------------------------------- #
# Errors
# --------------------------------------------------------------------------- #
BAD_VIEW = [  # (argv, what the one-line error says)
    (["export", "view", "--display", "sRGB", "--view", CLC], "--from is needed"),
    (
        ["export", "view", "--from", "Nope", "--display", "sRGB", "--view", CLC],
        "--from must be one of (",
    ),
    (["export", "view", "--from", "ACEScct", "--view", CLC], "--display is needed"),
    (
        ["export", "view", "--from", "ACEScct", "--display", "sRGB", "--view", "Nope"],
        "--view must be one of (",
    ),
    (
        [
            "export",
            "view",
            "--from",
            "ACEScct",
            "--display",
            "sRGB",
            "--view",
            CLC,
            "--format",
            "spi1d",
        ],
        "needs a 3D LUT",
    ),
    (
        [
            "export",
            "view",
            "--from",
            "Thin Film Morpho Iridescence",
            "--display",
            "sRGB",
            "--view",
            CLC,
            "--format",
            "csp",
        ],
        "a 1D LUT",
    ),
    (
        [
            "export",
            "view",
            "--from",
            "ACEScct",
            "--display",
            "sRGB",
            "--view",
            CLC,
            "--size",
            "1000",
        ],
        "--size must be in [2, ",
    ),
    (
        [
            "export",
            "view",
            "--from",
            "ACEScct",
            "--display",
            "sRGB",
            "--view",
            CLC,
            "--range",
            "0",
            "2",
        ],
        "--range applies to the thin-film inputs only",
    ),
    (
        [
            "export",
            "view",
            "--from",
            "Thin Film Morpho Iridescence",
            "--display",
            "sRGB",
            "--view",
            CLC,
            "--resolve-shaper",
        ],
        "--resolve-shaper applies to 3D LUTs",
    ),
]


@pytest.mark.parametrize(
    "argv, says", BAD_VIEW, ids=lambda a: " ".join(a[2:]) if isinstance(a, list) else ""
)
def test_bad_view_arguments(argv, says, tmp_path, capsys):
    out = tmp_path / "out" / ("x" if "--format" in argv else "x.cube")
    assert cli.main(argv + ["--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and err.startswith("ocio-thinfilm export view: error: "), err
    assert says in err, err
    assert list(tmp_path.rglob("*")) == []


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        (dict(source=None), "source is needed"),
        (dict(display=None), "display is needed"),
        (dict(view=None), "view is needed"),
        (dict(size=1000), "size must be in [2, "),
        (dict(value_range=(0.0, 2.0)), "value_range applies to the thin-film inputs only"),
        (dict(fmt="spi3d", shaper=True, out="v.spi3d"), "shaper applies to .cube files"),
        (dict(out="v.lut"), "fmt is needed: no format can be told from 'v.lut'"),
    ],
)
def test_the_library_names_its_parameters(kwargs, parameter, tmp_path, monkeypatch):
    """Reference: the parameter names of export_view's signature."""
    monkeypatch.chdir(tmp_path)
    call = dict(source="ACEScct", display="sRGB", view=CLC, out="v.cube") | kwargs
    with pytest.raises(ValueError) as raised:
        export_view.export_view(
            call.pop("source"), call.pop("display"), call.pop("view"), call.pop("out"), **call
        )
    assert str(raised.value).startswith(parameter) and "--" not in str(raised.value)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "kwargs",
    [
        dict(size="9"),
        dict(size=9.0),
        dict(source="Thin Film Phase-Change Thickness", value_range=("0", "1")),
    ],
)
def test_arguments_of_the_wrong_type_are_type_errors(kwargs, tmp_path):
    call = dict(source="ACEScct", display="sRGB", view=CLC) | kwargs
    with pytest.raises(TypeError, match=f"^{'size' if 'size' in kwargs else 'value_range'} "):
        export_view.export_view(
            call.pop("source"), call.pop("display"), call.pop("view"), tmp_path / "v.cube", **call
        )
    assert list(tmp_path.iterdir()) == []


def test_cli_export_view_writes_file(tmp_path, capsys):
    out = tmp_path / "v.csp"
    assert (
        cli.main(
            [
                "export",
                "view",
                "--from",
                "ACEScg",
                "--display",
                "Rec.2020",
                "--view",
                CLC,
                "--size",
                "9",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    assert "wrote" in capsys.readouterr().out
    assert out.read_text().startswith("CSPLUTV100")


# --------------------------------------------------------------------------- #
# HDR displays: ACEScct -> Rec.2100-PQ (and the other HDR displays)
# --------------------------------------------------------------------------- #
HDR_K = 1000.0 / 203.0


def _hdr_dE(code, XYZ, display):
    """dE2000 of an HDR display LUT's codes (decoded with colour-science's ST 2084 /
    BT.2100 HLG EOTF, Y = 1 at 203 cd/m2) against the analytic clip scaled into the
    PQ volume, k clip(X / k), relative to the peak white (as test_hdr.py and the SDR
    files' dE2000 relative to their white)."""
    import colour

    from ocio_thinfilm import registry

    entry = registry.as_display(display)
    code = np.asarray(code, dtype=np.float64)
    nits = (
        colour.models.eotf_ST2084(code)
        if entry.transfer == "PQ"
        else colour.models.eotf_BT2100_HLG(code, L_B=0.0, L_W=1000.0)
    )
    got = colorimetry.RGB_to_XYZ(nits / 203.0, entry.gamut.name)
    return colorimetry.delta_E2000(got / HDR_K, clip.clip_XYZ(XYZ / HDR_K, entry.gamut.name))


@pytest.fixture(scope="module")
def hdr_luts(tmp_path_factory):
    d = tmp_path_factory.mktemp("hdr")
    files = {}
    for display in ("Rec.2100-PQ", "P3-D65 PQ"):
        stem = display.replace(" ", "").replace(".", "")
        for fmt in ("cube", "csp"):
            files[display, fmt] = export_view.export_view(
                "ACEScct", display, CLC, d / f"{stem}.{fmt}"
            )
        files[display, "cube-resolve"] = export_view.export_view(
            "ACEScct", display, CLC, d / f"{stem}-resolve.cube", shaper=True
        )
    return files


#: Measured on object colours inside AP1 and the same colours at 1000 / 203 (highlights
#: up to the 1000 cd/m2 peak), dE2000 relative to the peak white, p99 / max: Resolve
#: .cube (colour-science) Rec.2100-PQ 0.15 / 2.35, P3-D65 PQ 0.51 / 2.12; .csp (OCIO)
#: 0.14 / 2.09 and 0.39 / 1.78; held to the SDR files' targets (p99 1.0, max 3.0). The
#: plain .cube (a grid uniform in ACEScct, cells 0.27 stops wide at the peak where the
#: clip bends everything towards the peak white): 2.28 / 9.94 and 3.19 / 10.62 (diffuse
#: colours 0.06-0.15 / 0.9-1.5, highlights 3.5-4.9 / 9.9-10.6), held to the SDR plain
#: files' limits.
HDR_LIMITS = {"cube-resolve": (1.0, 3.0), "csp": (1.0, 3.0), "cube": (5.5, 12.0)}


@pytest.mark.parametrize("display", ["Rec.2100-PQ", "P3-D65 PQ"])
@pytest.mark.parametrize(
    "fmt, consumer",
    [("cube-resolve", "colour"), ("csp", "ocio"), ("cube", "ocio"), ("cube", "colour")],
)
def test_acescct_hdr_view_luts(hdr_luts, inside_AP1, display, fmt, consumer):
    """ACEScct -> an HDR display: the file's codes, applied by colour-science or OCIO
    and decoded with colour-science's ST 2084 EOTF, against the analytic clip scaled
    into the 1000 cd/m2 volume; in-gamut greys keep 203 Y cd/m2."""
    import colour

    from ocio_thinfilm import registry

    XYZ, cct = inside_AP1
    XYZ = np.vstack([XYZ, XYZ * HDR_K])
    cct = np.vstack(
        [cct, colour.models.log_encoding_ACEScct(colour_science_rgb(XYZ[len(cct) :], "ACEScg"))]
    )
    (path,) = hdr_luts[display, fmt]
    if fmt == "cube":
        assert 'TITLE "ACEScct to ' + display in path.read_text().splitlines()[0]
    apply = (
        _colour_tetrahedral
        if (fmt, consumer) == ("cube", "colour")
        else (
            (lambda p, v: _colour_apply([p], v))
            if consumer == "colour"
            else (lambda p, v: apply_lut_files([p], v))
        )
    )
    dE = _hdr_dE(apply(path, cct), XYZ, display)
    mean, p99, worst = _stats(dE)
    n = len(dE) // 2
    print(
        f"ACEScct->{display} .{fmt} ({consumer}): mean {mean:.3f} p99 {p99:.3f} "
        f"max {worst:.3f} (diffuse p99 {np.percentile(dE[:n], 99):.3f} max "
        f"{dE[:n].max():.3f}; highlights p99 {np.percentile(dE[n:], 99):.3f} max "
        f"{dE[n:].max():.3f})"
    )
    assert p99 <= HDR_LIMITS[fmt][0] and worst <= HDR_LIMITS[fmt][1]
    # grey ramp up to the peak: neutral, at 203 Y cd/m2 (dE2000 relative to the peak, as
    # the SDR files' grey ramp relative to their white)
    g = np.array([0.002, 0.01, 0.05, 0.18, 0.5, 1.0, 2.0, 4.0, 4.9])
    code = apply(path, np.repeat(colour_acescct(g)[:, None], 3, axis=1))
    white = colorimetry.RGB_to_XYZ(np.ones(3), registry.as_display(display).colorimetry)
    assert _hdr_dE(code, g[:, None] * white, display).max() <= 0.5


@pytest.mark.skipif(FFMPEG is None, reason="ffmpeg not installed (Debian package ffmpeg)")
def test_acescct_hdr_csp_in_ffmpeg(hdr_luts, inside_AP1):
    XYZ, cct = inside_AP1
    (path,) = hdr_luts["Rec.2100-PQ", "csp"]
    mean, p99, worst = _stats(_hdr_dE(ffmpeg_apply(path, cct), XYZ, "Rec.2100-PQ"))
    print(f"ACEScct->Rec.2100-PQ .csp (ffmpeg): mean {mean:.3f} p99 {p99:.3f} max {worst:.3f}")
    assert p99 <= 1.0 and worst <= 3.0


def test_documented_fit_table_comes_from_the_benchmark(load_benchmark, marked):
    """docs/gamut_map.md's table of the fitted plain .cube over the inside-gamut weight
    is what benchmarks/bench_view_fit.py renders from reports/bench_view_fit.json, and
    its shipped row is the weight the package uses."""
    import json

    from ocio_thinfilm.export import view_fit

    root = Path(__file__).resolve().parents[1]
    bench = load_benchmark("bench_view_fit")
    result = json.loads((root / "reports" / "bench_view_fit.json").read_text())
    doc = (root / "docs" / "gamut_map.md").read_text()
    assert marked(doc, bench.BEGIN, bench.END) == bench.docs_markdown(result)
    assert view_fit.INSIDE_WEIGHT in [row["weight"] for row in result["rows"]]

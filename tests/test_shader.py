"""The views' map as code (``ocio-thinfilm export shader``): GLSL on the headless Mesa
context and DCTL compiled as C++, held to the double-precision analytic view.

The truth is :func:`evaluation.shaders.analytic_view`: the input decoded by
colour-science, the analytic map (``colour.clip.clip_XYZ``,
``colour.compress.compress_XYZ``), the display encoding by colour-science's transfer
functions. The shaders run in float32 on the same float32 inputs. What no test here
covers (a real DaVinci Resolve, Flame, Baselight, a browser's WebGL other than
Chromium's): docs/shaders.md.
"""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

from evaluation.colours import gamut_map_sets
from evaluation.shaders import (
    DctlView,
    GlslView,
    analytic_inverse_view,
    analytic_view,
    source_values,
)
from evaluation.views import EXTREME_XYZ, apply_view
from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.cli.main import main
from ocio_thinfilm.export import shader
from ocio_thinfilm.lut.options import MapOptions

#: The target: float32 code values within 1e-3 (0.26 / 255) of the analytic view.
TOLERANCE = 1e-3
CLIP, COMPRESS = shader.SHADER_VIEWS
#: Knobs other than the defaults the compression is checked with.
OTHER_KNOBS = [(0.6, 1.5), (0.9, 1.05), (0.3, 3.0)]


def _one_per_encoding() -> list[str]:
    """The first display of each encoding of the registry (each SDR encoding, PQ, HLG):
    where a test samples displays to save time, every encoding's code still runs."""
    first: dict = {}
    for d in registry.ALL_DISPLAY_LIST:
        first.setdefault(d.transfer if d.hdr else d.encoding, d.name)
    return list(first.values())


ENCODING_DISPLAYS = _one_per_encoding()

#: Where an input space on a display misses the 1e-3 target (the bound reached, the test
#: xfails above 1e-3), measured once sampling every encoding: the clip of the sRGB
#: texture space on Rec.2020 (BT.1886's pure 2.4 power near black) 1.22e-3, of Apple Log
#: on Rec.2100-PQ 1.23e-3 (the object and AP0 sets, GLSL and DCTL alike).
DECODING_REACHED = {
    ("Rec.2020", registry.TEXTURE_SPACE): 1.3e-3,
    ("Rec.2100-PQ", "Apple Log Rec.2020"): 1.3e-3,
}


@pytest.fixture(scope="module")
def sets():
    return gamut_map_sets()


_BUILT: dict = {}


def _view(lang, display, view, source=registry.REFERENCE, version="330", inverse=False):
    """The exported shader, compiled once per module run (GLSL: the view's function or
    its inverse; the DCTL has both, its Invert check box picks)."""
    key = (lang, display, view, source, version, inverse and lang == "glsl")
    if key not in _BUILT:
        text = shader.shader_source(lang, display, view, source)
        function = "ocio_thinfilm_view_inverse" if inverse else "ocio_thinfilm_view"
        _BUILT[key] = (
            GlslView(text, version, function=function) if lang == "glsl" else DctlView(text)
        )
    return _BUILT[key]


@pytest.fixture(params=["glsl", "dctl"])
def lang(request):
    request.getfixturevalue("gl" if request.param == "glsl" else "cxx")
    return request.param


def _truth(values, source, display, view, knobs=(0.8, 1.3)):
    with warnings.catch_warnings():  # colour-science's HLG evaluates log(<0) in a masked branch
        warnings.simplefilter("ignore", RuntimeWarning)
        return analytic_view(values, source, display, view, *knobs)


@pytest.mark.parametrize("view", shader.SHADER_VIEWS)
@pytest.mark.parametrize("display", registry.ALL_DISPLAYS)
def test_the_code_is_the_analytic_view_on_every_test_set(lang, display, view, sets):
    """Object, monochromatic, random-AP0 and spectral-mixture colours (scaled into an
    HDR display's volume), default knobs and others: within 1e-3 code values."""
    code = _view(lang, display, view)
    scale = registry.as_display(display).scale
    knob_sets = [(0.8, 1.3)] + (OTHER_KNOBS if view == COMPRESS else [])
    worst = {}
    for knobs in knob_sets:
        for name, XYZ in sets.items():
            x = (XYZ * scale).astype(np.float32)
            got = code.apply(x, *knobs)
            worst[knobs, name] = float(
                np.abs(got - _truth(x, registry.REFERENCE, display, view, knobs)).max()
            )
    print({k: round(v * 1e3, 4) for k, v in worst.items()}, "(1e-3 code values)")
    assert max(worst.values()) <= TOLERANCE


@pytest.mark.parametrize("source", shader.SHADER_SOURCES[1:])
@pytest.mark.parametrize("display", ENCODING_DISPLAYS)
def test_every_input_space_is_decoded_exactly(lang, source, display, sets):
    """The scene-linear spaces, the log spaces (every encoded space of the registry) and
    the texture space: the same sets as values of the input space (colour-science
    encodes each log space with the function its registry curve names), both views."""
    scale = registry.as_display(display).scale
    reached = DECODING_REACHED.get((display, source), TOLERANCE)
    worst = 0.0
    for view in shader.SHADER_VIEWS:
        code = _view(lang, display, view, source)
        for name, XYZ in sets.items():
            texture = source == "sRGB - Texture"  # SDR content: not scaled into HDR
            v = source_values(XYZ * (1.0 if texture else scale), source).astype(np.float32)
            if texture:
                # texture codes of [0, 1] and a little beyond: far outside it the sRGB
                # curve's linear segment is extrapolated, by colour-science with IEC
                # 61966-2-1's rounded slope 12.92 and by OCIO (the config, the code) with
                # the continuous 12.923 (a relative 2e-4, 2e-3 code values at codes of -200)
                v = v[((v >= -0.05) & (v <= 1.05)).all(axis=1)]
            err = float(np.abs(code.apply(v) - _truth(v, source, display, view)).max())
            assert err <= reached, (view, name, err)
            worst = max(worst, err)
    if worst > TOLERANCE:
        pytest.xfail(f"{source} on {display}: {worst:.3g} (target {TOLERANCE})")


@pytest.mark.parametrize("view", shader.SHADER_VIEWS)
@pytest.mark.parametrize("display", registry.ALL_DISPLAYS)
def test_glsl_es_300_compiles_and_agrees(gl, display, view, sets):
    """The same file as GLSL ES 3.00 (precision highp float): the same results."""
    es = _view("glsl", display, view, "ACEScct", version="es300")
    desktop = _view("glsl", display, view, "ACEScct")
    v = source_values(sets["mixtures"], "ACEScct").astype(np.float32)
    assert np.abs(es.apply(v) - desktop.apply(v)).max() <= 1e-6


_INF, _NAN = np.inf, np.nan
#: Non-finite components, alone and together.
NON_FINITE = np.array(
    [
        [_NAN, _NAN, _NAN],
        [_INF, _INF, _INF],
        [-_INF, -_INF, -_INF],
        [_NAN, 0.5, 0.5],
        [0.5, _NAN, 0.5],
        [0.3, 0.2, _NAN],
        [_INF, 0.5, 0.5],
        [-_INF, 0.5, 0.5],
        [0.5, _INF, 0.5],
        [0.5, -_INF, 0.5],
        [0.3, 0.2, _INF],
        [0.3, 0.2, -_INF],
        [_NAN, _INF, -_INF],
    ],
    dtype=np.float32,
)


def _as_the_config_limits(values):
    """NaN and -Inf as -1e6, +Inf as 1e6: what the config's Range makes of them."""
    v = np.where(np.isnan(values), -1e6, values)
    return np.clip(v, -1e6, 1e6).astype(np.float32)


@pytest.mark.parametrize("view", shader.SHADER_VIEWS)
@pytest.mark.parametrize("display", registry.ALL_DISPLAYS)
def test_every_finite_input_gives_finite_codes_and_non_finite_ones_the_config_s(
    lang, display, view, cfg
):
    """Random components of every magnitude up to 1e30 and float32's largest: finite
    codes in [0, 1]; +-Inf and NaN give what the config's view gives them (NaN and -Inf
    the lowest value, +Inf the highest), which is the analytic view of those values."""
    code = _view(lang, display, view)
    rng = np.random.default_rng(5)
    magnitude = 10.0 ** rng.uniform(-40, 30, (20000, 3))
    finite = np.concatenate(
        [EXTREME_XYZ, (magnitude * rng.choice([-1.0, 1.0], (20000, 3))).astype(np.float32)]
    )
    got = code.apply(finite)
    assert np.isfinite(got).all() and got.min() >= 0.0 and got.max() <= 1.0
    # the extreme set itself against the analytic view (float32 keeps its luminance: the
    # code takes Y from XYZ, so no cancellation between channels of 1e6)
    extreme = float(
        np.abs(
            got[: len(EXTREME_XYZ)] - _truth(EXTREME_XYZ, registry.REFERENCE, display, view)
        ).max()
    )
    print(display, view, lang, f"extreme set: {extreme:.1e} code values from the analytic view")
    assert extreme <= TOLERANCE

    got = code.apply(NON_FINITE)
    limited = _as_the_config_limits(NON_FINITE)
    np.testing.assert_array_equal(got, code.apply(limited))
    assert np.abs(got - _truth(limited, registry.REFERENCE, display, view)).max() <= TOLERANCE
    config = apply_view(cfg, display, NON_FINITE, view=view)
    np.testing.assert_allclose(config, apply_view(cfg, display, limited, view=view), atol=1e-3)
    # all-NaN / all -Inf: black, all +Inf: the peak white, as the config's view (whose
    # LUTs put that white 1.5e-4 below 1 in one channel)
    np.testing.assert_allclose(got[:3], config[:3], atol=1e-3)


def test_glsl_uniforms_left_unset_or_invalid_give_the_exported_knobs(gl, sets):
    text = shader.shader_source(
        "glsl", "sRGB", COMPRESS, options=MapOptions(compress_threshold=0.6, compress_limit=1.5)
    )
    assert "uniform float ocio_thinfilm_threshold;" in text
    assert "uniform float ocio_thinfilm_limit;" in text
    assert not re.search(r"^\s*#\s*version", text, re.M)
    code = GlslView(text)
    try:
        x = sets["monochromatic"].astype(np.float32)
        exported = _truth(x, registry.REFERENCE, "sRGB", COMPRESS, (0.6, 1.5))
        for knobs in [(0.0, 0.0), (1.2, 1.5), (0.6, 0.9), (0.6, 1e9), (_NAN, 1.5)]:
            assert np.abs(code.apply(x, *knobs) - exported).max() <= TOLERANCE, knobs
        other = code.apply(x, 0.8, 1.3)
        assert np.abs(other - _truth(x, registry.REFERENCE, "sRGB", COMPRESS)).max() <= TOLERANCE
        assert np.abs(other - exported).max() > 0.05  # the knobs do move colours
    finally:
        code.release()


def test_dctl_sliders_and_built_ins(cxx):
    text = shader.shader_source(
        "dctl", "Rec.2100-PQ", COMPRESS, "ACEScct", options=MapOptions(compress_threshold=0.7)
    )
    assert (
        "__DEVICE__ float3 transform(int p_Width, int p_Height, int p_X, int p_Y, "
        "float p_R, float p_G, float p_B)" in text
    )
    assert "DEFINE_UI_PARAMS(ocio_thinfilm_invert, Invert, DCTLUI_CHECK_BOX, 0)" in text
    sliders = DctlView(text).sliders()
    assert set(sliders) == {"Threshold", "Limit"}
    assert sliders["Threshold"][0] == pytest.approx(0.7) and sliders["Limit"][0] == pytest.approx(
        1.3
    )
    lo, hi = sliders["Threshold"][1:3]
    assert 0.0 < lo < hi < 1.0
    assert sliders["Limit"][1] > 1.0
    # DCTL's documented math built-ins (DaVinci Resolve's DCTL reference, section 8) are
    # the only calls of names that start with an underscore; every float literal ends in f
    documented = {
        "_fabs",
        "_powf",
        "_logf",
        "_log2f",
        "_log10f",
        "_expf",
        "_exp2f",
        "_exp10f",
        "_copysignf",
        "_fmaxf",
        "_fminf",
        "_clampf",
        "_saturatef",
        "_sqrtf",
        "_ceilf",
        "_floorf",
        "_truncf",
        "_round",
        "_fmod",
        "_hypotf",
    }
    code = "\n".join(
        line.split("//")[0] for line in text.splitlines() if not line.startswith("DEFINE_UI")
    )
    assert set(re.findall(r"\b(_\w+)\s*\(", code)) <= documented
    assert not re.findall(r"\b\d+\.\d+(?:e[-+]?\d+)?(?![\w.])", code)
    clip_text = shader.shader_source("dctl", "sRGB", CLIP)
    assert "DCTLUI_SLIDER_FLOAT" not in clip_text and "uniform" not in shader.shader_source(
        "glsl", "sRGB", CLIP
    )


def test_knobs_move_the_dctl_as_they_move_the_map(cxx, sets):
    code = _view("dctl", "Display P3", COMPRESS)
    x = sets["mixtures"].astype(np.float32)
    for knobs in OTHER_KNOBS:
        assert (
            np.abs(
                code.apply(x, *knobs) - _truth(x, registry.REFERENCE, "Display P3", COMPRESS, knobs)
            ).max()
            <= TOLERANCE
        )


#: The inverse's target: the preimage within this ΔE2000 of the analytic one (relative to
#: the display's peak white). Measured: <= 0.005, and 0.031 back to sRGB - Texture for
#: wide-gamut colours, whose negative texture codes colour-science and OCIO extend with
#: the sRGB curve's slopes 12.92 and 12.923 (the code follows OCIO).
INVERSE_TOLERANCE = 0.05


@pytest.mark.parametrize("view", shader.SHADER_VIEWS)
@pytest.mark.parametrize("display", registry.ALL_DISPLAYS)
def test_the_inverse_is_the_analytic_inverse(lang, display, view):
    """Display code values -> the input space (GLSL ``ocio_thinfilm_view_inverse``, the
    DCTL's Invert check box): the colour the view maps onto each code, compared in
    CIE XYZ with ΔE2000; and the view of it gives the code back."""
    from evaluation.shaders import _to_XYZ
    from ocio_thinfilm.colour import colorimetry

    entry = registry.as_display(display)
    rng = np.random.default_rng(11)
    codes = rng.uniform(0.0, 1.0, (20000, 3))
    if entry.hdr and entry.transfer == "PQ":  # the display's volume: up to the peak's code
        codes *= _truth(
            [[0.95047 * entry.scale, entry.scale, 1.08883 * entry.scale]],
            registry.REFERENCE,
            display,
            CLIP,
        )[0, 1]
    codes = codes.astype(np.float32)
    worst = {}
    for source in (registry.REFERENCE, *registry.ENCODED_SPACES, "sRGB - Texture"):
        inverse = _view(lang, display, view, source, inverse=True)
        for knobs in [(0.8, 1.3)] + (OTHER_KNOBS[:1] if view == COMPRESS else []):
            got = inverse.apply(codes, *knobs, **({"invert": True} if lang == "dctl" else {}))
            assert np.isfinite(got).all()
            truth = analytic_inverse_view(codes, source, display, view, *knobs)
            de = colorimetry.delta_E2000(
                _to_XYZ(got, source) / entry.scale, _to_XYZ(truth, source) / entry.scale
            )
            worst[source, knobs] = float(de.max())
            if source == registry.REFERENCE:
                again = _truth(got, source, display, view, knobs)
                # well inside the range: the view gives the code back
                inside = (codes > 0.05).all(axis=1) & (codes < 0.7).all(axis=1)
                assert np.abs(again - codes)[inside].max() <= TOLERANCE
    print({k: round(v, 4) for k, v in worst.items()}, "(ΔE2000)")
    assert max(worst.values()) <= INVERSE_TOLERANCE


@pytest.mark.parametrize(
    "kwargs, parameter",
    [
        (dict(lang="hlsl"), "lang"),
        (dict(display="Rec.709"), "display"),
        (dict(view="Raw"), "view"),
        (dict(source="Thin Film Morpho Iridescence"), "source"),
        (dict(source="sRGB - Display"), "source"),
        (dict(compress_threshold=0.0), "compress_threshold"),
        (dict(compress_threshold=1.0), "compress_threshold"),
        (dict(compress_limit=1.0), "compress_limit"),
        (dict(compress_limit=float("nan")), "compress_limit"),
        (dict(compress_limit=shader.KNOB_LIMIT_MAX * 2), "compress_limit"),
    ],
)
def test_library_refuses_bad_arguments_naming_them(kwargs, parameter):
    args = dict(lang="glsl", display="sRGB", view=COMPRESS, source=registry.REFERENCE)
    args.update(kwargs)
    knobs = {k: args.pop(k) for k in ("compress_threshold", "compress_limit") if k in args}
    with pytest.raises(ParameterError) as info:
        options = MapOptions(**knobs)  # a knob out of any range is refused here already
        shader.shader_source(
            args["lang"], args["display"], args["view"], args["source"], options=options
        )
    assert info.value.parameter == parameter


def test_cli_writes_the_file_and_refuses_bad_options(tmp_path, capsys, cxx, sets):
    out = tmp_path / "p3.dctl"
    argv = ["export", "shader", "--lang", "dctl", "--display", "Display P3", "--view", COMPRESS]
    assert (
        main(argv + ["--compress-threshold", "0.6", "--compress-limit", "1.5", "--out", str(out)])
        == 0
    )
    code = DctlView(out.read_text())
    x = sets["ap0"].astype(np.float32)
    truth = _truth(x, registry.REFERENCE, "Display P3", COMPRESS, (0.6, 1.5))
    assert np.abs(code.apply(x) - truth).max() <= TOLERANCE  # the sliders' defaults
    assert code.sliders()["Threshold"][0] == pytest.approx(0.6)
    capsys.readouterr()
    for extra, option in [
        (["--compress-threshold", "1.3"], "--compress-threshold"),
        (["--compress-limit", "0.9"], "--compress-limit"),
        (["--compress-limit", "200"], "--compress-limit"),  # above the shaders' largest
        (["--lang", "hlsl"], "--lang"),
        (["--size", "33"], "--size"),
        (["--from", "Thin Film Phase-Change Thickness"], "--from"),
    ]:
        bad = tmp_path / "bad.dctl"
        assert main(argv + extra + ["--out", str(bad)]) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1 and option in err, err
        assert not bad.exists()
    assert (
        main(
            [
                "export",
                "view",
                "--lang",
                "glsl",
                "--display",
                "sRGB",
                "--view",
                CLIP,
                "--from",
                "ACEScct",
                "--out",
                str(tmp_path / "v.cube"),
            ]
        )
        == 2
    )
    assert "--lang" in capsys.readouterr().err


@pytest.mark.parametrize("display", ENCODING_DISPLAYS)
def test_the_dctl_stays_exact_under_fast_math(cxx, display, sets):
    """GPU compilers may treat DCTL arithmetic as fast-math (reassociation, approximate
    reciprocals, no NaN): built with g++ -O3 -ffast-math the code still holds the
    analytic view within 1e-3 on the test sets and gives finite codes in [0, 1] for
    finite input of any size. What NaN and Inf give there is printed, not asserted:
    fast-math assumes they never come (docs/shaders.md)."""
    scale = registry.as_display(display).scale
    for view in shader.SHADER_VIEWS:
        code = DctlView(shader.shader_source("dctl", display, view), flags=("-O3", "-ffast-math"))
        try:
            worst = 0.0
            for XYZ in sets.values():
                x = (XYZ * scale).astype(np.float32)
                worst = max(
                    worst,
                    float(
                        np.abs(code.apply(x) - _truth(x, registry.REFERENCE, display, view)).max()
                    ),
                )
            got = code.apply(EXTREME_XYZ)
            assert np.isfinite(got).all() and got.min() >= 0.0 and got.max() <= 1.0
            non_finite = code.apply(NON_FINITE)
            print(
                display,
                view,
                f"fast-math: {worst:.2e}; NaN/Inf rows finite in [0, 1]:",
                bool(
                    np.isfinite(non_finite).all()
                    and non_finite.min() >= 0
                    and non_finite.max() <= 1
                ),
            )
            assert worst <= TOLERANCE
        finally:
            code.release()

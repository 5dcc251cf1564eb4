"""One registry of displays, views and thin-film input spaces (ocio_thinfilm.registry)."""

from __future__ import annotations

import dataclasses
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from evaluation import truth
from evaluation.views import COMMITTED_CONFIG
from ocio_thinfilm import config, registry
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.export import files as export
from ocio_thinfilm.lut import display_transforms
from ocio_thinfilm.lut.options import MapOptions
from ocio_thinfilm.render import frames as render

ROOT = Path(__file__).resolve().parent.parent


def test_every_module_lists_the_registrys_displays_views_and_spaces():
    assert registry.DISPLAYS == tuple(d.name for d in registry.DISPLAY_LIST)
    # the clip's tables: one set per gamut, the first display with those primaries (a
    # display with an earlier one's gamut, e.g. Rec.1886 Rec.709 with sRGB's, has none)
    firsts = {}
    for d in registry.DISPLAY_LIST:
        firsts.setdefault(d.primaries, d.name)
    assert clip.DISPLAYS == registry.GAMUT_DISPLAYS == tuple(firsts.values())
    assert registry.VIEWS == tuple(v.name for v in registry.VIEW_LIST)
    assert registry.ALL_DISPLAYS == registry.DISPLAYS + registry.HDR_DISPLAYS
    assert registry.HDR_DISPLAYS == tuple(d.name for d in registry.HDR_DISPLAY_LIST)
    assert tuple(d.name for d in registry.ALL_DISPLAY_LIST) == registry.ALL_DISPLAYS
    assert [render.png_colorspace(d) for d in registry.ALL_DISPLAYS] == [
        d.png_colorspace for d in registry.ALL_DISPLAY_LIST
    ]
    small = MapOptions(clip_size=9, film_size=16, morpho_size=16)
    data = config.config_data(inline=True, options=small)
    assert [cs["name"] for cs in data.colorspaces if cs["family"] == "Thin Film"] == list(
        registry.THIN_FILM_SPACES
    )
    assert list(data.displays) == list(registry.ALL_DISPLAYS)
    assert all(
        [v["name"] for v in views] == list(registry.VIEWS) for views in data.displays.values()
    )


def test_the_baked_config_has_exactly_the_registrys_entries():
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(COMMITTED_CONFIG))
    assert tuple(cfg.getDisplays()) == registry.ALL_DISPLAYS
    for d in registry.DISPLAY_LIST + registry.HDR_DISPLAY_LIST:
        assert tuple(cfg.getViews(d.name)) == registry.VIEWS
        assert cfg.getColorSpace(d.colorspace) is not None
        for white in (False, True):
            stem = d.clip_lut_stem(white)
            assert stem == d.gamut.clip_lut_stem(white)
            assert (COMMITTED_CONFIG.parent / "luts" / f"{stem}.clf").is_file()
    # HDR displays reuse their gamut's LUT files: none of their own
    luts = {p.name for p in (COMMITTED_CONFIG.parent / "luts").iterdir()}
    assert luts == (
        {f"{d.clip_lut_stem(w)}.clf" for d in registry.DISPLAY_LIST for w in (False, True)}
        | {f"{d.compress_lut_stem(w)}.clf" for d in registry.DISPLAY_LIST for w in (False, True)}
        | {f"{s.lut_stem}.clf" for s in registry.THIN_FILM_LIST}
    )
    for s in registry.THIN_FILM_LIST:
        assert cfg.getColorSpace(s.name).getFamily() == "Thin Film"
        assert (COMMITTED_CONFIG.parent / "luts" / f"{s.lut_stem}.clf").is_file()


def test_file_stems_come_from_the_registry():
    rec2020, p3 = registry.as_display("Rec.2020"), registry.as_display("Display P3")
    assert rec2020.clip_lut_stem(True) == "ConstantLightnessClip_Rec2020_WhiteFaces"
    assert p3.clip_lut_stem() == "ConstantLightnessClip_DisplayP3_BlackFaces"
    assert registry.as_display("Rec.2100-PQ").clip_lut_stem(True) == rec2020.clip_lut_stem(True)
    assert export._stem("clip", None, "Display P3", None) == "ConstantLightnessClip_DisplayP3"
    assert registry.thin_film_space_for_kind("morpho").name == "Thin Film Morpho Iridescence"
    with pytest.raises(ValueError, match="display must be one of"):
        registry.as_display("Rec.709")


def test_displays_are_passed_as_objects_or_names():
    """``as_display`` is the one look-up by name: a registry display passes as itself, a
    name gives its display, and what is neither is refused naming the parameter."""
    from ocio_thinfilm.checks import ParameterError

    for entry in registry.ALL_DISPLAY_LIST:
        assert registry.as_display(entry) is entry
        assert registry.as_display(entry.name) is entry
        assert registry.find_display(entry.name) is entry
        assert registry.display_name(entry) == entry.name
        assert entry.gamut in registry.DISPLAY_LIST and entry.gamut.gamut is entry.gamut
        assert entry.hdr == (entry in registry.HDR_DISPLAY_LIST)
        assert entry.scale == (entry.peak / registry.HDR_REFERENCE_WHITE if entry.hdr else 1.0)
        assert entry.colorimetry == entry.gamut.colorimetry
    assert registry.find_display("ACES 1.0 - SDR Video") is None
    assert registry.display_name("anything") == "anything" and registry.display_name(None) is None
    with pytest.raises(ParameterError, match=r"^display must be one of \('sRGB', 'Display P3', "):
        registry.as_display("Rec.2100-PQ", hdr=False)
    with pytest.raises(ParameterError, match="^target must be one of") as caught:
        registry.as_display("CRT", parameter="target")
    assert caught.value.parameter == "target"
    foreign = dataclasses.replace(registry.DISPLAY_LIST[0], lut_stem="Mine")
    with pytest.raises(ParameterError, match="must be a display of the registry"):
        registry.as_display(foreign)
    with pytest.raises(TypeError, match=r"^display must be a display name \(str\) or a registry"):
        registry.as_display(3)


def test_functions_take_a_display_object_as_they_take_its_name():
    """The same transforms and LUTs whether a display comes as its object or its name."""
    import numpy as np

    from ocio_thinfilm.lut import clip_lut, ocio_ops, view_transforms

    rgb = np.random.default_rng(3).uniform(-0.2, 1.4, (200, 3))
    for entry in registry.ALL_DISPLAY_LIST:
        name = entry.name
        for view in (v.name for v in registry.VIEW_LIST if not v.raw):
            a = ocio_ops.apply(view_transforms.view_transform(entry, view, 9), rgb)
            b = ocio_ops.apply(view_transforms.view_transform(name, view, 9), rgb)
            np.testing.assert_array_equal(a, b, err_msg=f"{name} / {view}")
        assert display_transforms.display_colorspace_transform(entry) is not None
    p3 = registry.as_display("Display P3")
    assert clip_lut.clip_lut(p3, 9) is clip_lut.clip_lut("Display P3", 9)


def test_the_colorimetry_knows_the_registrys_spaces_and_kinds():
    """The registry imports nothing of the pipeline, so the names it gives the
    colorimetry are checked here: every display's RGB space and every film table's kind."""
    import colour

    for d in registry.ALL_DISPLAY_LIST:
        assert d.colorimetry in registry.RGB_COLORIMETRY
    for g in registry.GAMUT_LIST:  # each gamut names a colourspace colour-science has
        assert g.colour_science in colour.RGB_COLOURSPACES, g
        assert registry.RGB_COLORIMETRY[g.name] == g.colour_science
    assert {s.gamut for s in registry.SCENE_LINEAR_LIST} <= set(registry.GAMUT_LIST)
    for s in registry.THIN_FILM_LIST:
        assert s.kind in colorimetry.FILM_KINDS + ("morpho",)


def test_entries_are_frozen():
    with pytest.raises(dataclasses.FrozenInstanceError):
        registry.DISPLAY_LIST[0].name = "other"


@pytest.mark.parametrize(
    "attr, value, message",
    [
        ("DISPLAYS", ("sRGB", "sRGB", "Rec.2020"), "unique"),
        (
            "DISPLAY_LIST",
            registry.DISPLAY_LIST[:2]
            + (
                dataclasses.replace(
                    registry.DISPLAY_LIST[2], primaries=registry.DISPLAY_LIST[0].primaries
                ),
            ),
            "named like a gamut",
        ),
        (
            "DISPLAY_LIST",
            registry.DISPLAY_LIST[:2]
            + (dataclasses.replace(registry.DISPLAY_LIST[2], lut_stem="Rec.2020"),),
            "file-name safe",
        ),
        (
            "DISPLAY_LIST",
            registry.DISPLAY_LIST[:2]
            + (
                dataclasses.replace(
                    registry.DISPLAY_LIST[2], encoding=registry.Encoding("BT.1886", gamma=0.0)
                ),
            ),
            "encoding",
        ),
        ("VIEW_LIST", registry.VIEW_LIST[::-1], "raw view"),
        (
            "THIN_FILM_LIST",
            registry.THIN_FILM_LIST[:2]
            + (dataclasses.replace(registry.THIN_FILM_LIST[2], table="film", args=(3,)),),
            "bad table",
        ),
    ],
)
def test_validation_rejects_bad_entries(monkeypatch, attr, value, message):
    monkeypatch.setattr(registry, attr, value)
    with pytest.raises(ValueError, match=message):
        registry.validate()


def test_adding_a_display_is_one_entry(tmp_path):
    """A copy of the package with two more Display entries generates a config with those
    displays, their views, LUT files and PNG tags: Adobe RGB, a new gamut, gets clip
    tables of its own; Gamma 2.2 Rec.709, sRGB's gamut, shares sRGB's (no new files)."""
    package = tmp_path / "ocio_thinfilm"
    shutil.copytree(ROOT / "ocio_thinfilm", package, ignore=shutil.ignore_patterns("__pycache__"))
    source = (package / "registry" / "displays.py").read_text()
    anchor = "\n)\n\n_SDR = "  # the end of DISPLAY_LIST: after the displays it has
    assert source.count(anchor) == 1
    entries = (
        '    Display(name="Adobe RGB", primaries=Gamut("Adobe RGB (1998)", "Adobe RGB (1998)"), '
        'colorspace="Adobe RGB - Display", description="Adobe RGB (1998), gamma 563/256", '
        'encoding=Encoding("gamma 2.2", gamma=563 / 256), lut_stem="AdobeRGB", '
        'png_colorspace="g22_adobergb_display"),\n'
        '    Display(name="Gamma 2.2 Rec.709", primaries=SRGB_GAMUT, '
        'colorspace="Gamma 2.2 Rec.709 - Display", description="Rec.709, gamma 2.2", '
        'encoding=Encoding("gamma 2.2", gamma=2.2), lut_stem="G22Rec709", '
        'png_colorspace="g22_rec709_display"),\n'
    )
    (package / "registry" / "displays.py").write_text(
        source.replace(anchor, "\n" + entries + anchor[1:])
    )
    code = (
        "import json; from ocio_thinfilm import config, registry\n"
        "from ocio_thinfilm.colour import clip\nfrom ocio_thinfilm.render import frames as render\n"
        "from ocio_thinfilm.lut.options import MapOptions\n"
        "small = MapOptions(clip_size=9, film_size=64, morpho_size=32)\n"
        "data = config.config_data(inline=True, options=small)\n"
        "cfg = config.generate_config(data)\n"
        "print(json.dumps([list(cfg.getDisplays()), list(cfg.getViews('Adobe RGB')),\n"
        "    list(cfg.getViews('Gamma 2.2 Rec.709')), sorted(data.luts), list(clip.DISPLAYS),\n"
        "    [render.png_colorspace(n) for n in ('Adobe RGB', 'Gamma 2.2 Rec.709')],\n"
        "    registry.as_display('Gamma 2.2 Rec.709').clip_lut_stem(),\n"
        "    list(registry.RGB_COLORIMETRY)]))\n"
    )
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    out = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        env=env,
        cwd=tmp_path,
        check=True,
    )
    displays, views, shared_views, luts, clip_displays, tags, stem, gamuts = json.loads(
        out.stdout.strip().splitlines()[-1]
    )
    sdr, hdr = list(registry.DISPLAYS), list(registry.HDR_DISPLAYS)
    assert displays == [*sdr, "Adobe RGB", "Gamma 2.2 Rec.709", *hdr]
    assert views == shared_views == list(registry.VIEWS)
    assert clip_displays == [*registry.GAMUT_DISPLAYS, "Adobe RGB"]
    assert "Adobe RGB (1998)" in gamuts
    own = [n for n in luts if "AdobeRGB" in n]
    assert own == [
        "ConstantLightnessClip_AdobeRGB_BlackFaces.clf",
        "ConstantLightnessClip_AdobeRGB_WhiteFaces.clf",
        "ConstantLightnessCompress_AdobeRGB_BlackFaces.clf",
        "ConstantLightnessCompress_AdobeRGB_WhiteFaces.clf",
    ]
    assert not [n for n in luts if "G22Rec709" in n]
    assert stem == "ConstantLightnessClip_sRGB_BlackFaces"
    assert tags == ["g22_adobergb_display", "g22_rec709_display"]


def test_every_stage_maps_every_view_kind_and_curve_kind():
    """Each stage's one mapping keyed by view kind or curve kind has an entry for every
    kind of the registry (a new kind fails here until each stage says what it does with
    it); a log curve itself is never a key: its fields are the code."""
    from ocio_thinfilm.colour.views import ANALYTIC_MAPS
    from ocio_thinfilm.config.data import LUT_FILE_VIEWS
    from ocio_thinfilm.config.spaces import CURVE_DECODINGS
    from ocio_thinfilm.export.shader import SHADER_MAPS
    from ocio_thinfilm.lut.view_transforms import LINEAR_VIEWS, LUT_VIEWS

    by_kind = dict(
        ANALYTIC_MAPS=ANALYTIC_MAPS,
        LINEAR_VIEWS=LINEAR_VIEWS,
        LUT_VIEWS=LUT_VIEWS,
        LUT_FILE_VIEWS=LUT_FILE_VIEWS,
        SHADER_MAPS=SHADER_MAPS,
    )
    kinds = {v.kind for v in registry.VIEW_LIST}
    assert kinds == set(registry.VIEW_KINDS)
    assert {name: sorted(m) for name, m in by_kind.items()} == {
        name: sorted(kinds) for name in by_kind
    }
    assert sorted(CURVE_DECODINGS) == sorted(registry.CURVE_KINDS)
    assert [e.curve for e in registry.ENCODED_LIST] == list(registry.LOG_CURVE_LIST)
    assert {c.kind for c in registry.LOG_CURVE_LIST} == set(registry.CURVE_KINDS)
    # the raw view has no transform anywhere; every other view has a config chain
    assert all(m["raw"] is None for m in by_kind.values())
    assert all(LINEAR_VIEWS[k] is not None for k in kinds - {"raw"})


@pytest.mark.parametrize("encoded", registry.ENCODED_LIST, ids=lambda e: e.name)
def test_every_log_curve_is_colour_sciences_curve(encoded):
    """Each encoded space against its independent truth (evaluation/truth.py): the
    colour-science functions and RGB colourspace of it exist, and the curve's published
    constants (the model every stage derives its code from) are colour-science's curve
    with the truth's arguments to 1e-12 (measured 7e-16 / 5e-15): encoding over linear -0.2..1e4,
    decoding over codes -0.1..1.1, and the code of black, which decodes to 0."""
    import colour

    from ocio_thinfilm.colour import log_curves

    curve = encoded.curve
    entry = truth.COLOUR_SCIENCE_LOGS[curve.name]
    encode, decode = entry.encode, entry.decode
    assert truth.COLOUR_SCIENCE_GAMUTS[encoded.gamut.name] in colour.RGB_COLOURSPACES
    linear = np.concatenate([np.linspace(-0.2, 2.0, 20001), np.geomspace(2.0, 1e4, 2001)])
    linear = linear[linear > (curve.toe_origin if curve.kind == "quadratic-toe" else -1.0)]
    with np.errstate(invalid="ignore", divide="ignore"):
        expected = encode(linear)
    np.testing.assert_allclose(log_curves.encode(curve, linear), expected, rtol=0, atol=1e-12)
    codes = np.linspace(-0.1, 1.1, 24001)
    codes = codes[codes >= 0.0] if curve.kind == "quadratic-toe" else codes
    with np.errstate(over="ignore", invalid="ignore"):
        expected = decode(codes)
    got = log_curves.decode(curve, codes)
    np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-12)
    # black: the published code is colour-science's, and decodes to 0 exactly
    assert encode(0.0) == pytest.approx(curve.black, abs=1e-12)
    assert float(log_curves.decode(curve, curve.black)) == pytest.approx(0.0, abs=1e-15)
    for x in (0.0, 0.18, 1.0):  # the scalar model too
        assert curve.encode_one(x) == pytest.approx(float(encode(x)), abs=1e-12)


def test_a_curve_breaking_its_models_assumptions_is_refused_at_import():
    """A curve's assumptions are checked when it is made: V-Log's published toe misses
    its log part by 3.1e-7 (refused at a tighter continuity), a wrong black, a mirrored
    curve whose toe misses black, an unknown kind."""
    v_log = registry.find_curve("Panasonic V-Log")
    assert abs(v_log.gap + 3.11e-7) < 1e-9 and v_log.toe_intercept == 0.125
    with pytest.raises(ValueError, match="meet -3.11e-07 apart"):
        dataclasses.replace(v_log, continuity=1e-7)
    with pytest.raises(ValueError, match="black encodes to 0.125, not 0.126"):
        dataclasses.replace(v_log, black=0.126)
    clog3 = registry.find_curve("Canon Log 3")
    with pytest.raises(ValueError, match="toe passes through"):
        dataclasses.replace(clog3, toe_offset=0.13)
    with pytest.raises(ValueError, match="kind must be one of"):
        dataclasses.replace(v_log, kind="cubic")
    # derived from continuity (None), the toe meets the log part: no gap
    derived = dataclasses.replace(v_log, toe_offset=None, black=v_log.encode_one(0.0) - 3.1e-7)
    assert derived.gap == 0.0 and derived.toe_intercept == pytest.approx(0.125 - 3.11e-7)


#: The registry's constants that hold one view's or one colour space's name.
NAME_CONSTANTS = {"CLIP_VIEW", "COMPRESS_VIEW", "REFERENCE", "TEXTURE_SPACE", "RAW_SPACE"}


def _named_literals(path: Path, names: set[str]) -> list[str]:
    """``line: name`` of each comparison with, or dict key of, a string in ``names``, and
    of each comparison with a registry constant of :data:`NAME_CONSTANTS` (``view ==
    registry.COMPRESS_VIEW`` picks by name as much as ``view == "..."`` does)."""
    import ast

    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        operands: list[ast.expr] = []
        if isinstance(node, ast.Compare):
            operands = [node.left, *node.comparators]
            operands += [
                e for o in operands if isinstance(o, (ast.Tuple, ast.List, ast.Set)) for e in o.elts
            ]
            found += [
                f"{o.lineno}: registry.{o.attr}"
                for o in operands
                if isinstance(o, ast.Attribute)
                and o.attr in NAME_CONSTANTS
                and isinstance(o.value, ast.Name)
                and o.value.id == "registry"
            ]
        elif isinstance(node, ast.Dict):
            operands = [k for k in node.keys if k is not None]
        found += [
            f"{o.lineno}: {o.value}"
            for o in operands
            if isinstance(o, ast.Constant) and isinstance(o.value, str) and o.value in names
        ]
    return found


def test_no_view_or_space_is_picked_by_its_name_outside_the_registry(tmp_path):
    """Behaviour comes from a view's kind, a colour space's kind
    (:func:`ocio_thinfilm.registry.space_kind`) and an encoded space's curve: no module of
    the package (``cli/`` included) compares a view's or a colour space's name with a
    string literal or with a registry constant holding one, or keys a dict by one (the
    check can fail: copies of such comparisons are found)."""
    names = (
        set(registry.VIEWS)
        | set(registry.LOG_CURVES)
        | set(registry.ENCODED_SPACES)
        | set(registry.SCENE_LINEAR_SPACES)
        | set(registry.THIN_FILM_SPACES)
        | {registry.REFERENCE, registry.TEXTURE_SPACE, registry.RAW_SPACE}
    )
    package = ROOT / "ocio_thinfilm"
    found = {
        str(p.relative_to(package)): hits
        for p in sorted(package.rglob("*.py"))
        if p.relative_to(package).parts[0] != "registry" and (hits := _named_literals(p, names))
    }
    assert found == {}
    assert (package / "cli" / "export.py") in set(package.rglob("*.py"))
    bad = tmp_path / "bad.py"
    bad.write_text(
        "def f(view, source):\n"
        '    return view == "Channel Clamp" or {"Raw": 1} or source == "CIE-XYZ-D65"\n'
        "def g(args):\n"
        "    return args.view != registry.COMPRESS_VIEW or registry.REFERENCE == args.source\n"
    )
    assert sorted(_named_literals(bad, names)) == [
        "2: CIE-XYZ-D65",
        "2: Channel Clamp",
        "2: Raw",
        "4: registry.COMPRESS_VIEW",
        "4: registry.REFERENCE",
    ]


def test_every_space_of_the_registry_has_one_kind():
    """:func:`~ocio_thinfilm.registry.space_kind` gives each colour space the registry
    names its kind, every kind is used, and other names have none."""
    expected = {
        registry.REFERENCE: "reference",
        registry.TEXTURE_SPACE: "texture",
        registry.RAW_SPACE: "raw",
        **{n: "scene-linear" for n in registry.SCENE_LINEAR_SPACES},
        **{n: "encoded" for n in registry.ENCODED_SPACES},
        **{n: "thin-film" for n in registry.THIN_FILM_SPACES},
        **{d.colorspace: "display" for d in registry.ALL_DISPLAY_LIST},
    }
    assert {n: registry.space_kind(n) for n in expected} == expected
    assert sorted(set(expected.values())) == sorted(registry.SPACE_KINDS)
    assert registry.space_kind("ACES 1.0 - SDR Video") is None
    assert registry.space_kind(None) is None  # type: ignore[arg-type]


def test_the_readme_lists_the_registrys_log_spaces():
    """README's list of the log input spaces names every encoded space of the registry."""
    text = (ROOT / "README.md").read_text()
    start = text.index("The config, `export view` and `export shader` take the camera")
    listed = text[start : text.index("\n\n", start)]
    assert [n for n in registry.ENCODED_SPACES if f"`{n}`" not in listed] == []


def test_the_config_page_lists_the_registrys_views_and_spaces():
    """docs/config.md names every view, scene-linear space and log space of the registry."""
    text = (ROOT / "docs" / "config.md").read_text()
    names = registry.VIEWS + registry.SCENE_LINEAR_SPACES + registry.ENCODED_SPACES
    assert [n for n in names if f"`{n}`" not in text] == []


def _paragraph(text: str, start: str) -> str:
    """The paragraph of ``text`` that begins with ``start``."""
    i = text.index(start)
    return text[i : text.index("\n\n", i)]


@pytest.mark.parametrize(
    ("page", "start", "kind"),
    [
        ("README.md", "`configs/thinfilm/config.ocio` (profile 2.1", "display"),
        ("docs/config.md", "| Displays |", "display"),
        ("docs/config.md", "| Display spaces |", "space"),
        ("docs/render.md", "| `--display` |", "sdr"),
        ("docs/shaders.md", "What each file holds", "display"),
    ],
)
def test_the_docs_list_every_display_of_the_registry(page, start, kind):
    """The README and the docs name every display (and display colour space) the
    registry has: a new display entry without its docs fails here."""
    listed = _paragraph((ROOT / page).read_text(), start)
    displays = registry.DISPLAY_LIST if kind == "sdr" else registry.ALL_DISPLAY_LIST
    names = [d.colorspace if kind == "space" else d.name for d in displays]
    assert [n for n in names if f"`{n}`" not in listed] == [], page

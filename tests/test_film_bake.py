"""Users' films through the baked config and the exported files, applied the way a host
applies them (OCIO processors from the written config.ocio, OCIO FileTransforms of the
written LUTs, colour-science's read_LUT, OpenImageIO's EXR reader), against the
independent transfer-matrix references of ``test_films`` (colour-science where it is
valid, PyPI tmm otherwise). Bad film files: one line, exit 2, nothing written."""

from __future__ import annotations

import numpy as np
import pytest

from evaluation.films import COLOUR_VALID, FILMS_TOML, WL, colour_R, tmm_RTA
from evaluation.films import delta_E as _delta_E
from evaluation.views import apply_processor
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.physics import films as films_module

pytest.importorskip("tmm")

KEYS = ["Soap", "OilOnWater", "Temper", "Stack", "SilicaOnGold"]
EXTRA = '\n[films.Renamed]\nstack = ["air", "water", "air"]\nname = "Water Film"\n'


@pytest.fixture(scope="module")
def film_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("films") / "films.toml"
    path.write_text(FILMS_TOML + EXTRA)
    return path


@pytest.fixture(scope="module")
def films(film_file):
    return films_module.read_films(film_file)


@pytest.fixture(scope="module")
def baked(tmp_path_factory, film_file):
    out = tmp_path_factory.mktemp("bake") / "thinfilm"
    assert cli.main(["bake", "--out", str(out), "--films", str(film_file), "--quiet"]) == 0
    return out / "config.ocio"


@pytest.fixture(scope="module")
def reference(films):
    """XYZ of each film in KEYS at 40 thicknesses (plus 10 random), from colour-science
    (1 nm) where it is valid, else from tmm (4 nm, trapezoid)."""
    import colour

    shape = colour.SpectralShape(380, 780, 1)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    w1 = cmfs.values * d65.values[:, None]
    w1 /= w1[:, 1].sum()
    out = {}
    for key in KEYS:
        film = films[key]
        rng = np.random.default_rng(3)
        t = np.concatenate([np.linspace(*film.range_um, 40), rng.uniform(*film.range_um, 10)])
        if key in COLOUR_VALID:
            XYZ = colour_R(film, t * 1000.0) @ w1
        else:
            t = t[::4]
            wl = np.arange(380.0, 781.0, 4.0)
            w = np.array([w1[np.searchsorted(WL, x)] for x in wl]) * 4.0
            w[[0, -1]] /= 2.0
            w /= w[:, 1].sum()
            XYZ = np.array([tmm_RTA(film, x * 1000.0, wl)[:, 0] for x in t]) @ w
        out[key] = (t, XYZ)
    return out


WHITE = (0.3127, 0.329)


def _grey(t):
    """Thickness values as the (N, 3) pixels of a film's colour space (all channels)."""
    return np.repeat(np.asarray(t)[:, None], 3, axis=1)


def _check(XYZ, ref):
    dE = _delta_E(XYZ, ref, np.array(WHITE))
    assert np.percentile(dE, 99) <= 0.5 and dE.max() <= 1.0, (np.percentile(dE, 99), dE.max())


@pytest.mark.parametrize("key", KEYS)
def test_baked_colour_spaces_match_the_independent_tmm(baked, films, reference, key):
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(baked))
    film = films[key]
    assert film.name == f"Thin Film {key}"
    t, ref = reference[key]
    _check(apply_processor(cfg.getProcessor(film.name, "CIE-XYZ-D65"), _grey(t)), ref)
    # and its named transform is the same table
    named = cfg.getProcessor(f"{film.name} to CIE-XYZ-D65", ocio.TRANSFORM_DIR_FORWARD)
    _check(apply_processor(named, _grey(t)), ref)


def test_a_film_name_sets_its_colour_space_and_the_rest_of_the_config_is_the_default(baked):
    import PyOpenColorIO as ocio

    cfg = ocio.Config.CreateFromFile(str(baked))
    names = list(cfg.getColorSpaceNames())
    assert "Water Film" in names and "Thin Film Renamed" not in names
    assert "Thin Film Phase-Change Thickness" in names
    text = baked.read_text()
    assert "films.toml" in text and str(baked.parent.parent) not in text  # no absolute path


@pytest.mark.parametrize("key", ["OilOnWater", "Temper"])
def test_exported_files_applied_by_ocio_and_colour_science(
    tmp_path, film_file, films, reference, key
):
    import colour
    import OpenImageIO as oiio
    import PyOpenColorIO as ocio

    out = tmp_path / "out"
    assert (
        cli.main(["export", "film", "--films", str(film_file), "--film", key, "--out", str(out)])
        == 0
    )
    stem = f"ThinFilm_User_{key}"
    t, ref = reference[key]
    for ext in ("clf", "cube", "spi1d"):
        path = out / f"{stem}.{ext}"
        ft = ocio.FileTransform(str(path), interpolation=ocio.INTERP_LINEAR)
        proc = ocio.Config.CreateRaw().getProcessor(ft)
        _check(apply_processor(proc, _grey(t)), ref)
        if ext in ("cube", "spi1d"):
            lut = colour.read_LUT(str(path))
            _check(lut.apply(np.repeat(t[:, None], 3, axis=1)), ref)
    # the ramp: texel i at lo + (i + 0.5) / width * (hi - lo), sampled as a shader does
    image = oiio.ImageBuf(str(out / f"{stem}_ramp.exr"))
    pixels = image.get_pixels(oiio.FLOAT)[0]
    lo, hi = films[key].range_um
    # (an EXR float attribute: float32)
    assert image.spec().getattribute("ocio_thinfilm:domain") == pytest.approx((lo, hi))
    u = (t - lo) / (hi - lo) * pixels.shape[0] - 0.5
    sampled = np.stack(
        [np.interp(u, np.arange(pixels.shape[0]), pixels[:, c]) for c in range(3)], axis=-1
    )
    inside = (u >= 0) & (u <= pixels.shape[0] - 1)
    _check(sampled[inside], ref[inside])


@pytest.mark.parametrize(
    "toml, message",
    [
        ('[films.A]\nstack = ["air", "Nope", "air"]', "film 'A': stack: unknown material 'Nope'"),
        ("[films.A]\nrange_um = [0, 1]", "film 'A': stack: the key is missing"),
        ('[films.A]\nstack = ["air", "water"', "films.toml:2: TOML syntax error"),
        ('[films.A]\nstack = ["air", "water", "air"]\nname = "ACEScg"', "name: 'ACEScg'"),
        ('[films.A]\nstack = ["air", "water", "air"]\nrange_um = [-1, 2]', "range_um"),
    ],
)
def test_bad_film_files_exit_2_with_one_line_and_write_nothing(tmp_path, capsys, toml, message):
    path = tmp_path / "films.toml"
    path.write_text(toml)
    out = tmp_path / "cfg"
    assert cli.main(["bake", "--out", str(out), "--films", str(path), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("ocio-thinfilm bake: error: --films ")
    assert message in err and not out.exists()
    assert cli.main(["export", "film", "--films", str(path), "--out", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("ocio-thinfilm export film: error: --films ") and message in err
    assert not (tmp_path / "x").exists()


def test_keys_that_give_one_file_name_are_named_with_the_file(tmp_path, capsys):
    """``"Oil Slick"`` and ``Oil_Slick`` would write one LUT file: one line naming both
    keys and the file, exit 2, nothing written."""
    path = tmp_path / "films.toml"
    stack = 'stack = ["air", "oil", "water"]'
    path.write_text(f'[films."Oil Slick"]\n{stack}\n[films.Oil_Slick]\n{stack}\n')
    out = tmp_path / "cfg"
    assert cli.main(["bake", "--out", str(out), "--films", str(path), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("ocio-thinfilm bake: error: --films "), err
    assert "'Oil Slick' and 'Oil_Slick'" in err and "ThinFilm_User_Oil_Slick.clf" in err, err
    assert not out.exists()


def test_a_film_key_without_its_film_file_says_films_is_missing(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert cli.main(["export", "film", "--film", "AR"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert err.startswith("ocio-thinfilm export film: error: --films FILE is missing"), err
    assert list(tmp_path.iterdir()) == []


def test_render_oil_and_soap_with_a_users_film(tmp_path, film_file, baked, capsys):
    """The oil scene through a config without the film (its table as bake --films
    writes it) and the soap scene through the config baked with it; the EXR says which
    film and what its thickness AOV is; other scenes refuse --films in one line."""
    import OpenImageIO as oiio

    out = tmp_path / "renders"
    common = ["--films", str(film_file), "--size", "64x48", "--out", str(out), "--quiet"]
    assert cli.main(["render", "oil", "--film", "OilOnWater"] + common) == 0
    exr = oiio.ImageBuf(str(out / "oil.exr"))
    spec = exr.spec()
    assert "Thin Film OilOnWater" in spec.getattribute("ocio_thinfilm:tables")
    assert "physical thickness" in spec.getattribute("ocio_thinfilm:aov:thickness")
    pixels = exr.get_pixels(oiio.FLOAT)
    assert np.all(np.isfinite(pixels)) and pixels[..., :3].min() >= 0
    config = ["--config", str(baked)]
    assert cli.main(["render", "soap", "--film", "Soap"] + common + config) == 0
    assert (out / "soap.png").is_file()
    capsys.readouterr()
    assert cli.main(["render", "morpho", "--film", "Soap"] + common) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--films applies to the oil and soap scenes" in err


def test_into_a_studio_config_a_film_name_must_not_repeat_its_names_or_aliases(tmp_path, capsys):
    path = tmp_path / "films.toml"
    path.write_text('[films.A]\nstack = ["air", "water", "air"]\nname = "Utility - Raw"\n')
    out = tmp_path / "studio"
    argv = ["bake", "--into", "ocio://studio-config-latest", "--out", str(out)]
    assert cli.main(argv + ["--films", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--films" in err and "'Utility - Raw' is already" in err
    assert not out.exists()

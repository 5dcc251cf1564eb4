"""Films' reflectance and transmittance colours from colour-science alone, and their
material tables as EXR files: the independent truth the renderer tests compare with.

Nothing here uses ``ocio_thinfilm``'s physics or colour code: the spectra are
colour-science's exact transfer-matrix method (``colour.phenomena.thin_film_tmm`` for one
layer, ``multilayer_tmm`` for a stack; s and p averaged: unpolarised light), integrated
against colour-science's CIE 1931 2 degree CMFs under one of its illuminants, and turned
into linear RGB with its RGB colourspaces (the illuminant's white adapted to the space's
white with CAT02, so the perfect reflector is RGB (1, 1, 1)).

- :class:`Stack` -- a film: incident medium, layers (one of them the varying one),
  substrate; constant or per-wavelength indices.
- :func:`film_rgb` -- R or T of a stack as RGB at (thickness, cos theta) pairs.
- :func:`table` -- the thickness x cos theta table with the material contract's
  node-centred axes (texture rows: row 0 = cos theta 0, the last row cos theta 1).
- :func:`write_table` -- that table as a float EXR with the contract's header
  (OpenImageIO; first scanline = the top = cos theta 1).
- :func:`write_film_folder` -- the tables and the Blender script of a film, laid out as
  ``export material`` lays them out.
- :func:`delta_e` -- CIE 2000 between linear BT.709 colours (colour-science).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from pathlib import Path

import numpy as np

__all__ = [
    "Stack",
    "SOAP_BUBBLE",
    "SOAP_ON_GLASS",
    "delta_e",
    "film_rgb",
    "table",
    "write_table",
    "write_film_folder",
    "COLOUR_SPACES",
]

Index = complex | float | Sequence[complex] | np.ndarray


@dataclasses.dataclass(frozen=True)
class Stack:
    """A film: ``incident`` | ``layers`` | ``substrate``, light arriving from ``incident``.

    ``layers`` are (index, thickness_nm) from the incident side; the layer at ``varying``
    has its thickness set by the table (its listed thickness is ignored). An index is a
    number (constant, ``n + ik`` for absorbing media) or an array with one value per
    wavelength used: 380 to 780 nm in steps of ``step_nm`` (:func:`film_rgb`; 81 values
    at the default 5 nm).
    """

    incident: Index
    layers: tuple[tuple[Index, float], ...]
    substrate: Index
    varying: int = 0

    @classmethod
    def single(cls, n_film: Index, n_incident: Index = 1.0, n_substrate: Index = 1.0) -> Stack:
        """One layer: ``(n_film, n_incident, n_substrate)``."""
        return cls(n_incident, ((n_film, 0.0),), n_substrate)


#: A soap film in air, free-standing (a bubble's wall): n = 1.33.
SOAP_BUBBLE = Stack.single(1.33)
#: A soap-like film (n = 1.33) on glass (n = 1.5, semi-infinite), in air: a film
#: Blender's Principled thin film describes too.
SOAP_ON_GLASS = Stack.single(1.33, 1.0, 1.5)


def _spectral(illuminant: str, step_nm: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Wavelengths (380-780 nm), CMFs * illuminant * step normalised so the perfect
    reflector has Y = 1, and the illuminant white's xy."""
    import colour

    shape = colour.SpectralShape(380, 780, step_nm)
    cmfs = colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"].copy().align(shape)
    sd = colour.SDS_ILLUMINANTS[illuminant].copy().align(shape)
    weights = cmfs.values * sd.values[:, None]
    weights /= weights[:, 1].sum()
    white_xy = colour.XYZ_to_xy(weights.sum(axis=0))
    return shape.wavelengths, weights, white_xy


def _index(n: Index, wavelengths: np.ndarray) -> np.ndarray:
    value = np.asarray(n, dtype=complex)
    return np.broadcast_to(value, wavelengths.shape) if value.ndim == 0 else value


def _spectra(stack: Stack, thickness_nm: float, cos_theta: np.ndarray, wl: np.ndarray):
    """(R, T) unpolarised, shape (A, W), of ``stack`` at one varying thickness."""
    import colour

    theta = np.degrees(np.arccos(np.clip(cos_theta, 0.0, 1.0)))
    n = [_index(stack.incident, wl)] + [_index(m, wl) for m, _ in stack.layers]
    n.append(_index(stack.substrate, wl))
    n_stack = np.array(n)
    if len(stack.layers) == 1:
        R, T = colour.phenomena.thin_film_tmm(n_stack, [thickness_nm], wl, theta)
        return R.mean(axis=-1)[:, :, 0].T, T.mean(axis=-1)[:, :, 0].T
    d = [t for _, t in stack.layers]
    d[stack.varying] = thickness_nm
    R, T = colour.phenomena.multilayer_tmm(n_stack, d, wl, theta)
    return R.mean(axis=-1).reshape(len(wl), -1).T, T.mean(axis=-1).reshape(len(wl), -1).T


def film_rgb(
    stack: Stack,
    thickness_um: np.ndarray,
    cos_theta: np.ndarray,
    *,
    quantity: str = "reflectance",
    space: str = "ITU-R BT.709",
    illuminant: str = "D65",
    step_nm: float = 5.0,
) -> np.ndarray:
    """R or T of ``stack`` as linear RGB of ``space`` at each (thickness, cos theta) pair.

    ``thickness_um`` and ``cos_theta`` broadcast together; the result has their shape
    plus a last axis of 3. Pairs are grouped by thickness (one TMM call per distinct
    thickness, all its angles at once).
    """
    import colour

    t, c = np.broadcast_arrays(np.asarray(thickness_um, float), np.asarray(cos_theta, float))
    wl, weights, white_xy = _spectral(illuminant, step_nm)
    flat_t, flat_c = t.ravel(), c.ravel()
    xyz = np.empty((flat_t.size, 3))
    which = 0 if quantity == "reflectance" else 1
    if quantity not in ("reflectance", "transmittance"):
        raise ValueError(f"quantity must be 'reflectance' or 'transmittance', got {quantity!r}")
    for value in np.unique(flat_t):
        rows = np.flatnonzero(flat_t == value)
        spectrum = _spectra(stack, 1000.0 * value, flat_c[rows], wl)[which]
        xyz[rows] = spectrum @ weights
    rgb = colour.XYZ_to_RGB(xyz, space, illuminant=white_xy, chromatic_adaptation_transform="CAT02")
    return rgb.reshape(*t.shape, 3)


def table(
    stack: Stack,
    range_um: tuple[float, float],
    width: int,
    height: int,
    **options,
) -> np.ndarray:
    """The (height, width, 3) table of :func:`film_rgb` in texture row order: column i
    at thickness ``lo + i (hi - lo) / (width - 1)``, row j at cos theta ``j / (height -
    1)`` (row 0 = grazing, the last row normal incidence), as the material contract
    samples it (node-centred)."""
    lo, hi = range_um
    t = lo + np.arange(width) * (hi - lo) / (width - 1)
    c = np.arange(height) / (height - 1)
    return film_rgb(stack, t[None, :], c[:, None], **options)


def write_table(
    path: Path,
    rgb: np.ndarray,
    *,
    key: str,
    quantity: str,
    range_um: tuple[float, float],
    space: str = "Linear Rec.709 (sRGB)",
    illuminant: str = "D65",
) -> Path:
    """Write a texture-row-order table as the contract's float EXR (first scanline =
    the top = cos theta 1), with its ``ocio_thinfilm:*`` header."""
    import OpenImageIO as oiio

    pixels = np.ascontiguousarray(rgb[::-1], dtype=np.float32)
    height, width = pixels.shape[:2]
    spec = oiio.ImageSpec(width, height, 3, oiio.FLOAT)
    spec.channelnames = ("R", "G", "B")
    attributes = {
        "film": key,
        "quantity": quantity,
        "space": space,
        "x": "thickness_um",
        "y": "cos_theta",
        "sampling": "node-centred",
        "illuminant": illuminant,
        "version": "evaluation.materials",
    }
    for name, value in attributes.items():
        spec.attribute(f"ocio_thinfilm:{name}", value)
    spec.attribute("ocio_thinfilm:x_range", oiio.TypeDesc("float[2]"), tuple(map(float, range_um)))
    spec.attribute("ocio_thinfilm:y_range", oiio.TypeDesc("float[2]"), (0.0, 1.0))
    out = oiio.ImageOutput.create(str(path))
    if out is None or not out.open(str(path), spec):
        raise OSError(f"cannot write {path}: {oiio.geterror()}")
    out.write_image(pixels)
    out.close()
    return Path(path)


#: colour-science's names of the registry's scene-linear spaces the tests render in.
COLOUR_SPACES = {
    "Linear Rec.709 (sRGB)": "ITU-R BT.709",
    "Linear Rec.2020": "ITU-R BT.2020",
    "ACEScg": "ACEScg",
}


def write_film_folder(
    folder: Path,
    stack: Stack,
    key: str,
    range_um: tuple[float, float],
    width: int,
    height: int,
    *,
    transmittance: bool = False,
    name: str | None = None,
    spaces: Sequence[str] = ("Linear Rec.709 (sRGB)",),
) -> Path:
    """Write ``ThinFilm_User_<key>_R.exr`` (and ``_T.exr``) and the Blender script
    ``ThinFilm_User_<key>.py`` (:func:`ocio_thinfilm.export.hosts.blender.blender_script`,
    the node group and material named ``name``, default ``Thin Film <key>``) into
    ``folder``; return the script's path. Further ``spaces`` (keys of
    :data:`COLOUR_SPACES`) get their own tables, ``ThinFilm_User_<key>_<Space>_R.exr``
    (the space's name without spaces or punctuation), as ``export material --space A
    --space B`` lays them out; each table's share of texels with a negative channel and
    its lowest value go into the script."""
    import re

    from ocio_thinfilm.export.hosts.blender import BlenderTables, blender_script

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    entries = []
    for i, space in enumerate(spaces):
        stem = f"ThinFilm_User_{key}" + ("" if i == 0 else "_" + re.sub(r"[^A-Za-z0-9]", "", space))
        names = {"reflectance": f"{stem}_R.exr"}
        if transmittance:
            names["transmittance"] = f"{stem}_T.exr"
        values = []
        for quantity, file_name in names.items():
            rgb = table(
                stack, range_um, width, height, quantity=quantity, space=COLOUR_SPACES[space]
            )
            write_table(
                folder / file_name, rgb, key=key, quantity=quantity, range_um=range_um, space=space
            )
            values.append(rgb.reshape(-1, 3))
        rgb = np.concatenate(values)
        outside = (float(np.mean((rgb < 0).any(axis=1))), min(float(rgb.min()), 0.0))
        entries.append(
            BlenderTables(space, names["reflectance"], names.get("transmittance"), outside)
        )
    script = folder / f"ThinFilm_User_{key}.py"
    first = entries[0]
    script.write_text(
        blender_script(
            key,
            first.reflectance,
            first.transmittance,
            range_um,
            name=name,
            space=first.space,
            outside=first.outside,
            alternates=entries[1:],
        )
    )
    return script


def delta_e(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """CIE 2000 colour difference of linear BT.709 colours (D65 white), colour-science's
    ``RGB_to_XYZ``, ``XYZ_to_Lab`` and ``delta_E``."""
    import colour

    white = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]

    def lab(rgb):
        return colour.XYZ_to_Lab(colour.RGB_to_XYZ(rgb, "ITU-R BT.709"), white)

    return colour.delta_E(lab(a), lab(b), method="CIE 2000")

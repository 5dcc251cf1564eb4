"""How the baked LUTs store their values: 16-bit codes that half-float textures keep.

The config's LUT files hold 16-bit integer codes (half the text of floats); a host that
uploads a texture as half floats (Blender's viewport) rounds them again. So every
stored value is first a half float and then the nearest 16-bit code, and the clip's
black pass (the faces through black of Smits & Meyer 1990, Section 3.2) stores its
chart coordinates in a frame where two of the three faces are exactly 0 and the third
is kept a little inside: no path (16-bit CPU values, half-float GPU textures) sees a
point outside the gamut, whose negative channel the white pass would clamp at the cost
of Y. Design and measurements: docs/gamut_map.md ("Faces that are exact on every host").

- :data:`LUT_CODE_MAX` -- the largest 16-bit code;
- :func:`q16` -- values on the 16-bit grid; :func:`half16` -- half floats, then that grid;
- :func:`grid_scale` -- the output scale that makes a Lut3D's grid values k / (n - 1)
  exact half floats (a LUT that holds the identity on part of its grid stores it
  exactly);
- :func:`face_frame` -- the stored coordinates z = sign (u - origin) of the black pass;
- :func:`halves_inside` -- points of the triangle as the nearest half floats inside it.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import reproducible

__all__ = [
    "LUT_CODE_MAX",
    "q16",
    "half16",
    "grid_scale",
    "face_frame",
    "halves_inside",
]

#: 16-bit LUT files: values are stored as codes of this maximum.
LUT_CODE_MAX = 65535


def q16(values: npt.ArrayLike) -> np.ndarray:
    """Clip ``values`` to [0, 1] and round them to the 16-bit grid.

    Float64 out, never a negative zero, whose sign -- and so a file's text -- would depend
    on the CPU.

    Examples
    --------
    >>> (q16([0.5, 1.2, -0.0]) * LUT_CODE_MAX).tolist()
    [32768.0, 65535.0, 0.0]
    """
    # + 0.0: no negative zero, whose sign (and so the file's text) depends on the CPU
    # snapped first: a value on a code's rounding boundary in exact arithmetic (0.5 is
    # 32767.5) rounds the same way whatever last bits the CPU left (ocio_thinfilm.reproducible)
    snapped = reproducible.snap(np.clip(values, 0.0, 1.0))
    return np.round(snapped * LUT_CODE_MAX) / LUT_CODE_MAX + 0.0


def half16(values: npt.ArrayLike) -> np.ndarray:
    """Round ``values`` to half floats, then to the 16-bit grid (:func:`q16`).

    What a host that uploads the 16-bit file as a half-float texture holds as well.

    Examples
    --------
    1/3 is the half float 0.333251953125, code 21839.67 -> 21840 (the code of 1/3
    itself is 21845):

    >>> float(half16(1.0 / 3.0) * LUT_CODE_MAX)
    21840.0
    """
    return q16(reproducible.snap(values).astype(np.float16).astype(np.float64))


def grid_scale(size: int) -> float:
    """Return the scale that makes a Lut3D's grid values exact half floats.

    The scale ``s = (size - 1) / 2^m`` (``2^m`` the smallest power of 2 >= size - 1)
    that makes every grid value ``k / (size - 1)`` of a Lut3D of edge ``size``, scaled,
    the exact half float ``k / 2^m`` (for ``size - 1 <= 2048``).

    A LUT that reproduces its input on part of its grid (the identity inside a gamut)
    and stores ``s`` times its output, followed by a gain ``1 / s``, then holds that
    identity exactly in half floats, and within half a 16-bit step in the file: half
    floats cannot hold ``k / 48`` (2.4e-4 off near 1) but hold ``k / 64``.

    Examples
    --------
    >>> grid_scale(49), grid_scale(65), grid_scale(33)
    (0.75, 1.0, 1.0)
    >>> round(float(half16(7 / 48 * grid_scale(49)) * 64), 4)  # 7 / 64 to a 16-bit step
    7.0001
    """
    cells = size - 1
    return cells / 2.0 ** int(np.ceil(np.log2(cells)))


def face_frame(V: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return the black pass's stored coordinates z = sign * (u - origin) per chart axis.

    For the primaries' triangle ``V`` (3, 2) in the chart: 0 on the face lying on u_a = const
    (resp. u_b = const) and >= 0 on the triangle, so a point of those faces is stored as
    0 exactly, in 16-bit codes and half floats alike.

    Returns
    -------
    tuple of numpy.ndarray
        (origin (2,), sign (2,)).

    Examples
    --------
    >>> V = np.array([[0.2, 0.9], [0.8, 0.9], [0.2, 0.3]])  # edges u_a = 0.2, u_b = 0.9
    >>> [a.tolist() for a in face_frame(V)]
    [[0.2, 0.9], [1.0, -1.0]]
    """
    origin, sign = np.zeros(2), np.ones(2)
    for axis in (0, 1):
        for a, b in ((0, 1), (1, 2), (2, 0)):
            if abs(V[a, axis] - V[b, axis]) < 1e-12:
                origin[axis] = V[a, axis]
                sign[axis] = 1.0 if V[:, axis].max() > origin[axis] + 1e-12 else -1.0
    return origin, sign


def halves_inside(
    z: np.ndarray, Vz: np.ndarray, margin: float = 2.0 * 0.5 / LUT_CODE_MAX
) -> np.ndarray:
    """Round points ``z`` (N, 2) of the triangle ``Vz`` (3, 2) to half floats that stay in it.

    ``z`` and ``Vz`` in the stored coordinates of :func:`face_frame`; the result: the nearest
    pairs of half floats that stay in the triangle: on the two faces z = 0 exactly, and
    ``margin`` inside the third (its points are not half floats; the 16-bit codes of the
    file sit within 7.6e-6 of the half floats).

    So the CPU (16-bit values) and a host that uploads half floats (Blender's viewport)
    see the same points of the faces, and none outside the gamut, whose negative
    channel the white pass would clamp (changing Y).

    Returns
    -------
    numpy.ndarray
        float64, (N, 2) (a point with no such neighbour: its own half floats).
    """
    h = z.astype(np.float16)
    steps = [h]
    for direction in (np.inf, -np.inf):
        x = h
        for _ in range(2):
            x = np.nextafter(x, np.float16(direction))
            steps.append(x)
    grid = np.stack([s.astype(np.float64) for s in steps], axis=1)  # (N, 5, 2)
    cand = np.stack(np.broadcast_arrays(grid[:, :, None, 0], grid[:, None, :, 1]), axis=-1)
    cand = cand.reshape(len(z), -1, 2)
    ok = (cand >= 0.0).all(axis=-1)
    # the third face: the edge of Vz that lies on neither axis
    for a, b, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        e = Vz[b] - Vz[a]
        if abs(e[0]) > 1e-12 and abs(e[1]) > 1e-12:
            normal = np.array([-e[1], e[0]]) / np.hypot(*e)
            normal *= np.sign(reproducible.matmul(normal, Vz[c] - Vz[a]))
            ok &= reproducible.matmul(cand - Vz[a], normal) >= margin
    dist = ((cand - z[:, None]) ** 2).sum(axis=-1)
    dist[~ok] = np.inf
    best = cand[np.arange(len(z)), dist.argmin(axis=1)]
    return np.where(np.isfinite(dist.min(axis=1))[:, None], best, h.astype(np.float64))

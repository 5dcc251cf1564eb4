"""Applying the committed config's views the way a host does, for the tests and benchmarks.

One definition of each: the committed config's path, OCIO's optimisation levels, a
processor and a view applied to CIE-XYZ-D65 by OCIO's CPU processor (float32, as hosts
run it), a view's code values on every test-colour set, the error statistics the view
tests compare with their targets, the extreme inputs every view must survive,
colour-science's names of the display gamuts, and display code values decoded back to
display-linear light with colour-science's transfer functions (independent of the
package's own encodings).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import numpy.typing as npt

from ocio_thinfilm import registry

#: The repository's baked config (``ocio-thinfilm bake`` writes it).
COMMITTED_CONFIG = Path(__file__).resolve().parents[1] / "configs" / "thinfilm" / "config.ocio"

#: OCIO's CPU optimisation levels the tests run every view at: our name -> the
#: ``PyOpenColorIO`` attribute.
OPTIMIZATION_LEVELS = {
    "NONE": "OPTIMIZATION_NONE",
    "DRAFT": "OPTIMIZATION_DRAFT",
    "GOOD": "OPTIMIZATION_GOOD",
    "VERY_GOOD": "OPTIMIZATION_VERY_GOOD",
    "LOSSLESS": "OPTIMIZATION_LOSSLESS",
    "DEFAULT": "OPTIMIZATION_DEFAULT",
}

#: colour-science's name of each display gamut (``colour.RGB_COLOURSPACES``), typed here
#: apart from the package's ``registry.RGB_COLORIMETRY``: a reference that looked the
#: names up there would agree with a wrong entry of it.
COLOUR_SCIENCE_NAMES = {
    "sRGB": "sRGB",
    "Display P3": "Display P3",
    "Rec.2020": "ITU-R BT.2020",
    "P3-DCI": "DCI-P3",
}


_F32_MAX = float(np.finfo(np.float32).max)
#: CIE-XYZ-D65 inputs at and beyond every edge: black, denormals, negatives, above
#: white, 1e30 and float32's largest value in any channel.
EXTREME_XYZ = np.array(
    [
        [0, 0, 0],
        [1e-40, 1e-40, 1e-40],
        [0, 0, 1e-40],
        [-1, -1, -1],
        [-1, 0.5, 0.5],
        [0.5, -3, 0.5],
        [2, 2, 2],
        [0.95, 1.5, 1.09],
        [1e4, 1e4, 1e4],
        [1e30, 0.5, 0.5],
        [-1e30, 0.5, 0.5],
        [0.5, 1e30, 0.5],
        [0.5, 0.5, 1e30],
        [_F32_MAX] * 3,
        [-_F32_MAX] * 3,
        [_F32_MAX, -_F32_MAX, _F32_MAX],
        [1e-30, 1.0, 1e30],
    ],
    dtype=np.float32,
)


def apply_view(
    cfg,
    display: str,
    XYZ: npt.ArrayLike,
    optimization=None,
    view: str = "Constant-Lightness Clip",
) -> np.ndarray:
    """The config's ``view`` of ``display`` on CIE-XYZ-D65 (float32 code values, (N, 3)).

    ``optimization``: a ``PyOpenColorIO.OptimizationFlags`` value, or ``None`` for the
    default CPU processor (what a host gets).
    """
    import PyOpenColorIO as ocio

    proc = cfg.getProcessor("CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD)
    return apply_processor(proc, np.asarray(XYZ).reshape(-1, 3), optimization)


def apply_processor(processor, values: npt.ArrayLike, optimization=None) -> np.ndarray:
    """An OCIO ``Processor`` applied by its CPU processor to RGB ``values`` (..., 3):
    a float32 array of their shape out, ``values`` untouched; ``optimization`` as in
    :func:`apply_view`."""
    import PyOpenColorIO as ocio

    cpu = (
        processor.getDefaultCPUProcessor()
        if optimization is None
        else processor.getOptimizedCPUProcessor(
            ocio.BIT_DEPTH_F32, ocio.BIT_DEPTH_F32, optimization
        )
    )
    px = np.array(values, dtype=np.float32, order="C", copy=True)
    cpu.applyRGB(px)
    return px


def view_codes(cfg, display: str, view: str, scale: float = 1.0):
    """Yield ``(set name, XYZ, code values)`` of ``view`` on every set of
    :func:`evaluation.colours.gamut_map_sets`, each scaled by ``scale`` (HDR: the
    reference white's multiple)."""
    from evaluation.colours import gamut_map_sets

    for name, XYZ in gamut_map_sets().items():
        XYZ = XYZ * scale
        yield name, XYZ, apply_view(cfg, display, XYZ, view=view)


def error_stats(truth: npt.ArrayLike, got: npt.ArrayLike, inside=None) -> dict[str, float]:
    """dE2000 of ``got`` against ``truth`` (XYZ, Y = 1 white): its 99th percentile and
    maximum, and with ``inside`` (a mask) the maximum over those colours."""
    from ocio_thinfilm.colour import colorimetry

    de = colorimetry.delta_E2000(truth, got)
    stats = {"p99": float(np.percentile(de, 99)), "max": float(de.max())}
    if inside is not None:
        stats["inside_max"] = float(de[inside].max()) if np.any(inside) else 0.0
    return stats


def decode_display(code: npt.ArrayLike, display: str) -> np.ndarray:
    """SDR display code values (clamped to [0, 1]) -> display-linear RGB, by
    colour-science: the sRGB piecewise EOTF (IEC 61966-2-1), BT.1886's EOTF with a
    black level of 0 (a pure 2.4 power) or a pure power of another gamma (DCI's 2.6),
    as the registry's encoding says."""
    import colour

    code = np.clip(np.asarray(code, dtype=np.float64), 0.0, 1.0)
    encoding = registry.as_display(display, hdr=False).encoding
    if encoding.offset is None and encoding.gamma == 2.4:
        return colour.models.eotf_BT1886(code)
    if encoding.offset is None:
        return colour.gamma_function(code, encoding.gamma)
    return colour.cctf_decoding(code, function="sRGB")


def encode_display(rgb: npt.ArrayLike, display: str) -> np.ndarray:
    """SDR display-linear RGB -> code values, by colour-science: the inverse of
    :func:`decode_display` (unclamped; a pure power takes negatives to 0)."""
    import colour

    rgb = np.asarray(rgb, dtype=np.float64)
    encoding = registry.as_display(display, hdr=False).encoding
    if encoding.offset is None and encoding.gamma == 2.4:
        return colour.models.eotf_inverse_BT1886(rgb)
    if encoding.offset is None:
        return colour.gamma_function(np.maximum(rgb, 0.0), 1.0 / encoding.gamma)
    return colour.cctf_encoding(rgb, function="sRGB")


def colour_science_rgb(XYZ: npt.ArrayLike, name: str) -> np.ndarray:
    """XYZ (D65) -> linear RGB of colour-science's colourspace ``name``, Bradford
    adapted (independent of the package's matrices)."""
    import colour

    d65 = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
    return colour.XYZ_to_RGB(
        XYZ, colour.RGB_COLOURSPACES[name], d65, chromatic_adaptation_transform="Bradford"
    )


def apply_lut_files(paths, values: npt.ArrayLike) -> np.ndarray:
    """LUT files applied in order by OCIO's FileTransform (tetrahedral), as a host
    applies them: float32 in, float64 out, (N, 3)."""
    import PyOpenColorIO as ocio

    group = ocio.GroupTransform()
    for path in paths:
        t = ocio.FileTransform(str(path))
        t.setInterpolation(ocio.INTERP_TETRAHEDRAL)
        group.appendTransform(t)
    px = np.asarray(values).reshape(-1, 3)
    return apply_processor(ocio.Config.CreateRaw().getProcessor(group), px).astype(np.float64)

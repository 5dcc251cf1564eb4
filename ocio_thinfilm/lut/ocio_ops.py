"""The OCIO op helpers: one implementation each, used by every module that builds transforms.

A leaf module (it imports only NumPy and, lazily, PyOpenColorIO): the tables, clip
LUTs and views of :mod:`ocio_thinfilm.lut`, the config and its merge, the exports, the
report and the benchmarks build their transforms from these.

- :func:`module`: the ``PyOpenColorIO`` module (imported on first use).
- :func:`transform_id`: a transform ID in the style of the ACES OCIO configs.
- :func:`group`: a ``GroupTransform`` with CLF-style metadata.
- :func:`inverse`: a ``GroupTransform`` applied in the inverse direction.
- :func:`matrix`: a ``MatrixTransform`` from a 3x3 matrix and an offset.
- :func:`range_`: a clamping ``RangeTransform`` (same range in and out);
  :func:`finite_limit_transform`: the one that keeps every processor finite.
- :func:`lut1d_transform`, :func:`lut3d_transform`: LUT ops holding NumPy data.
- :func:`quantize`: rounding before data go into a file (byte-reproducible files).
- :func:`apply`: apply a transform to a (..., 3) array with OCIO's CPU processor.
"""

from __future__ import annotations

from collections.abc import Iterable
from types import ModuleType
from typing import Any, TypeAlias

import numpy as np
import numpy.typing as npt

__all__ = [
    "Transform",
    "Config",
    "Processor",
    "CPUProcessor",
    "VENDOR",
    "module",
    "transform_id",
    "group",
    "inverse",
    "matrix",
    "range_",
    "LIMIT",
    "finite_limit_transform",
    "lut1d_transform",
    "lut3d_transform",
    "quantize",
    "apply",
]

# PyOpenColorIO ships no type stubs (mypy: ignore_missing_imports), so its objects are Any
# to the type checker; these names say in signatures which OCIO object is meant.
#: An OCIO transform (``PyOpenColorIO.Transform`` or a subclass): PyOpenColorIO ships no
#: type stubs.
Transform: TypeAlias = Any
#: An OCIO config (``PyOpenColorIO.Config``): no type stubs either.
Config: TypeAlias = Any
#: An OCIO processor (``PyOpenColorIO.Processor``): no type stubs either.
Processor: TypeAlias = Any
#: An OCIO CPU processor (``PyOpenColorIO.CPUProcessor``): no type stubs either.
CPUProcessor: TypeAlias = Any

#: ``urn:aswf:ocio:transformId:1.0:<Vendor>:<Type>:<Name>:1.0`` (OpenColorIO-Config-ACES).
VENDOR = "OCIO-ThinFilm"


def module() -> ModuleType:
    """Return the ``PyOpenColorIO`` module (imported here, on first use)."""
    import PyOpenColorIO as ocio

    return ocio


def transform_id(kind: str, name: str) -> str:
    """Transform ID in the style of the ACES OCIO configs.

    ``urn:aswf:ocio:transformId:1.0:<Vendor>:<Type>:<Name>:1.0``.

    >>> transform_id("Gamut_Map", "Constant-Lightness Clip sRGB")
    'urn:aswf:ocio:transformId:1.0:OCIO-ThinFilm:Gamut_Map:Constant_Lightness_Clip_sRGB:1.0'
    """
    safe = "".join(c if c.isalnum() else "_" for c in name).strip("_")
    return f"urn:aswf:ocio:transformId:1.0:{VENDOR}:{kind}:{safe}:1.0"


def group(
    transforms: Iterable[Transform | None],
    *,
    name: str | None = None,
    description: str | None = None,
    id: str | None = None,
    input_descriptor: str | None = None,
    output_descriptor: str | None = None,
) -> Transform:
    """Return a ``GroupTransform`` of ``transforms`` with CLF-style metadata.

    ``None`` entries are skipped.
    """
    ocio = module()
    g = ocio.GroupTransform()
    for t in transforms:
        if t is not None:
            g.appendTransform(t)
    md = g.getFormatMetadata()
    if name:
        md.setName(name)
    if id:
        md.setID(id)
    if description:
        md.addChildElement("Description", description)
    if input_descriptor:
        md.addChildElement("InputDescriptor", input_descriptor)
    if output_descriptor:
        md.addChildElement("OutputDescriptor", output_descriptor)
    return g


def inverse(transforms: Iterable[Transform | None]) -> Transform:
    """Return a GroupTransform of ``transforms`` (a list) applied in the inverse direction."""
    g = group(transforms)
    g.setDirection(module().TRANSFORM_DIR_INVERSE)
    return g


def quantize(values: npt.ArrayLike, decimals: int = 7) -> np.ndarray:
    """Round to ``decimals`` decimal places (and turn -0 into 0) before data go into a file.

    Float64 results can differ in the last bits between runs (BLAS reduction order, memory
    alignment); rounded, the written files are byte-reproducible.
    """
    return np.round(np.asarray(values, dtype=np.float64), decimals) + 0.0


def matrix(m3: npt.ArrayLike | None = None, offset: npt.ArrayLike = (0.0, 0.0, 0.0)) -> Transform:
    """Return a ``MatrixTransform``: ``m3`` (3x3, identity if None) and ``offset``.

    Both rounded to 12 decimals.
    """
    ocio = module()
    m = np.eye(4)
    if m3 is not None:
        m[:3, :3] = m3
    return ocio.MatrixTransform(
        [float(v) for v in quantize(m, 12).ravel()],
        [float(v) for v in quantize(offset, 12)] + [0.0],
    )


def range_(lo: float, hi: float) -> Transform:
    """Return a ``RangeTransform`` clamping to [lo, hi] (no scaling)."""
    r = module().RangeTransform()
    r.setMinInValue(lo)
    r.setMaxInValue(hi)
    r.setMinOutValue(lo)
    r.setMaxOutValue(hi)
    return r


#: Limit of every component before a matrix or a chart: no real pixel comes near it, and
#: +-Inf (and NaN, which OCIO's CPU Range sends to the lower bound) become finite, so
#: no processor overflows to Inf - Inf = NaN at OPTIMIZATION_NONE (ops not composed).
LIMIT = 1e6


def finite_limit_transform() -> Transform:
    """Clamp every component to [-LIMIT, LIMIT].

    +-Inf become finite (and NaN, which OCIO's CPU Range sends to the lower bound).
    """
    return range_(-LIMIT, LIMIT)


def lut1d_transform(values: np.ndarray, *, bitdepth: str | None = None) -> Transform:
    """Return an OCIO Lut1DTransform (linear interpolation) holding ``values`` (N, 3).

    ``bitdepth="uint16"``: the values already lie on the 16-bit grid (in [0, 1]) and
    are written as 16-bit integers; otherwise they are quantised
    (:func:`quantize`) and written as floats.
    """
    ocio = module()
    t = ocio.Lut1DTransform()
    t.setLength(len(values))
    data = values if bitdepth else quantize(values)
    t.setData(np.ascontiguousarray(data, dtype=np.float32).ravel())
    t.setInterpolation(ocio.INTERP_LINEAR)
    if bitdepth == "uint16":
        t.setFileOutputBitDepth(ocio.BIT_DEPTH_UINT16)
    return t


def lut3d_transform(values: np.ndarray, *, bitdepth: str | None = None) -> Transform:
    """Return an OCIO Lut3DTransform (tetrahedral) holding ``values`` (N, N, N, 3).

    Index [r][g][b]. ``bitdepth``: ``"uint16"`` (values on the 16-bit grid in [0, 1]) or
    ``"half"`` (values already rounded to half floats) are written as such in a CLF
    file; otherwise values are quantised (:func:`quantize`) and written as floats.
    """
    ocio = module()
    t = ocio.Lut3DTransform()
    t.setGridSize(values.shape[0])
    t.setInterpolation(ocio.INTERP_TETRAHEDRAL)
    t.setData(
        np.ascontiguousarray(values if bitdepth else quantize(values), dtype=np.float32).ravel()
    )
    if bitdepth == "uint16":
        t.setFileOutputBitDepth(ocio.BIT_DEPTH_UINT16)
    elif bitdepth == "half":
        t.setFileOutputBitDepth(ocio.BIT_DEPTH_F16)
    return t


def apply(
    transform: Transform, pixels: npt.ArrayLike, *, config: Config | None = None
) -> np.ndarray:
    """Apply an OCIO transform to a (..., 3) array with OCIO's CPU processor.

    The input is converted to float32 and not modified; returns a new float32 array
    of the same shape. ``config``: the config whose processor applies it (default: a
    raw config).
    """
    ocio = module()
    a = np.asarray(pixels, dtype=np.float32)
    if a.ndim == 0 or a.shape[-1] != 3:
        raise ValueError(f"pixels must have a last axis of length 3, got shape {a.shape}")
    out = np.ascontiguousarray(a.reshape(-1, 3)).copy()
    cfg = ocio.Config.CreateRaw() if config is None else config
    cpu = cfg.getProcessor(transform).getDefaultCPUProcessor()
    if out.size:
        cpu.applyRGB(out)
    return out.reshape(a.shape)

"""``ocio-thinfilm export view``: a whole display/view of the config as one standalone LUT.

Input: the raw pixel values of any colour space of the config (``ACEScct``,
``ACEScg``, ``Linear Rec.709 (sRGB)``, ``CIE-XYZ-D65``, the thin-film spaces, ...).
Output: display code values of ``--display`` / ``--view``. The file takes the pixel
as it is: nothing has to be scaled by hand first.

Formats: ``.cube`` (plain, or with a Resolve 1D shaper), ``.csp`` (the shaper as a
prelut), ``.spi3d`` (with a companion ``.shaper.spi1d`` where the input needs one),
``.clf`` / ``.ctf`` (the exact chain where CLF can hold it); thin-film inputs give a
1D LUT over ``--range``. The SDR displays' ``.cube`` and ``.csp`` tables hold node
values fitted by lattice regression (Garcia & Gupta 2009;
:mod:`ocio_thinfilm.export.view_fit`, :mod:`ocio_thinfilm.lut.lattice_fit`); the shaper
is :mod:`ocio_thinfilm.export.view_shaper`'s. How each format carries the input and
which tables are fitted: docs/gamut_map.md, *Design notes*.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path

import numpy as np

from ocio_thinfilm import cache, registry
from ocio_thinfilm.checks import ParameterError, as_choice, as_pair
from ocio_thinfilm.colour import compress as compress_map
from ocio_thinfilm.export import view_fit
from ocio_thinfilm.export.files import LUT_FORMATS, lut_format
from ocio_thinfilm.export.view_shaper import (
    DEFAULT_VIEW_SIZE,
    SHAPER_SIZE,
    linear_sibling,
    shaper_domain,
    shaper_from_zero,
    view_config,
)
from ocio_thinfilm.io import StrPath, atomic_file, check_writable, write_text
from ocio_thinfilm.lut import ocio_ops, storage
from ocio_thinfilm.lut.options import MapOptions, as_options

__all__ = [
    "VIEW_FORMATS",
    "DEFAULT_VIEW_SIZE",
    "SHAPER_SIZE",
    "shaper_domain",
    "view_config",
    "export_view",
]

#: Format -> OCIO writer name: every format of :data:`~ocio_thinfilm.export.files.LUT_FORMATS`
#: (``.spi1d`` only for the 1D, thin-film, inputs).
VIEW_FORMATS = {name: spec[0] for name, spec in LUT_FORMATS.items()}
MAX_VIEW_SIZE = 129
#: Formats whose 3D table holds fitted node values (:mod:`ocio_thinfilm.export.view_fit`,
#: lattice regression) rather than samples of the view, for the SDR displays (the HDR
#: displays' tables stay samples; see :func:`_fitted_table`).
FITTED_FORMATS = ("cube", "csp")


# --------------------------------------------------------------------------- #
# The input spaces (names and their properties from the registry)
# --------------------------------------------------------------------------- #
#: Thin-film input spaces: a 1D LUT each.
_THIN_FILM = {s.name: s for s in registry.THIN_FILM_LIST}
#: Inputs whose code values in [0, 1] cover every value the views need (ACEScct 1.0
#: is linear 222.9, far above the display white that every view maps brighter colours
#: to): their ``.cube`` is a plain 3D LUT over [0, 1] unless the Resolve form is asked for.
_PLAIN_INPUTS = tuple(e.name for e in registry.ENCODED_LIST if e.plain)


# --------------------------------------------------------------------------- #
# Validation
# --------------------------------------------------------------------------- #
def _cube_shaper(source, fmt, shaper):
    """Whether a 3D ``.cube`` of ``source`` carries the 1D shaper (the Resolve form)."""
    if shaper is None:
        return source not in _PLAIN_INPUTS
    if fmt != "cube":
        raise ParameterError(
            "shaper", f" applies to .cube files, not .{fmt} (its shaper is part of the format)"
        )
    if not shaper and source not in _PLAIN_INPUTS:
        raise ParameterError(
            "shaper",
            f"=False (a plain .cube) needs an input whose code values 0..1 cover "
            f"the views' colours ({', '.join(_PLAIN_INPUTS)}); {source} "
            "takes the Resolve form",
        )
    return bool(shaper)


def _validate(source, display, view, size, fmt, value_range):
    from ocio_thinfilm import config as config_module

    spaces = [cs["name"] for cs in config_module.config_data(inline=True).colorspaces]
    if source is None:
        raise ParameterError("source", " is needed: a colour space of the config")
    as_choice("source", source, spaces)
    if display is None:
        raise ParameterError("display", f" is needed: one of {', '.join(registry.ALL_DISPLAYS)}")
    registry.as_display(display)
    if view is None:
        raise ParameterError("view", f" is needed: one of {', '.join(registry.VIEWS)}")
    registry.as_view(view)
    as_choice("fmt", fmt, VIEW_FORMATS)
    if size is not None and (isinstance(size, bool) or not isinstance(size, (int, np.integer))):
        raise TypeError(f"size must be an integer, got {size!r} ({type(size).__name__})")
    one_d = source in _THIN_FILM
    if one_d:
        film = _THIN_FILM[source]
        default_range, default_size = film.default_range, film.default_size
        if fmt in ("csp", "spi3d"):
            raise ValueError(
                f"{source} takes one value per pixel, a 1D LUT: use cube, "
                f"spi1d or clf (format {fmt} holds only 3D LUTs)"
            )
        lo, hi = default_range if value_range is None else as_pair("value_range", value_range)
        if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= hi:
            raise ParameterError(
                "value_range", f" must be two finite numbers MIN < MAX, got {lo:g} {hi:g}"
            )
        top = 1.0 if film.kind == "morpho" else 100.0  # cos(theta), or thickness in um
        if lo < 0 or hi > top:
            raise ParameterError(
                "value_range",
                f" for {source} ({film.pixel}) must lie in 0..{top:g}, got {lo:g} {hi:g}",
            )
        size = default_size if size is None else size
        if not 2 <= size <= 1 << 20:
            raise ParameterError("size", f" must be in [2, {1 << 20}] for a 1D LUT, got {size}")
        return size, (float(lo), float(hi))
    if value_range is not None:
        raise ParameterError(
            "value_range", " applies to the thin-film inputs only (3D LUTs carry their own domain)"
        )
    if fmt == "spi1d":
        raise ValueError(f"{source} needs a 3D LUT: use cube, csp, clf, ctf or spi3d")
    size = DEFAULT_VIEW_SIZE if size is None else size
    if not 2 <= size <= MAX_VIEW_SIZE:
        raise ParameterError("size", f" must be in [2, {MAX_VIEW_SIZE}] for a 3D LUT, got {size}")
    return size, None


def _stem(source, display, view):
    return set_name(source, display, view)


def set_name(source: str, display: str, view: str) -> str:
    """Return the file stem in the shipped set.

    E.g. ``ACEScct_to_sRGB_ConstantLightnessClip``, ``ACEScct_to_Rec2020_ChannelClamp``.
    """

    def clean(text):
        return "".join(c for c in text if c.isalnum())

    return f"{clean(source)}_to_{clean(display)}_{clean(view)}"


# --------------------------------------------------------------------------- #
# Writing
# --------------------------------------------------------------------------- #
def _description(source, entry, view, size, shaper, baked, knobs=None):
    text = (
        f"ocio-thinfilm display LUT: {source} -> {entry.name} / {view}. Input: the raw "
        f"pixel values of {source}; output: {entry.name} display code values."
    )
    if knobs is not None:
        t, lim = (compress_map.knob_text(v) for v in knobs)
        text += f" Compression threshold {t}, limit {lim}."
    if shaper:
        sibling = linear_sibling(source)
        assert sibling is not None  # a 3D input: XYZ, scene-linear or encoded
        lo, hi = shaper_domain(sibling, size, entry)
        text += (
            f" Shaper: sign(x)|x|^(1/2) per channel of linear "
            f"{sibling} over {lo:.6g}..{hi:.6g} (clamped beyond)."
        )
    if baked:
        text += f" 3D LUT {size}^3, tetrahedral."
    return text


def _cube_title(source, display, view, size, shaper):
    """Return the first line of a .cube, saying which form the file is.

    OCIO's writer has no title. The plain form gets the format's ``TITLE`` keyword; the Resolve
    form a comment, because OCIO's Resolve .cube parser refuses ``TITLE`` ("Unsupported tag",
    OCIO 2.6) and that parser is the only one of OCIO's that reads the shaper.
    """
    if shaper:
        return (
            f"# {source} to {display} {view}, {size}^3: Resolve form, a 1D shaper + "
            "3D LUT (ffmpeg, OBS and other readers that ignore the shaper need the "
            "plain form)"
        )
    return (
        f'TITLE "{source} to {display} {view}, {size}^3 (plain 3D LUT over 0..1, '
        'read alike by every .cube reader)"'
    )


def _metadata(source, display, view):
    stem = _stem(source, display, view)
    return dict(
        name=stem,
        id=ocio_ops.transform_id("Display_View", stem),
        input=f"{source}: raw pixel values",
        output=f"{display} display code values ({view})",
    )


def _bake_text(cfg, fmt, source, shaper, entry, view, size, description, options, target=None):
    import PyOpenColorIO as ocio

    baker = ocio.Baker()
    baker.setConfig(cfg)
    baker.setFormat(VIEW_FORMATS[fmt])
    baker.getFormatMetadata().addChildElement("Description", description)
    baker.setInputSpace(source)
    if target is not None:
        baker.setTargetSpace(target)
    else:
        baker.setDisplayView(entry.name, view)
    if shaper:
        baker.setShaperSpace(shaper)
        baker.setShaperSize(SHAPER_SIZE)
    baker.setCubeSize(SHAPER_SIZE if fmt == "spi1d" else size)
    text = baker.bake()
    if target is None and _fitted_table(source, fmt, shaper, entry):
        nodes = _fitted_nodes(source, entry.name, view, size, bool(shaper), options)
        text = _with_table(text, nodes)
    if fmt == "cube":
        text = _without_trailing_zeros(text)
    return text if text.endswith("\n") else text + "\n"


@cache.persistent(
    modules=(
        "ocio_thinfilm.export.view",
        "ocio_thinfilm.export.view_fit",
        "ocio_thinfilm.lut.lattice_fit",
        "ocio_thinfilm.colour.clip",
        "ocio_thinfilm.colour.compress",
        "ocio_thinfilm.lut.clip_lut",
        "ocio_thinfilm.lut.grid",
        "ocio_thinfilm.lut.node_fit",
        "ocio_thinfilm.lut.storage",
        "ocio_thinfilm.lut.display_transforms",
        "ocio_thinfilm.lut.view_transforms",
        "ocio_thinfilm.config.data",
        "ocio_thinfilm.registry",
    )
)
def _fitted_nodes(source, display, view, size, shaper, options):
    """Return the fitted 3D table of a display LUT, memoised on disk (a fit takes seconds).

    :func:`ocio_thinfilm.export.view_fit.fit_view_table` for ``source`` (over its code
    values, or with ``shaper`` over the shaper of :func:`view_config`). ``options``: the
    config's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`), the compression's
    at their defaults for the views other than Constant-Lightness Compress (which do not
    depend on them: one fit serves every knob).
    """
    cfg, shaper_space = view_config(source, size, display, options=options)
    compress = registry.as_view(view).kind == "compress"
    fit = dict(knobs=options.knobs()) if compress else {}
    if shaper and shaper_space:
        return view_fit.fit_view_table(
            cfg,
            shaper_space,
            display,
            view,
            size,
            object_weight=view_fit.SHAPER_OBJECT_WEIGHT,
            **fit,
        )
    return view_fit.fit_view_table(cfg, source, display, view, size, **fit)


def _fitted_table(source, fmt, shaper, entry):
    """Return whether the 3D table is fitted (:data:`FITTED_FORMATS`, SDR displays).

    The plain form always; with a shaper only for inputs whose shaper reaches below 0
    (not a space whose ``shaper_from_zero`` is set): the AP1 inputs' shaper tables, sampled, are
    within ΔE2000 max 2.1-2.4 on object colours and fitted ones 4.2-6.0 (least squares does not
    hold the largest error down).
    """
    if fmt not in FITTED_FORMATS or entry.hdr:
        return False
    sibling = linear_sibling(source)
    return not shaper or sibling is None or not shaper_from_zero(sibling)


def _with_table(text, nodes):
    """Return the baked ``text`` (.cube or .csp) with its 3D table replaced by ``nodes``.

    The table is the last size^3 lines of three numbers (red fastest in both formats);
    ``nodes`` (indexed [r, g, b]) are printed as OCIO's writers print them (6 decimals).
    """
    size = nodes.shape[0]
    lines = text.split("\n")
    rows = [i for i, line in enumerate(lines) if _TABLE_ROW.match(line)][-(size**3) :]
    flat = np.asarray(nodes, dtype=np.float64).transpose(2, 1, 0, 3).reshape(-1, 3) + 0.0
    # Python floats (not numpy scalars) format several times faster
    for i, (r, g, b) in zip(rows, flat.tolist(), strict=True):
        lines[i] = f"{r:.6f} {g:.6f} {b:.6f}".replace("-0.000000", "0.000000")
    return "\n".join(lines)


#: A row of a 3D table: three numbers.
_TABLE_ROW = re.compile(r"^\s*[-+0-9.eE]+ [-+0-9.eE]+ [-+0-9.eE]+\s*$")
#: A line of a LUT's table: numbers only (OCIO's .cube writer prints them as %.6f).
_TABLE_LINE = re.compile(r"[-+0-9. ]+")


def _without_trailing_zeros(text):
    """Return ``text`` with each table value in its shortest fixed form.

    ``0.500000`` becomes ``0.5``, ``1.000000`` becomes ``1``. The numbers are the same, every
    .cube reader parses either form, and a 65^3 display .cube shrinks by about 40 % (clipped
    colours are mostly 0 and 1).
    """
    short: dict[str, str] = {}  # the tables repeat their values (0 and 1 most of all)

    def shortest(token: str) -> str:
        if token not in short:
            short[token] = token.rstrip("0").rstrip(".") if "." in token else token
        return short[token]

    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line and _TABLE_LINE.fullmatch(line):
            lines[i] = " ".join(shortest(t) for t in line.split(" "))
    return "\n".join(lines)


def _write_group(path, fmt, transforms, meta, description):
    import PyOpenColorIO as ocio

    g = ocio_ops.group(
        transforms,
        name=meta["name"],
        id=meta["id"],
        description=description,
        input_descriptor=meta["input"],
        output_descriptor=meta["output"],
    )
    with atomic_file(path) as tmp:
        g.write(VIEW_FORMATS[fmt], str(tmp), ocio.Config.CreateRaw())
    return Path(path)


def _baked_3d_transforms(cfg, source, shaper, display, view, size):
    """Return the content of the .cube as OCIO transforms, for CLF.

    [input -> shaper ops (exact), Lut3D over the shaper (tetrahedral)].
    """
    import PyOpenColorIO as ocio

    u = np.linspace(0.0, 1.0, size)
    grid = np.stack(np.meshgrid(u, u, u, indexing="ij"), axis=-1).reshape(-1, 3)
    nodes = np.ascontiguousarray(grid, dtype=np.float32)
    start = shaper or source
    proc = cfg.getProcessor(start, display, view, ocio.TRANSFORM_DIR_FORWARD)
    proc.getDefaultCPUProcessor().applyRGB(nodes)
    ops = []
    if shaper:
        ops += list(cfg.getProcessor(source, shaper).createGroupTransform())
    values = nodes.reshape(size, size, size, 3).astype(np.float64)
    if values.min() >= -1e-4 and values.max() <= 1.0 + 1e-4:
        # Display code values: 16-bit integers (half the text of floats; the step,
        # 1.5e-5, is far below the interpolation error).
        values = storage.q16(values)
        ops.append(ocio_ops.lut3d_transform(values, bitdepth="uint16"))
        ops.append(ocio_ops.matrix())  # the CLF writer keeps 16i only before another op
    else:
        ops.append(ocio_ops.lut3d_transform(values))
    return ops


def _write_1d(path, fmt, cfg, source, display, view, size, value_range, meta, description):
    """Write the 1D LUT of a thin-film input over ``value_range``.

    Thin-film inputs get a 1D LUT, written by the export module's writer (which states the
    domain in every format).
    """
    import PyOpenColorIO as ocio

    from ocio_thinfilm.export import files as export

    lo, hi = value_range
    x = np.linspace(lo, hi, size)
    px = np.ascontiguousarray(np.repeat(x[:, None], 3, axis=1), dtype=np.float32)
    cfg.getProcessor(
        source, display, view, ocio.TRANSFORM_DIR_FORWARD
    ).getDefaultCPUProcessor().applyRGB(px)
    values = px.astype(np.float64)
    what = _THIN_FILM[source].pixel
    lut_meta = dict(
        meta,
        input=f"{source}: {what}",
        range=(lo, hi),
        size=size,
        description=description + f" 1D LUT, {size} entries uniform over {lo:g}..{hi:g}.",
    )
    return export.write_lut(path, fmt, values, ocio_ops.lut1d_transform(values), lut_meta)


def export_view(
    source: str | None,
    display: registry.DisplayLike | None,
    view: str | None,
    out: StrPath | None = None,
    *,
    fmt: str | None = None,
    size: int | None = None,
    value_range: Sequence[float] | None = None,
    shaper: bool | None = None,
    options: MapOptions | None = None,
) -> list[Path]:
    """Write the display LUT ``source`` -> ``display`` / ``view``.

    Returns the paths written (two for ``.spi3d`` with a shaper: the 3D LUT and its
    ``.shaper.spi1d``).

    ``shaper`` (``.cube`` only): None -- the plain 3D form for the plain inputs (ACEScct),
    the Resolve form (1D shaper + 3D) for the others; True -- the Resolve form;
    False -- the plain form (only for the plain inputs (ACEScct)).

    ``options``: the config's knobs (:class:`~ocio_thinfilm.lut.options.MapOptions`;
    ``None`` for the defaults); the file's description states the compression's knobs
    for the Constant-Lightness Compress view. The other views do not depend on them.
    """
    options = as_options(options)
    fmt = lut_format(out, fmt, LUT_FORMATS, "cube")
    size, value_range = _validate(source, display, view, size, fmt, value_range)
    assert source is not None and display is not None and view is not None  # _validate
    entry = registry.as_display(display)  # the objects from here on, their names for text
    view_entry = registry.as_view(view)
    cube_shaper = _shaper_form(source, fmt, shaper)
    out = _output_path(out, source, entry.name, view_entry.name, fmt)
    if view_entry.kind != "compress":  # the other views: one config (and fit) for any knob
        options = replace(
            options, compress_threshold=compress_map.THRESHOLD, compress_limit=compress_map.LIMIT
        )
    knobs = options.knobs() if view_entry.kind == "compress" else None
    cfg, shaper_space = view_config(source, size, entry, options=options)
    view = view_entry.name
    if source in _THIN_FILM:
        description = _description(source, entry, view, size, None, False, knobs)
        meta = _metadata(source, entry.name, view)
        return [
            _write_1d(out, fmt, cfg, source, entry.name, view, size, value_range, meta, description)
        ]
    if fmt in ("clf", "ctf"):
        return [_write_chain(out, fmt, cfg, source, entry, view, size, shaper_space, knobs)]
    if fmt == "cube" and not cube_shaper:
        shaper_space = None  # the plain form: the grid over ACEScct itself
    return _write_3d_text(out, fmt, cfg, source, entry, view, size, shaper_space, options)


def _shaper_form(source, fmt, shaper):
    """Return whether a ``.cube`` carries the 1D shaper (None: not a 3D ``.cube``)."""
    if source in _THIN_FILM:
        if shaper is not None:
            raise ParameterError("shaper", f" applies to 3D LUTs; {source} gives a 1D LUT")
        return None
    if fmt == "cube" or shaper is not None:
        return _cube_shaper(source, fmt, shaper)
    return None


def _output_path(out, source, display, view, fmt):
    """Return the file to write (default: named after the view), checked writable."""
    if out is None:
        out = Path(_stem(source, display, view) + "." + fmt)
    out = Path(out)
    if out.exists() and out.is_dir():
        raise ParameterError("out", f" {out} is a directory")
    check_writable(out.parent if str(out.parent) else Path("."), create=False)
    return out


def _write_chain(out, fmt, cfg, source, entry, view, size, shaper_space, knobs):
    """Write a ``.clf`` / ``.ctf``: the exact chain.

    CLF cannot hold FixedFunction ops: then the exact shaper ops and the baked 3D LUT.
    """
    import PyOpenColorIO as ocio

    meta = _metadata(source, entry.name, view)
    proc = cfg.getProcessor(source, entry.name, view, ocio.TRANSFORM_DIR_FORWARD)
    exact = list(proc.createGroupTransform())
    description = _description(source, entry, view, size, None, False, knobs)
    try:
        return _write_group(out, fmt, exact, meta, description + " Exact chain.")
    except ocio.Exception:
        if fmt != "clf":
            raise
    return _write_group(
        out,
        fmt,
        _baked_3d_transforms(cfg, source, shaper_space, entry.name, view, size),
        meta,
        _description(source, entry, view, size, shaper_space, True, knobs),
    )


def _write_3d_text(out, fmt, cfg, source, entry, view, size, shaper_space, options):
    """Write a baked 3D LUT (``.cube``, ``.csp``, ``.spi3d`` and its shaper's ``.spi1d``)."""
    knobs = options.knobs() if registry.as_view(view).kind == "compress" else None
    description = _description(source, entry, view, size, shaper_space, True, knobs)
    bake = dict(description=description, options=options)
    if fmt == "spi3d" and shaper_space:
        companion = out.with_name(out.stem + ".shaper.spi1d")
        text3d = _bake_text(cfg, "spi3d", shaper_space, None, entry, view, size, **bake)
        text1d = _bake_text(
            cfg, "spi1d", source, shaper_space, entry, view, size, target=shaper_space, **bake
        )
        return [write_text(out, text3d), write_text(companion, text1d)]
    text = _bake_text(cfg, fmt, source, shaper_space, entry, view, size, **bake)
    if fmt == "cube":  # OCIO's writer has no title line: say which form the file is
        text = _cube_title(source, entry.name, view, size, bool(shaper_space)) + "\n" + text
    return [write_text(out, text)]

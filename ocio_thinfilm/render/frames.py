"""Rendering the paper's example scenes (Section 4, Figures 4-7) through a config.

For each scene (:mod:`ocio_thinfilm.render.scenes`) :func:`render_scene`

1. hands the scene a ``lookup`` that applies, for each table the scene declares, the
   config's thin-film input colour space (:mod:`ocio_thinfilm.render.processors`);
2. applies the config's display view to the composited scene-linear picture, with
   captions where the scene has them;

and :func:`save_frame` writes the picture as an OpenEXR file -- CIE XYZ (D65, Y = 1 the
perfect white) in R, G, B (``oiio:ColorSpace`` names it) plus the scene's AOVs
(optical thickness, view angle ...) -- and the display-encoded 8-bit PNG, as one
transaction. A frame depends only on (scene, frame, seed, size, display, view, config):
output bytes are a function of the arguments.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.io import (
    StrPath,
    Transaction,
    check_output_file,
    images,
    transaction,
    write_image,
)
from ocio_thinfilm.lut import ocio_ops
from ocio_thinfilm.render import scenes as scene_module
from ocio_thinfilm.render.processors import ConfigProcessors, display_image, make_lookup

__all__ = [
    "DEFAULT_SIZE",
    "DEFAULT_DISPLAY",
    "DEFAULT_VIEW",
    "EXR_COLORSPACE",
    "png_colorspace",
    "render_scene",
    "draw_labels",
    "frame_paths",
    "save_frame",
    "write_frame",
]

DEFAULT_SIZE = (512, 512)
DEFAULT_DISPLAY = "sRGB"
DEFAULT_VIEW = registry.CLIP_VIEW

#: How the EXR's colour channels are to be read (also written into every EXR).
EXR_COLORSPACE = "CIE-XYZ-D65"
EXR_DOC = (
    "R,G,B hold scene-linear CIE XYZ (1931 2-degree observer, D65, Y = 1 is the "
    "perfect white under the scene's unit illuminant)"
)


def png_colorspace(display: str) -> str:
    """Return how a PNG for ``display`` is tagged.

    sRGB gets PNG's sRGB chunk, Display P3, Rec.2020 and P3-DCI a cICP chunk
    (``png_cicp`` where OpenImageIO writes none), Rec.1886 Rec.709 a gAMA chunk; the
    displays of other configs (an ACES config merged with ``bake --into``) ``"data"``,
    no tag -- never a wrong sRGB one. The HDR displays get their cICP chunk (BT.2100
    PQ: 9 16 0 1, HLG: 9 18 0 1, P3-D65 PQ: 12 16 0 1) and 16 bits per channel.

    Parameters
    ----------
    display : str
        A display name, of the registry or of another config.

    Returns
    -------
    str
        An OpenImageIO colour interop ID (the registry display's ``png_colorspace``), or
        ``"data"`` for a display the registry does not have.

    Examples
    --------
    >>> png_colorspace("Display P3"), png_colorspace("ACES 1.0 - SDR Video")
    ('srgb_p3d65_display', 'data')
    """
    entry = registry.find_display(display)
    return "data" if entry is None else entry.png_colorspace


#: The EXR ``DateTime`` (fixed, for byte-identical output): Eurographics Workshop on
#: Photosimulation, Realism and Physics in Computer Graphics, Rennes, 11 June 1990.
FIXED_DATETIME = "1990:06:11 00:00:00"


#: Code value of the captions on SDR displays (sRGB: 83 % of white).
LABEL_CODE = 0.92


def label_code(display: str) -> float:
    """Return the captions' code value on ``display``.

    :data:`LABEL_CODE` on SDR displays (and on displays the registry does not have); on
    the registry's HDR displays the code of the same light relative to the 203 cd/m2
    reference white (graphics white of ITU-R BT.2408), not 0.92 of the PQ / HLG range.

    Parameters
    ----------
    display : str
        A display name.

    Returns
    -------
    float
        The code value, in [0, 1].

    Examples
    --------
    >>> round(label_code("sRGB"), 2), round(label_code("Rec.2100-PQ"), 3)
    (0.92, 0.561)
    """
    entry = registry.find_display(display)
    if entry is None or not entry.hdr:
        return LABEL_CODE
    from ocio_thinfilm.colour import colorimetry
    from ocio_thinfilm.lut import display_transforms, ocio_ops

    light = ((LABEL_CODE + 0.055) / 1.055) ** 2.4  # the sRGB EOTF of LABEL_CODE
    grey = light * colorimetry.white_XYZ(entry.colorimetry)
    return float(ocio_ops.apply(display_transforms.hdr_encoding_transform(entry), grey)[1])


def draw_labels(
    rgb: np.ndarray,
    labels: Sequence[tuple[float, float, str, float]],
    code: float = LABEL_CODE,
) -> tuple[np.ndarray, bool]:
    """Draw captions with OpenImageIO's ``render_text`` and its bundled font.

    :func:`ocio_thinfilm.io.images.draw_labels` with the scenes' grey.

    Parameters
    ----------
    rgb : numpy.ndarray
        (H, W, 3) display code values.
    labels : sequence of (float, float, str, float)
        ``(x, y, text, size)`` captions: the text centred at x, its baseline at y
        (pixels, truncated to integers), ``size`` its height in pixels.
    code : float, optional
        The captions' grey, a code value (default :data:`LABEL_CODE`).

    Returns
    -------
    image : numpy.ndarray
        float32 (H, W, 3) with the captions; ``rgb`` itself when there are no labels
        or when a caption could not be drawn (then none is drawn).
    drawn : bool
        Whether the captions were drawn (``True`` without labels).
    """
    return images.draw_labels(rgb, labels, code)


# --------------------------------------------------------------------------- #
# Rendering one frame of one scene
# --------------------------------------------------------------------------- #
def render_scene(
    name: str,
    size: tuple[int, int] = DEFAULT_SIZE,
    *,
    seed: int = 0,
    frame: int = 1,
    display: str = DEFAULT_DISPLAY,
    view: str = DEFAULT_VIEW,
    lookup: scene_module.Lookup | None = None,
    config: ConfigProcessors | ocio_ops.Config | StrPath | None = None,
    film: scene_module.TableSpec | None = None,
) -> tuple[scene_module.Picture, np.ndarray]:
    """Render one frame of a scene through a config's processors.

    Parameters
    ----------
    name : str
        A scene of :data:`ocio_thinfilm.render.scenes.SCENES`.
    size : tuple of int, optional
        (width, height) in pixels (default :data:`DEFAULT_SIZE`).
    seed : int, optional
        Noise seed, an integer >= 0 (default 0).
    frame : int, optional
        Frame number, 1 the still (default 1).
    display : str, optional
        A display of the config (default :data:`DEFAULT_DISPLAY`).
    view : str, optional
        A view of that display (default :data:`DEFAULT_VIEW`); a scene's columns may
        name their own (the spectrum scene's).
    lookup : callable, optional
        A scene lookup from :func:`~ocio_thinfilm.render.processors.make_lookup`; it
        brings its own processors, used when ``config`` is ``None``. Default: one made
        for the config.
    config : ConfigProcessors, PyOpenColorIO.Config, str or os.PathLike, optional
        The config: its processors, the config itself or its file (default:
        :data:`ocio_thinfilm.render.processors.DEFAULT_CONFIG`).
    film : TableSpec, optional
        A user's film for the oil or soap scene
        (:meth:`ocio_thinfilm.render.scenes.Scene.with_film`).

    Returns
    -------
    picture : ocio_thinfilm.render.scenes.Picture
        The scene-linear picture (CIE XYZ) and its AOVs.
    rgb : numpy.ndarray
        float32 (H, W, 3) display code values in [0, 1], with the scene's captions.

    Raises
    ------
    ValueError
        For an unknown scene.
    ParameterError
        Naming ``config``: it cannot be loaded, or lacks a colour space, display or
        view the frame needs.
    """
    scene = scene_module.get_scene(name)
    if film is not None:
        scene = scene.with_film(film)
    width, height = size
    carried = getattr(lookup, "processors", None)  # a make_lookup lookup's processors
    if isinstance(config, ConfigProcessors):
        processors = config
    elif config is None and carried is not None:
        processors = carried
    else:
        processors = ConfigProcessors(config)
    lookup = lookup or make_lookup(processors)
    picture = scene.render(width, height, lookup=lookup, seed=seed, frame=frame)
    rgb = display_image(picture, display, view, processors)
    rgb, _ = draw_labels(rgb, picture.labels, label_code(display))
    return picture, rgb


def _exr_attributes(scene, picture, *, seed, frame, display, view):
    attrs = {
        "oiio:ColorSpace": EXR_COLORSPACE,
        "ocio_thinfilm:colorspace": EXR_DOC,
        "ocio_thinfilm:scene": f"{scene.name} ({scene.figure}): {scene.title}",
        "ocio_thinfilm:seed": int(seed),
        "ocio_thinfilm:frame": int(frame),
        "ocio_thinfilm:png_view": f"{display} / {view}",
        "ocio_thinfilm:tables": "; ".join(
            f"{t.kind} over {t.encoding} in [{t.range[0]:g}, {t.range[1]:g}], {t.entries} entries"
            for t in scene.tables
        ),
    }
    for channel, doc in picture.aov_docs.items():
        attrs[f"ocio_thinfilm:aov:{channel}"] = doc
    for key, value in picture.attributes.items():
        number = isinstance(value, (int, float, np.floating))
        attrs[f"ocio_thinfilm:{key}"] = float(value) if number else str(value)
    return attrs


def frame_paths(name: str, out_dir: Path, frame: int | None) -> list[Path]:
    """Return the EXR and PNG paths of one frame of one scene.

    Parameters
    ----------
    name : str
        The scene's name.
    out_dir : pathlib.Path
        The output directory.
    frame : int or None
        The frame number (``NAME.####``), or ``None`` for the still (``NAME``).

    Returns
    -------
    list of pathlib.Path
        ``[out_dir / "NAME[.####].exr", out_dir / "NAME[.####].png"]``.

    Examples
    --------
    >>> [p.name for p in frame_paths("oil", Path("renders"), 12)]
    ['oil.0012.exr', 'oil.0012.png']
    """
    stem = name if frame is None else f"{name}.{frame:04d}"
    return [Path(out_dir) / f"{stem}.exr", Path(out_dir) / f"{stem}.png"]


def save_frame(
    name: str,
    picture: scene_module.Picture,
    rgb: np.ndarray,
    out_dir: Path,
    *,
    seed: int,
    frame: int | None,
    display: str,
    view: str,
    tx: Transaction | None = None,
    film: scene_module.TableSpec | None = None,
) -> list[Path]:
    """Write a rendered frame as ``NAME[.####].exr`` and ``.png``.

    The pair is one transaction (:mod:`.io`): both files are written aside and checked,
    then renamed together, so a failed EXR never leaves a new PNG beside an old EXR.

    Parameters
    ----------
    name : str
        The scene's name (a key of :data:`ocio_thinfilm.render.scenes.SCENES`).
    picture : ocio_thinfilm.render.scenes.Picture
        The scene-linear picture: the EXR's R, G, B (CIE XYZ) and AOV channels.
    rgb : numpy.ndarray
        (H, W, 3) display code values in [0, 1]: the PNG (16 bits per channel for an
        HDR display of the registry, else 8).
    out_dir : pathlib.Path
        The output directory.
    seed : int
        The noise seed, recorded in the EXR.
    frame : int or None
        The frame number, or ``None`` for the still (frame 1, no number in the names).
    display : str
        The PNG's display (recorded, and choosing its tag: :func:`png_colorspace`).
    view : str
        The PNG's view (recorded; a picture shown only through ``Raw`` views gets a
        ``"data"`` tag).
    tx : Transaction, optional
        Join the caller's transaction (committed by the caller) instead of committing
        the pair on return.
    film : TableSpec, optional
        The user's film the frame was rendered with (recorded in the EXR's metadata).

    Returns
    -------
    list of pathlib.Path
        The EXR and PNG paths.

    Raises
    ------
    ValueError
        For an unknown scene.
    ParameterError
        Naming ``out_dir``, if a file cannot be written there (see
        :func:`~ocio_thinfilm.io.destinations.check_output_file`).
    OSError
        If a file cannot be written.
    """
    if tx is None:
        with transaction() as own:
            return save_frame(
                name,
                picture,
                rgb,
                out_dir,
                seed=seed,
                frame=frame,
                display=display,
                view=view,
                tx=own,
                film=film,
            )
    scene = scene_module.get_scene(name)
    if film is not None:
        scene = scene.with_film(film)
    stem = name if frame is None else f"{name}.{frame:04d}"
    for path in frame_paths(name, out_dir, frame):
        check_output_file(path, parameter="out_dir", in_new_folder=True)
    channels = ["R", "G", "B"] + list(picture.aovs)
    data = np.concatenate([picture.xyz] + [a[..., None] for a in picture.aovs.values()], axis=-1)
    attrs = _exr_attributes(scene, picture, seed=seed, frame=frame or 1, display=display, view=view)
    # ZIPS: lossless, and faster than zip or piz on these pictures. The two files are
    # encoded in parallel (OpenImageIO releases the GIL); each is written atomically.
    attrs["compression"] = "zips"
    # OpenImageIO stamps EXRs with the current time unless told otherwise: a fixed
    # stamp (the paper's conference date) keeps the bytes a function of the arguments.
    attrs["DateTime"] = FIXED_DATETIME
    # R, G, B hold CIE XYZ: the EXR chromaticities of XYZ (white = equal energy E).
    attrs["chromaticities"] = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0 / 3.0, 1.0 / 3.0)
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(max_workers=2) as pool:
        exr_job = pool.submit(
            write_image,
            out_dir / f"{stem}.exr",
            data,
            channel_names=channels,
            dtype="half",
            attributes=attrs,
            tx=tx,
        )
        raw_views = {v.name for v in registry.VIEW_LIST if v.raw}
        raw = all((region[2] or view) in raw_views for region in picture.regions)
        png_tag = "data" if raw else png_colorspace(display)
        entry = registry.find_display(display)
        png_attributes: dict[str, Any] = {"png:compressionLevel": 3, "oiio:ColorSpace": png_tag}
        if not raw and isinstance(entry, registry.Display) and entry.png_cicp is not None:
            png_attributes["CICP"] = entry.png_cicp
        # HDR code values need 16 bits (PQ: 8-bit steps are visible banding)
        png_job = pool.submit(
            write_image,
            out_dir / f"{stem}.png",
            rgb,
            dtype="uint16" if entry is not None and entry.hdr else "uint8",
            attributes=png_attributes,
            tx=tx,
        )
        return [exr_job.result(), png_job.result()]


def write_frame(
    name: str,
    out_dir: Path,
    size: tuple[int, int],
    *,
    seed: int,
    frame: int | None,
    display: str,
    view: str,
    lookup: scene_module.Lookup | None = None,
    config: ConfigProcessors | ocio_ops.Config | StrPath | None = None,
    tx: Transaction | None = None,
    film: scene_module.TableSpec | None = None,
) -> list[Path]:
    """Render one frame of a scene and write ``NAME[.####].exr`` and ``.png``.

    :func:`render_scene` then :func:`save_frame`.

    Parameters
    ----------
    name : str
        A scene of :data:`ocio_thinfilm.render.scenes.SCENES`.
    out_dir : pathlib.Path
        The output directory.
    size : tuple of int
        (width, height) in pixels.
    seed : int
        Noise seed, an integer >= 0.
    frame : int or None
        Frame number, or ``None`` for the still (rendered as frame 1).
    display : str
        A display of the config.
    view : str
        A view of that display.
    lookup : callable, optional
        As for :func:`render_scene`.
    config : ConfigProcessors, PyOpenColorIO.Config, str or os.PathLike, optional
        As for :func:`render_scene`.
    tx : Transaction, optional
        As for :func:`save_frame`.
    film : TableSpec, optional
        A user's film, as for :func:`render_scene`.

    Returns
    -------
    list of pathlib.Path
        The EXR and PNG paths.

    Raises
    ------
    ValueError
        For an unknown scene.
    ParameterError
        Naming ``config`` or ``out_dir`` (see :func:`render_scene`,
        :func:`save_frame`).
    OSError
        If a file cannot be written.
    """
    picture, rgb = render_scene(
        name,
        size,
        seed=seed,
        frame=frame or 1,
        display=display,
        view=view,
        lookup=lookup,
        config=config,
        film=film,
    )
    return save_frame(
        name,
        picture,
        rgb,
        out_dir,
        seed=seed,
        frame=frame,
        display=display,
        view=view,
        tx=tx,
        film=film,
    )

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

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.io import StrPath, Transaction, check_output_file, transaction, write_image
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
DEFAULT_VIEW = "Constant-Lightness Clip"

#: How the EXR's colour channels are to be read (also written into every EXR).
EXR_COLORSPACE = "CIE-XYZ-D65"
EXR_DOC = (
    "R,G,B hold scene-linear CIE XYZ (1931 2-degree observer, D65, Y = 1 is the "
    "perfect white under the scene's unit illuminant)"
)


def png_colorspace(display: str) -> str:
    """How a PNG for ``display`` is tagged (an OpenImageIO colour interop ID, the
    registry display's ``png_colorspace``): sRGB gets PNG's sRGB chunk, Display P3 and
    Rec.2020 (BT.1886 gamma 2.4) a cICP chunk, the displays of other configs (an ACES
    config merged with ``bake --into``) ``"data"``, no tag -- never a wrong sRGB one. The
    HDR displays get their cICP chunk (BT.2100 PQ: 9 16 0 1, HLG: 9 18 0 1, P3-D65 PQ: 12
    16 0 1) and 16 bits per channel.

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
    """The captions' code value on ``display``: :data:`LABEL_CODE` on SDR displays; on
    the registry's HDR displays the code of the same light relative to the 203 cd/m2
    reference white (graphics white of ITU-R BT.2408), not 0.92 of the PQ / HLG range.

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
    """Draw ``(x, y, text, size)`` captions, centred at x, with OpenImageIO's
    ``render_text`` and its bundled font, in the grey of code value ``code``. Returns
    (image, whether text was drawn)."""
    if not labels:
        return rgb, True
    import OpenImageIO as oiio

    buf = oiio.ImageBuf(oiio.ImageSpec(rgb.shape[1], rgb.shape[0], 3, oiio.FLOAT))
    buf.set_pixels(oiio.ROI(), np.ascontiguousarray(rgb, dtype=np.float32))
    drawn = True
    for x, y, text, size in labels:
        ok = oiio.ImageBufAlgo.render_text(
            buf, int(x), int(y), text, int(size), "", (code, code, code), "center", "baseline", 0
        )
        drawn = drawn and bool(ok)
    if not drawn:
        return rgb, False
    pixels = buf.get_pixels(oiio.FLOAT)
    assert pixels is not None  # the buffer was filled above
    return pixels, True


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
    """Render one frame through a config's processors: returns (picture,
    display-encoded RGB float32). ``config``: a :class:`ConfigProcessors`, a
    ``PyOpenColorIO.Config`` or a path (default: :data:`DEFAULT_CONFIG`); a ``lookup``
    from :func:`make_lookup` brings its own. ``film``: a user's film for the oil or
    soap scene (:meth:`ocio_thinfilm.render.scenes.Scene.with_film`)."""
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
    """The EXR and PNG paths of one frame of one scene."""
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
    """Write a rendered frame as ``NAME[.####].exr`` and ``.png``; returns the paths.

    The pair is one transaction (:mod:`.io`): both files are written aside and checked,
    then renamed together, so a failed EXR never leaves a new PNG beside an old EXR.
    With ``tx`` they join the caller's transaction instead (committed by the caller).
    ``film``: the user's film the frame was rendered with (its EXR metadata)."""
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
        check_output_file(path, parameter="out_dir")
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
        # HDR code values need 16 bits (PQ: 8-bit steps are visible banding)
        png_job = pool.submit(
            write_image,
            out_dir / f"{stem}.png",
            rgb,
            dtype="uint16" if entry is not None and entry.hdr else "uint8",
            attributes={"png:compressionLevel": 3, "oiio:ColorSpace": png_tag},
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
    """Render and write ``NAME[.####].exr`` and ``.png``; returns the paths (``film``:
    a user's film, see :func:`render_scene`)."""
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

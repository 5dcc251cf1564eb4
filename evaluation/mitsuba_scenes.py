"""Mitsuba 3 scenes that measure a BSDF's colour: a flat plate under a uniform white sky.

The tests (tests/test_mitsuba.py) and the benchmark (benchmarks/fig_mitsuba.py) share
them. The plate (Mitsuba's ``rectangle``, 2 x 2 in the xy plane, normal +z) fills an
orthographic camera's frame seen at ``angle`` degrees from the normal (in the yz plane),
so every pixel sees the plate at that angle; the ``constant`` emitter is D65 in
Mitsuba's spectral variants (radiance 1: the film's RGB (1, 1, 1)). A black plate (a
``diffuse`` BSDF of reflectance 0, 400 x 400) behind the film (``side="reflect"``) hides
the sky the film transmits, so the pixel is the reflectance alone; in front of it
(``side="transmit"``, behind the camera, which sits 2 units from the film) it hides the
sky the film reflects, so the pixel is the transmittance.

:func:`plate_XYZ` renders and returns the frame's mean CIE XYZ (Mitsuba's linear sRGB
through colour-science's sRGB matrix: the D65 white at Y = 1).
"""

from __future__ import annotations

import contextlib
import time

import numpy as np

__all__ = ["plate_scene", "plate_image", "plate_XYZ", "delta_e"]


def plate_scene(
    bsdf: dict,
    angle: float,
    *,
    side: str = "both",
    size: int = 8,
    spp: int = 16,
    sampler: str = "ldsampler",
    window: float = 0.1,
) -> dict:
    """The scene dict: the plate with ``bsdf`` seen at ``angle`` degrees (see the module)."""
    import mitsuba as mi

    T = mi.ScalarTransform4f
    th = np.radians(angle)
    eye = [0.0, 2.0 * np.sin(th), 2.0 * np.cos(th)]
    scene = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 2},
        "sky": {"type": "constant"},
        "sensor": {
            "type": "orthographic",
            # a window of half-width ``window`` at the plate's centre: inside the
            # plate at every angle
            "to_world": T().look_at(origin=eye, target=[0, 0, 0], up=[0, 1, 0])
            @ T().scale([window, window, 1.0]),
            "film": {
                "type": "hdrfilm",
                "width": size,
                "height": size,
                "rfilter": {"type": "box"},
                "pixel_format": "rgb",
            },
            "sampler": {"type": sampler, "sample_count": spp},
        },
        "plate": {"type": "rectangle", "bsdf": bsdf},
    }
    if side != "both":
        z = -3.0 if side == "reflect" else 3.0
        scene["blocker"] = {
            "type": "rectangle",
            "to_world": T().translate([0.0, 0.0, z]) @ T().scale(200.0),
            "bsdf": {"type": "twosided", "bsdf": {"type": "diffuse", "reflectance": 0.0}},
        }
    return scene


def plate_image(
    bsdf: dict, angle: float, *, evaluated: bool = False, **kwargs: object
) -> tuple[np.ndarray, float]:
    """Render :func:`plate_scene` and return (its XYZ image, seconds to render).

    ``evaluated``: inside :func:`ocio_thinfilm.export.hosts.mitsuba.evaluated_mode` (JIT
    variants with the thinfilm plugin). The time covers loading and rendering.
    """
    import colour
    import mitsuba as mi

    from ocio_thinfilm.export.hosts import mitsuba as tfm

    mode = tfm.evaluated_mode() if evaluated else contextlib.nullcontext()
    start = time.perf_counter()
    with mode:
        image = np.array(mi.render(mi.load_dict(plate_scene(bsdf, angle, **kwargs))))
    seconds = time.perf_counter() - start
    return image @ colour.models.RGB_COLOURSPACE_sRGB.matrix_RGB_to_XYZ.T, seconds


def plate_XYZ(bsdf: dict, angle: float, **kwargs: object) -> tuple[np.ndarray, float]:
    """Return (the mean XYZ of :func:`plate_image`'s frame, seconds to render)."""
    image, seconds = plate_image(bsdf, angle, **kwargs)
    return image.reshape(-1, 3).mean(axis=0), seconds


def delta_e(XYZ_a: np.ndarray, XYZ_b: np.ndarray) -> float:
    """CIE 2000 between two XYZ colours (D65 white, Y = 1)."""
    import colour

    return float(
        colour.delta_E(colour.XYZ_to_Lab(XYZ_a), colour.XYZ_to_Lab(XYZ_b), method="CIE 2000")
    )

"""``ocio-thinfilm demo``: the colour of a soap film, and a strip of Newton's colours."""

from __future__ import annotations

import argparse
import sys

import numpy as np

from ocio_thinfilm import registry
from ocio_thinfilm.colour import clip, colorimetry, encodings
from ocio_thinfilm.io import check_output_file, is_stdout, write_image
from ocio_thinfilm.physics import spectra

SOAP_INDEX = 1.33


def soap_film_colour(thickness_nm: float, display: str = "sRGB", theta: float = 0.0) -> dict:
    """Return every stage's value for one soap film (phase change, n = 1.33).

    Parameters
    ----------
    thickness_nm : float
        Physical film thickness in nm.
    display : str, optional
        The SDR display whose linear RGB and clip are shown (default ``"sRGB"``).
    theta : float, optional
        Viewing angle in degrees from the normal (default 0, normal incidence).

    Returns
    -------
    dict
        ``optical_thickness_nm`` (float, t' = n t cos(theta_t)), ``XYZ`` (D65, white
        Y = 1), ``linear_rgb`` (the display's linear RGB, unclipped), ``clipped_rgb``
        (after the constant-lightness clip) and ``encoded`` (the clipped RGB, clamped to
        [0, 1] and encoded with the display's encoding).
    """
    t_opt = spectra.optical_thickness(thickness_nm, SOAP_INDEX, theta)
    XYZ = colorimetry.film_XYZ(t_opt)
    rgb = colorimetry.XYZ_to_RGB(XYZ, display)
    clipped = clip.clip_RGB(rgb, display)
    return {
        "optical_thickness_nm": float(t_opt),
        "XYZ": XYZ,
        "linear_rgb": rgb,
        "clipped_rgb": clipped,
        "encoded": _encode(clipped, display),
    }


def _encode(rgb, display="sRGB"):
    """Display-linear RGB clamped to [0, 1] -> code values in ``display``'s encoding.

    The registry's encoding as the config's OCIO op applies it (the sRGB piecewise curve
    of IEC 61966-2-1, or BT.1886's inverse EOTF with a black level of 0):
    :func:`ocio_thinfilm.colour.encodings.encode`.
    """
    encoding = registry.as_display(display, hdr=False, parameter="display").encoding
    return encodings.encode(np.clip(rgb, 0, 1), encoding)


def soap_strip(
    width: int = 1024, height: int = 96, max_thickness_nm: float = 2000.0, display: str = "sRGB"
) -> np.ndarray:
    """Return a display-encoded strip of soap-film colours (n = 1.33, normal incidence).

    Physical thickness 0..max left to right. Top half: constant-lightness clip; bottom
    half: per-channel clamp; both encoded with the sRGB curve.

    Parameters
    ----------
    width, height : int, optional
        Size in pixels (default 1024 x 96).
    max_thickness_nm : float, optional
        Physical thickness at the right edge, in nm (default 2000).
    display : str, optional
        The SDR display whose gamut the colours are clipped into (default ``"sRGB"``).

    Returns
    -------
    numpy.ndarray
        float32 (height, width, 3) code values in [0, 1].
    """
    t = np.linspace(0.0, max_thickness_nm, width)
    rgb = colorimetry.XYZ_to_RGB(
        colorimetry.film_XYZ(spectra.optical_thickness(t, SOAP_INDEX)), display
    )
    top = _encode(clip.clip_RGB(rgb, display), display)
    bottom = _encode(clip.clamp_RGB(rgb), display)
    rows = [top] * (height // 2) + [bottom] * (height - height // 2)
    return np.stack(rows).astype(np.float32)


def run(args: argparse.Namespace) -> int:
    """Run ``ocio-thinfilm demo``: print one film's colour at every stage, write the strip.

    Parameters
    ----------
    args : argparse.Namespace
        The parsed options: ``thickness`` (nm) and ``out`` (the PNG). The text goes to
        stderr when ``out`` is standard output.

    Returns
    -------
    int
        The exit code, 0.

    Raises
    ------
    ParameterError
        Naming ``out``, if it cannot be written.
    OSError
        If the PNG cannot be written.
    """
    out = check_output_file(args.out)
    text = sys.stderr if is_stdout(out) else sys.stdout  # keep a PNG on stdout clean
    result = soap_film_colour(args.thickness)
    print(
        f"Soap film, n = {SOAP_INDEX}, t = {args.thickness:g} nm, normal incidence "
        f"(t' = {result['optical_thickness_nm']:g} nm)",
        file=text,
    )
    for label, key in (
        ("XYZ (D65, Y_white = 1)", "XYZ"),
        ("linear sRGB, unclipped", "linear_rgb"),
        ("constant-lightness clip", "clipped_rgb"),
    ):
        # numpy's 1.13 layout, which colour-science's import makes the default: the same
        # text whether or not this process imported it
        row = np.array2string(result[key], precision=4, legacy="1.13")
        print(f"  {label:<28}{row}", file=text)
    code = "#" + "".join(f"{int(round(v * 255)):02X}" for v in result["encoded"])
    print(f"  sRGB-encoded                {code}", file=text)
    write_image(out, soap_strip())
    print(
        f"wrote {out}: soap-film colours for 0-2 um (top: constant-lightness clip, "
        "bottom: channel clamp)",
        file=text,
    )
    return 0


def register(sub: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add the ``demo`` command to the ``sub`` parsers.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The sub-parsers of the ``ocio-thinfilm`` parser.
    """
    p = sub.add_parser(
        "demo",
        help="print a soap film's colour and write a strip of Newton's colours",
        description="Print a soap film's colour at one thickness (n = 1.33, normal "
        "incidence: its XYZ, linear sRGB, the constant-lightness clip and the sRGB code) "
        "and write a PNG strip of soap-film colours for 0-2 um (top: the clip, bottom: a "
        "channel clamp).",
    )
    p.add_argument(
        "--thickness", type=float, default=300.0, help="physical film thickness in nm (default 300)"
    )
    p.add_argument(
        "--out",
        default="soap_strip.png",
        help="PNG to write (default soap_strip.png in the current folder)",
    )
    p.set_defaults(func=run)

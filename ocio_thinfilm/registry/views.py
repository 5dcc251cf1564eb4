"""The registry's views: one :class:`View` per kind, shown on every display.

A view's kind (:data:`VIEW_KINDS`) is what it does; each stage of the pipeline maps the
kinds to its own code. Part of :mod:`ocio_thinfilm.registry` (import it from there).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = [
    "VIEW_KINDS",
    "View",
    "VIEW_LIST",
    "view_of_kind",
    "CLIP_VIEW",
    "COMPRESS_VIEW",
]


#: The kinds of view: what a view does, which each stage maps to its own code (the
#: config's transforms, the analytic maps, the shaders); a view is one :class:`View`
#: entry of a kind.
VIEW_KINDS = ("clip", "compress", "clamp", "aces", "raw")


@dataclass(frozen=True)
class View:
    """A view of every display.

    Parameters
    ----------
    name : str
        The OCIO view name.
    kind : str
        What it does, one of :data:`VIEW_KINDS`: ``"clip"`` the constant-lightness clip
        (Smits & Meyer 1990, Section 3.2), ``"compress"`` the soft constant-lightness
        compression, ``"clamp"`` a per-channel clamp, ``"aces"`` OCIO's ACES 1.3 gamut
        compression, ``"raw"`` no view transform (the data passes through).
    description : str, optional
        The description of its view transforms; empty (the default) for the raw view.
        The compression's holds the fields ``{threshold}`` and ``{limit}``
        (:meth:`describe`).
    """

    name: str
    kind: str
    description: str = ""

    @property
    def raw(self) -> bool:
        """Whether the view passes data through (no view transform)."""
        return self.kind == "raw"

    def describe(self, threshold: str, limit: str) -> str:
        """Return the description with the compression's knobs filled in.

        Parameters
        ----------
        threshold, limit : str
            The knobs as the description states them
            (:func:`ocio_thinfilm.colour.compress.knob_text`); only the compression's
            description uses them.

        Returns
        -------
        str

        Examples
        --------
        >>> "beyond 0.6 of the distance" in view_of_kind("compress").describe("0.6", "1.5")
        True
        """
        return self.description.format(threshold=threshold, limit=limit)


_COMPRESS_DESCRIPTION = (
    "Soft constant-lightness gamut compression: along the same ray as the clip "
    "(towards the grey of the same luminance Y, which it keeps exactly), colours "
    "beyond {threshold} of the distance to the gamut boundary are compressed by the "
    "ACES 1.3 power curve so that {limit} boundary distances reach the boundary; "
    "further out, the clip. Smooth where the clip is flat (four 3D LUTs, two of them "
    "the clip's)."
)


VIEW_LIST = (
    View(
        "Constant-Lightness Clip",
        "clip",
        "Smits & Meyer 1990 Section 3.2: display-linear RGB clipped at constant luminance "
        "Y towards the display's neutral axis (two 3D LUTs, faces through black then "
        "through white); scene-linear 1.0 is display white, above white gives white, no "
        "tone mapping.",
    ),
    View("Constant-Lightness Compress", "compress", _COMPRESS_DESCRIPTION),
    View("Channel Clamp", "clamp", "Baseline: display-linear RGB clamped per channel to [0, 1]."),
    View(
        "ACES Gamut Compression",
        "aces",
        "Baseline: OCIO's ACES 1.3 reference gamut compression (ACES_GamutComp13) in "
        "display-linear RGB, then a clamp to [0, 1].",
    ),
    View("Raw", "raw"),
)


def view_of_kind(kind: str) -> View:
    """Return the view of ``kind`` (one of :data:`VIEW_KINDS`).

    Parameters
    ----------
    kind : str
        A view kind.

    Returns
    -------
    View

    Raises
    ------
    ValueError
        If no view is of that kind.

    Examples
    --------
    >>> view_of_kind("clip").name
    'Constant-Lightness Clip'
    """
    for view in VIEW_LIST:
        if view.kind == kind:
            return view
    raise ValueError(f"no view of kind {kind!r}")


#: The constant-lightness clip's view and the compression's (whose knobs, threshold and
#: limit, a bake may set).
CLIP_VIEW = view_of_kind("clip").name
COMPRESS_VIEW = view_of_kind("compress").name

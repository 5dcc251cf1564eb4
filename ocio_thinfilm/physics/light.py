"""The light a film is seen under: colour-science's names of illuminants and adaptations.

A film file's ``illuminant`` and ``adaptation`` keys name a spectrum of
``colour.SDS_ILLUMINANTS`` and a cone space of ``colour.CHROMATIC_ADAPTATION_TRANSFORMS``;
:func:`ocio_thinfilm.colour.adaptation.viewing_weights` integrates under them. The
defaults need no import of colour-science.
"""

from __future__ import annotations

import re

from ocio_thinfilm.checks import ParameterError

__all__ = ["SCENE_ILLUMINANT", "DEFAULT_ADAPTATION", "check_illuminant", "check_adaptation"]

#: The scene white every colour is adapted to.
SCENE_ILLUMINANT = "D65"
#: The default chromatic adaptation transform (a key of
#: ``colour.CHROMATIC_ADAPTATION_TRANSFORMS``; CIE 159:2004).
DEFAULT_ADAPTATION = "CAT02"


def _fluorescent(name: str) -> str:
    """Return colour-science's key of CIE's name for a fluorescent illuminant (F2 -> FL2)."""
    return re.sub(r"^F(\d)", r"FL\1", name)


def check_illuminant(name: str, parameter: str = "illuminant") -> str:
    """Return colour-science's key of an illuminant's name.

    Parameters
    ----------
    name : str
        A key of ``colour.SDS_ILLUMINANTS`` (``D65``, ``A``, ``FL2``, ...); CIE's names
        of the fluorescent illuminants (``F1`` to ``F12``, ``F3.1`` to ``F3.15``) are
        accepted for colour-science's ``FL1`` ...
    parameter : str, optional
        The parameter named in the error.

    Returns
    -------
    str
        The key.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``parameter``) naming the allowed names.

    Examples
    --------
    >>> check_illuminant("F11"), check_illuminant("D65")
    ('FL11', 'D65')
    """
    if name == SCENE_ILLUMINANT:  # the default needs no colour-science import
        return name
    import colour

    if isinstance(name, str):
        for key in (name, _fluorescent(name)):
            if key in colour.SDS_ILLUMINANTS:
                return key
    raise ParameterError(
        parameter,
        f" must be one of colour-science's colour.SDS_ILLUMINANTS (F1-F12 for FL1-FL12 too): "
        f"{', '.join(colour.SDS_ILLUMINANTS)}; got {name!r}",
    )


def check_adaptation(name: str, parameter: str = "adaptation") -> str:
    """Return ``name`` if it is a chromatic adaptation transform of colour-science.

    Parameters
    ----------
    name : str
        A key of ``colour.CHROMATIC_ADAPTATION_TRANSFORMS`` (``CAT02``, ``Bradford``,
        ``CAT16``, ``Von Kries``, ``XYZ Scaling``, ...).
    parameter : str, optional
        The parameter named in the error.

    Returns
    -------
    str
        ``name``.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``parameter``) naming the allowed names.
    """
    if name == DEFAULT_ADAPTATION:
        return name
    import colour

    if isinstance(name, str) and name in colour.CHROMATIC_ADAPTATION_TRANSFORMS:
        return name
    raise ParameterError(
        parameter,
        " must be one of colour-science's colour.CHROMATIC_ADAPTATION_TRANSFORMS: "
        f"{', '.join(colour.CHROMATIC_ADAPTATION_TRANSFORMS)}; got {name!r}",
    )

"""The built-in library: common film and substrate materials with cited dispersion data.

A material is added as one :data:`LIBRARY` entry: a vendored refractiveindex.info file
in ``ocio_thinfilm/data/materials`` (public domain, trimmed to 0.3-1.0 um, its header
naming its page and source commit), a constant index, or a dispersion :class:`Formula`;
its note says what it is and cites where the data come from.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from importlib import resources

from ocio_thinfilm.checks import ParameterError
from ocio_thinfilm.physics.materials.model import Formula, Material
from ocio_thinfilm.physics.materials.refractiveindex import read_refractiveindex_yaml

__all__ = ["LIBRARY", "builtin", "builtin_names", "find_builtin"]


@dataclass(frozen=True)
class _Entry:
    file: str | None  # a vendored file in ocio_thinfilm/data/materials, or None
    n: float = 1.0
    k: float = 0.0
    note: str = ""
    aliases: tuple[str, ...] = ()
    formula: Formula | None = None  # a dispersion formula instead of a file or constant


#: Built-in materials: name -> (vendored file, constant or formula; what it is and where
#: its data come from; aliases). Files are refractiveindex.info pages (public domain),
#: trimmed to 0.3-1.0 um; each file's header names its page and source commit.
LIBRARY: dict[str, _Entry] = {
    "air": _Entry(
        "air.yml", note="standard air, 15 C (Ciddor 1996, Appl. Opt. 35, 1566)", aliases=("Air",)
    ),
    "vacuum": _Entry(None, 1.0, note="n = 1 exactly"),
    "water": _Entry(
        "water.yml",
        note="distilled water, 20 C (Daimon & Masumura 2007, Appl. Opt. 46, 3811)",
        aliases=("H2O",),
    ),
    "soap film": _Entry(
        "water.yml",
        note="a soap film is water with a little surfactant: water's dispersion "
        "(Daimon & Masumura 2007), as the paper's n = 1.33",
        aliases=("soap",),
    ),
    "mineral oil": _Entry(
        None,
        1.47,
        note="light mineral (paraffin) oil, constant n = 1.47 (typical n_D 1.46-1.48 of "
        "mineral oils; the oil of this project's examples); no dispersion data vendored",
        aliases=("oil",),
    ),
    "fused silica": _Entry(
        "fused_silica.yml",
        note="fused silica, 20 C (Malitson 1965, J. Opt. Soc. Am. 55, 1205; Sellmeier)",
        aliases=("fused_silica",),
    ),
    "SiO2": _Entry(
        "sio2.yml",
        note="sputtered SiO2 thin film (Lemarchand 2013; Gao, Lemarchand & Lequime 2012, "
        "Opt. Express 20, 15734)",
    ),
    "BK7": _Entry(
        "bk7.yml",
        note="SCHOTT N-BK7 (SCHOTT Zemax catalogue 2017-01-20b; Sellmeier and k)",
        aliases=("N-BK7", "glass"),
    ),
    "MgF2": _Entry(
        "mgf2.yml",
        note="MgF2, ordinary ray, 19 C (Dodge 1984, Appl. Opt. 23, 1980; Sellmeier)",
    ),
    "TiO2": _Entry(
        "tio2.yml",
        note="TiO2 thin film, 200 nm on glass (Sarkar et al. 2019, ACS Appl. Mater. "
        "Interfaces 11, 13752); every 5th nm of the table",
    ),
    "Si3N4": _Entry(
        "si3n4.yml",
        note="silicon nitride, LPCVD film (Philipp 1973, J. Electrochem. Soc. 120, 295; "
        "Sellmeier of Baak 1982, Appl. Opt. 21, 1069)",
        aliases=("silicon nitride",),
    ),
    "Al2O3": _Entry(
        "al2o3.yml",
        note="synthetic sapphire, ordinary ray, 20 C (Malitson & Dodge 1972, J. Opt. Soc. "
        "Am. 62, 1405; Sellmeier)",
        aliases=("alumina", "sapphire"),
    ),
    "HfO2": _Entry(
        "hfo2.yml",
        note="e-beam HfO2 film, 113 nm on Si (Franta, Necas & Ohlidal 2015, Appl. Opt. 54, 9108)",
        aliases=("hafnia",),
    ),
    "Ta2O5": _Entry(
        "ta2o5.yml",
        note="ion-assisted e-beam Ta2O5 film, 400 nm on BK7 (Gao, Lemarchand & Lequime "
        "2012, Opt. Express 20, 15734)",
        aliases=("tantala",),
    ),
    "Nb2O5": _Entry(
        "nb2o5.yml",
        note="sputtered Nb2O5 film, 500 nm on BK7 (Lemarchand 2013; method of Gao, "
        "Lemarchand & Lequime 2012, Opt. Express 20, 15734)",
    ),
    "ZnS": _Entry(
        "zns.yml",
        note="zinc sulfide (Querry 1987, CRDEC-CR-88009)",
        aliases=("zinc sulfide", "zinc sulphide"),
    ),
    "ITO": _Entry(
        "ito.yml",
        note="indium tin oxide, 72 nm film on BK7 (Konig et al. 2014, ACS Nano 8, 6182)",
        aliases=("indium tin oxide", "In2O3-SnO2"),
    ),
    "chitin": _Entry(
        None,
        note="butterfly-wing chitin, Cauchy n = 1.517 + 8.80e3 nm^2 / lambda^2 "
        "(Leertouwer, Wilts & Stavenga 2011, Opt. Express 19, 24061)",
        formula=Formula(5, (1.517, 8.80e-3, -2.0), (300.0, 1000.0)),
    ),
    "Fe2O3": _Entry(
        "fe2o3.yml",
        note="haematite, alpha-Fe2O3, ordinary ray (Querry 1985, CRDC-CR-85034): the "
        "oxide of temper colours",
        aliases=("haematite", "hematite", "iron oxide"),
    ),
    "Si": _Entry(
        "si.yml",
        note="crystalline silicon, 300 K (Green 2008, Sol. Energy Mater. Sol. Cells 92, 1305)",
        aliases=("silicon",),
    ),
    "Ti": _Entry(
        "ti.yml",
        note="titanium (Johnson & Christy 1974, Phys. Rev. B 9, 5056)",
        aliases=("titanium",),
    ),
    "Fe": _Entry(
        "fe.yml",
        note="iron (Johnson & Christy 1974, Phys. Rev. B 9, 5056)",
        aliases=("iron",),
    ),
    "Al": _Entry(
        "al.yml",
        note="aluminium, Lorentz-Drude fit (Rakic et al. 1998, Appl. Opt. 37, 5271)",
        aliases=("aluminium", "aluminum"),
    ),
    "Cu": _Entry(
        "cu.yml",
        note="copper (Johnson & Christy 1972, Phys. Rev. B 6, 4370)",
        aliases=("copper",),
    ),
    "Ag": _Entry(
        "ag.yml",
        note="silver (Johnson & Christy 1972, Phys. Rev. B 6, 4370)",
        aliases=("silver",),
    ),
    "Au": _Entry(
        "au.yml",
        note="gold (Johnson & Christy 1972, Phys. Rev. B 6, 4370)",
        aliases=("gold",),
    ),
    "Cr": _Entry(
        "cr.yml",
        note="chromium, Lorentz-Drude fit (Rakic et al. 1998, Appl. Opt. 37, 5271)",
        aliases=("chromium",),
    ),
}


def _key(name: str) -> str:
    return re.sub(r"[\s_-]+", " ", name.strip()).lower()


_LOOKUP = {_key(alias): name for name, e in LIBRARY.items() for alias in (name,) + e.aliases}


def builtin_names() -> tuple[str, ...]:
    """Return the built-in materials' names (:data:`LIBRARY`).

    Returns
    -------
    tuple of str
        In the library's order.
    """
    return tuple(LIBRARY)


def find_builtin(name: str) -> str | None:
    """Return the built-in material ``name`` refers to.

    Parameters
    ----------
    name : str
        A name or alias (``gold`` for ``Au``); case, spaces, ``-`` and ``_`` do not
        matter.

    Returns
    -------
    str or None
        The library's name, ``None`` if there is none.

    Examples
    --------
    >>> find_builtin("Soap_Film"), find_builtin("gold"), find_builtin("mithril")
    ('soap film', 'Au', None)
    """
    return _LOOKUP.get(_key(name)) if isinstance(name, str) else None


_BUILTIN_CACHE: dict[str, Material] = {}


def builtin(name: str) -> Material:
    """Return a built-in material of :data:`LIBRARY` (see :func:`find_builtin` for names).

    Parameters
    ----------
    name : str
        Its name or an alias.

    Returns
    -------
    Material
        Its ``source`` says where the data come from.

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        Naming ``name`` and the library's names.

    Examples
    --------
    >>> gold = builtin("gold")
    >>> gold.name, gold.covers(380, 780), gold.absorbing
    ('Au', True, True)
    """
    key = find_builtin(name)
    if key is None:
        raise ParameterError(
            "name", f" must be a built-in material ({', '.join(LIBRARY)}), got {name!r}"
        )
    if key not in _BUILTIN_CACHE:
        entry = LIBRARY[key]
        if entry.formula is not None:
            material = Material(key, entry.formula, 0.0, entry.note)
        elif entry.file is None:
            material = Material(key, float(entry.n), float(entry.k), entry.note)
        else:
            resource = resources.files("ocio_thinfilm").joinpath("data", "materials", entry.file)
            read = read_refractiveindex_yaml(entry.file, key, text=resource.read_text("utf-8"))
            material = Material(key, read.n, read.k, f"{entry.note}; {read.source}", entry.file)
        _BUILTIN_CACHE[key] = material
    return _BUILTIN_CACHE[key]

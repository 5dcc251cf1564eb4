"""The YAML subset of refractiveindex.info's database files, read with the standard library.

Top-level keys, ``|`` block scalars and the ``DATA`` list of flat mappings: what those
files use, so PyYAML is not a dependency.
"""

from __future__ import annotations

import re

from ocio_thinfilm.checks import ParameterError

__all__ = ["parse", "numbers"]

_TOP = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*):\s*(.*?)\s*$")
_ITEM = re.compile(r"^(\s*)-\s+([A-Za-z_]+):\s*(.*?)\s*$")
_KEY = re.compile(r"^(\s+)([A-Za-z_]+):\s*(.*?)\s*$")


def parse(text: str, where: str) -> tuple[dict[str, str], list[dict[str, tuple[int, str]]]]:
    """Parse the YAML subset of a refractiveindex.info file.

    Parameters
    ----------
    text : str
        The file's contents.
    where : str
        The file, named in errors.

    Returns
    -------
    tuple
        Its top-level scalars and block scalars (key -> text), and the ``DATA`` list's
        entries (key -> (line, value)).

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``path``) naming the file and line of a line it cannot read.
    """
    lines = text.splitlines()
    top: dict[str, str] = {}
    entries: list[dict[str, tuple[int, str]]] = []
    i = 0

    def block(start: int, indent: int) -> tuple[str, int]:
        """Return the lines of a ``|`` block scalar more indented than ``indent``."""
        out, j = [], start
        while j < len(lines):
            line = lines[j]
            if line.strip() and len(line) - len(line.lstrip()) <= indent:
                break
            out.append(line.strip())
            j += 1
        return "\n".join(out).strip(), j

    while i < len(lines):
        line = lines[i]
        if not line.strip() or line.lstrip().startswith("#"):
            i += 1
            continue
        m = _TOP.match(line)
        if not m:  # an indented line of a top-level key we skip (CONDITIONS, PROPERTIES)
            i += 1
            continue
        key, value = m.groups()
        i += 1
        if key != "DATA":
            if value in ("|", ">"):
                value, i = block(i, 0)
            top[key] = value
            continue
        while i < len(lines):
            line = lines[i]
            if not line.strip() or line.lstrip().startswith("#"):
                i += 1
                continue
            item = _ITEM.match(line)
            if item:
                entries.append({item.group(2): (i + 1, item.group(3))})
                i += 1
                continue
            kv = _KEY.match(line)
            if kv and entries:
                number, (indent_text, k2, v2) = i + 1, kv.groups()
                i += 1
                if v2 in ("|", ">"):
                    v2, i = block(i, len(indent_text))
                entries[-1][k2] = (number, v2)
                continue
            if _TOP.match(line):
                break
            raise ParameterError("path", f": {where}:{i + 1}: cannot read {line.strip()!r}")
    return top, entries


def numbers(text: str, where: str, line: int) -> list[float]:
    """Return the white-space separated numbers of ``text``.

    Parameters
    ----------
    text : str
        The numbers.
    where : str
        The file, named in errors.
    line : int
        The line, named in errors.

    Returns
    -------
    list of float

    Raises
    ------
    ocio_thinfilm.checks.ParameterError
        (``path``) naming the file and line when one is not a number.
    """
    try:
        return [float(x) for x in text.split()]
    except ValueError:
        raise ParameterError("path", f": {where}:{line}: expected numbers") from None

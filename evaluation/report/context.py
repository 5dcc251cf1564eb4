"""What the sections share (:class:`Context`) and what each returns (:class:`Section`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ocio_thinfilm.io import atomic_file

__all__ = ["Context", "Section"]


class Context:
    """What every section shares: the output folder, the mode and the figures written.

    Parameters
    ----------
    out : pathlib.Path
        The output folder (``report.md``, PNGs, ``report.json``).
    quick : bool
        Smaller sweeps (the test suite's mode).
    tx : optional
        An :func:`ocio_thinfilm.io.transaction`: every file joins it and is committed
        with ``report.md``. Without one, each figure is written atomically on its own.
    """

    def __init__(self, out: Path, quick: bool, tx=None):
        self.out = out
        self.quick = quick
        self.tx = tx
        self.figures: list[str] = []

    def savefig(self, fig, name) -> str:
        """Write ``fig`` as ``<out>/<name>`` (PNG), close it, return its markdown link."""
        import matplotlib.pyplot as plt

        if self.tx is not None:
            fig.savefig(self.tx.file(self.out / name), dpi=110, bbox_inches="tight", format="png")
        else:
            with atomic_file(self.out / name) as tmp:
                fig.savefig(tmp, dpi=110, bbox_inches="tight", format="png")
        plt.close(fig)
        self.figures.append(name)
        return f"![{name}]({name})"


@dataclass
class Section:
    """One section's output.

    Attributes
    ----------
    markdown : str
        The section's text in ``report.md``.
    results : dict
        Its raw numbers, JSON key -> data, merged into ``report.json``.
    headline : dict
        Its headline facts, explicit id -> numbers, stored in
        ``report.json["headline"]`` and read by :mod:`.headline` (nothing is found by
        matching labels).
    """

    markdown: str
    results: dict = field(default_factory=dict)
    headline: dict = field(default_factory=dict)

"""``ocio-thinfilm report``: measure everything on this machine, write reports/report.md.

The report's code is not part of the installed package: it is the top-level
``evaluation`` package of the repository, beside ``benchmarks/`` (with matplotlib and
mpmath, the ``report`` extra). The command imports it as any package; where it is not
importable (an installed wheel, no checkout) it says in one line to run from a checkout.
"""

from __future__ import annotations

import argparse
import importlib.util
from pathlib import Path

__all__ = ["register"]

#: The one line ``report`` prints (exit 2) where ``evaluation`` is not importable.
NEEDS_CHECKOUT = (
    "the report needs a checkout of the repository (its evaluation/ folder is not "
    "installed with the package): run it from the checkout's top folder, "
    "pip install -e '.[report]' && python -m ocio_thinfilm report"
)


def _run_report():
    """``evaluation.report.run_report``, or a one-line UsageError."""
    from ocio_thinfilm.checks import UsageError

    try:
        found = importlib.util.find_spec("evaluation.report") is not None
    except ImportError:  # no ``evaluation`` package at all
        found = False
    if not found:
        raise UsageError(NEEDS_CHECKOUT)
    missing = [m for m in ("matplotlib", "mpmath") if importlib.util.find_spec(m) is None]
    if missing:
        raise UsageError(
            f"the report needs {' and '.join(missing)}: pip install -e '.[report]' in the checkout"
        )
    from evaluation.report import run_report

    return run_report


#: Where ``report --quick`` writes unless told: never the committed full report's folder.
QUICK_OUT = "reports/quick"


def _check_quick_out(out: Path) -> None:
    """Refuse a ``--quick`` report into a folder that holds a full one.

    A full report's ``report.json`` has no ``"quick": true``: a quick run must not
    replace the measurements a checkout commits (reports/report.md and its plots).
    """
    import json

    from ocio_thinfilm.checks import UsageError

    try:
        previous = json.loads((out / "report.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return
    if isinstance(previous, dict) and not previous.get("quick", False):
        raise UsageError(
            f"--out: {out} holds a full report; a --quick report goes to another folder "
            f"(default {QUICK_OUT})"
        )


def _run(args) -> int:
    run_report = _run_report()
    out = Path(args.out if args.out is not None else QUICK_OUT if args.quick else "reports")
    if args.quick:
        _check_quick_out(out)
    print(run_report(out, quick=args.quick, progress=not args.no_progress))
    return 0


def register(subparsers: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    """Add the ``report`` command to the parsers.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        The sub-parsers of the ``ocio-thinfilm`` parser.
    """
    p = subparsers.add_parser(
        "report",
        help="measure error against run time, peers, stability and throughput (from a checkout)",
        description="Measure everything on this machine and write <out>/report.md with PNG "
        "plots. Runs from a checkout of the repository (its evaluation/ folder).",
    )
    p.add_argument(
        "--out",
        default=None,
        help=f"output directory (default: reports; with --quick {QUICK_OUT}, and never a "
        "folder holding a full report)",
    )
    p.add_argument(
        "--quick",
        action="store_true",
        help="smaller sweeps (about 30 s): keeps the report working in the test suite",
    )
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(func=_run)

"""``ocio-thinfilm report``: measure everything on this machine, write reports/report.md."""

from __future__ import annotations

__all__ = ["register"]


def _run(args) -> int:
    from ocio_thinfilm.evaluation.report import run_report

    print(run_report(args.out, quick=args.quick, progress=not args.no_progress))
    return 0


def register(subparsers) -> None:
    """Add the ``report`` command to the parsers."""
    p = subparsers.add_parser(
        "report", help="measure error against run time, peers, stability and throughput",
        description="Measure everything on this machine and write <out>/report.md with PNG plots.")
    p.add_argument("--out", default="reports", help="output directory (default: reports)")
    p.add_argument("--quick", action="store_true",
                   help="smaller sweeps (about 30 s): keeps the report working in the test suite")
    p.add_argument("--no-progress", action="store_true", help="no progress bar")
    p.set_defaults(func=_run)

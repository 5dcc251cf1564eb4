"""The Pareto plot (error against cost) of each knob."""

from __future__ import annotations

import numpy as np

__all__ = ["pareto_plot"]


def pareto_plot(
    ctx, name, title, series, *, xlabel, ylabel="ΔE2000 (p99 and max)", default=None, note=None
) -> str:
    """Plot error against cost, log-log, and save it through ``ctx``.

    Parameters
    ----------
    ctx : Context
        Where the figure goes (:meth:`Context.savefig`).
    name, title : str
        The PNG's file name and the plot's title.
    series : dict
        ``{label: [(cost, p99, max, point_label), ...]}``; non-finite points are dropped.
    xlabel, ylabel : str
        Axis labels.
    default : tuple, optional
        ``(cost, p99, label)`` of the shipped default, marked with a star.
    note : str, optional
        A line of text under the plot.

    Returns
    -------
    str
        The figure's markdown link.
    """
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for i, (label, pts) in enumerate(series.items()):
        pts = [p for p in pts if np.isfinite(p[0]) and np.isfinite(p[1])]
        if not pts:
            continue
        colour_ = f"C{i}"
        xs = [p[0] for p in pts]
        ax.plot(xs, [max(p[1], 1e-6) for p in pts], "o-", color=colour_, label=f"{label} (p99)")
        ax.plot(
            xs,
            [max(p[2], 1e-6) for p in pts],
            "x:",
            color=colour_,
            alpha=0.6,
            label=f"{label} (max)",
        )
        for p in pts:
            ax.annotate(
                str(p[3]),
                (p[0], max(p[1], 1e-6)),
                fontsize=7,
                textcoords="offset points",
                xytext=(3, 3),
            )
    if default is not None:
        ax.plot(
            [default[0]],
            [max(default[1], 1e-6)],
            marker="*",
            markersize=18,
            color="gold",
            markeredgecolor="k",
            linestyle="none",
            label=f"default: {default[2]}",
        )
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axhline(1.0, color="grey", lw=0.8, ls="--")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    if note:
        fig.text(0.01, -0.02, note, fontsize=7)
    return ctx.savefig(fig, name)

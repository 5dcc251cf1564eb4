"""Section 2d: users' films -- the exact stack model's cost and its tables' error."""

from __future__ import annotations

from evaluation.films import error_against_time
from evaluation.report.context import Section
from evaluation.report.measure import fmt, table


def section(ctx) -> Section:
    """The Airy sum against the transfer-matrix recursion, and table size against ΔE2000."""
    sizes = (32, 128, 512) if ctx.quick else (32, 64, 128, 256, 512, 1024, 2048)
    result = error_against_time(sizes=sizes, samples=200 if ctx.quick else 500)
    rows = [
        [key] + [f"{fmt(r['dE_max'])} / {fmt(r['seconds'] * 1e3)} ms" for r in rows]
        for key, rows in result["tables"].items()
    ]
    worst_default = {
        key: next(r["dE_max"] for r in rows if r["size"] == max(sizes))
        for key, rows in result["tables"].items()
    }
    text = [
        "### 2d. Users' films: the exact model",
        "",
        f"One film (n = 1.47 on 1.33, 30°), {result['thicknesses']} thicknesses × "
        f"{result['wavelengths']} wavelengths: the Airy sum `exact.airy_reflectance` "
        f"{fmt(result['airy_seconds'] * 1e3)} ms, the transfer-matrix recursion "
        f"`exact.stack_reflectance` {fmt(result['transfer_matrix_seconds'] * 1e3)} ms "
        f"(max |ΔR| between them {fmt(result['max_abs_dR'])}).",
        "",
        "A film's table (`bake --films`) against its size: max ΔE2000 of the table's lookup "
        "at random thicknesses against colour-science's transfer-matrix method at 1 nm "
        "(independent), and the seconds the table took:",
        "",
        table(["film"] + [f"{s} entries" for s in sizes], rows),
    ]
    headline = {
        "size": max(sizes),
        "dE_max": max(worst_default.values()),
        "transfer_matrix_over_airy": result["transfer_matrix_seconds"] / result["airy_seconds"],
    }
    return Section("\n".join(text), {"films": result}, {"films": headline})

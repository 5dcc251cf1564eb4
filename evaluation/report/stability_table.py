"""Section 3: the stability table, measured now from the cases of
:mod:`evaluation.stability` (each row names the test that asserts it)."""

from __future__ import annotations

import warnings

from evaluation import stability
from evaluation.report.context import Section
from evaluation.report.measure import table
from ocio_thinfilm.colour import clip, colorimetry


def stability_rows() -> list[dict]:
    """Measure every stability case now.

    The physics rows (:func:`stability.physics_rows`), the clip's XYZ cases
    (:func:`stability.xyz_cases`) and the shipped OCIO clip transform
    (:func:`stability.ocio_clip_rows`), in that order. The expectations are physical
    or geometric facts, not outputs copied from the code under test.

    Returns
    -------
    list of dict
        One per case: ``case``, ``expected``, ``observed`` (text), ``ok`` (bool) and
        ``test`` (the test in tests/test_stability.py that asserts it).
    """
    rows = []

    def add(case, expected, observed, ok, test):
        rows.append(
            {"case": case, "expected": expected, "observed": observed, "ok": bool(ok), "test": test}
        )

    W = colorimetry.white_XYZ("sRGB")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for row in stability.physics_rows():
            ok, observed = row.check(row.measure())
            add(row.name, row.expected, observed, ok, row.test)
        for case in stability.xyz_cases(W):
            ok, observed = case.check(clip.clip_XYZ(case.inputs))
            add(case.name, case.expected, observed, ok, case.test)
        for row in stability.ocio_clip_rows(W):
            ok, observed = row.check(row.measure())
            add(row.name, row.expected, observed, ok, row.test)
    return rows


def section(ctx) -> Section:
    """The table: case, expected, observed, ok, test."""
    rows = stability_rows()
    body = table(
        ["case", "expected", "observed", "ok", "test (tests/test_stability.py)"],
        [
            [
                r["case"],
                r["expected"],
                r["observed"],
                "✓" if r["ok"] else "✗ **FAIL**",
                f"`{r['test']}`",
            ]
            for r in rows
        ],
    )
    fails = [r["case"] for r in rows if not r["ok"]]
    return Section(
        "\n".join(
            [
                "## 3. Stability on stiff and extreme cases",
                "",
                "Measured now; expectations are physical or geometric facts (incoherent limit, "
                "Fresnel, total internal reflection, mpmath at 50 digits, the geometric limit of "
                "the clip), and each row is asserted independently by the named test. XYZ rows "
                "go through `clip_XYZ` into sRGB.",
                "",
                body,
                "",
                f"{len(rows) - len(fails)} of {len(rows)} rows as expected"
                + (f"; not as expected: {'; '.join(fails)}." if fails else "."),
            ]
        ),
        {"stability": rows},
        {"stability": {"rows": len(rows), "not_as_expected": fails} if rows else None},
    )

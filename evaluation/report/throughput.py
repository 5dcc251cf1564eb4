"""Section 4: throughput of every view against the bandwidth bound (a memory copy)."""

from __future__ import annotations

import os
import tempfile
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from evaluation.report.context import Section
from evaluation.report.datasets import INTERFERENCE, lut_test_sets
from evaluation.report.measure import best_time, ocio_cpu, table
from ocio_thinfilm import registry
from ocio_thinfilm.lut import view_transforms

#: The view the headline quotes.
HEADLINE_VIEW = "Constant-Lightness Clip"


def section(ctx) -> Section:
    """Each view through OCIO (one thread, a strip pool) and OIIO, against a copy."""
    import matplotlib.pyplot as plt
    import OpenImageIO as oiio
    import PyOpenColorIO as ocio

    q = ctx.quick
    h, w = (540, 1024) if q else (2160, 4096)
    threads = os.cpu_count() or 1
    rng = np.random.default_rng(3)
    xyz = lut_test_sets(True)[INTERFERENCE]
    img = xyz[rng.integers(0, xyz.shape[0], h * w)].astype(np.float32).reshape(h, w, 3)
    work = np.empty_like(img)
    px = h * w
    rep = 2
    copy1 = px / best_time(lambda: np.copyto(work, img), repeat=rep, min_time=0.1) / 1e6
    strips = np.array_split(np.arange(h), max(threads * 4, 1))
    pool = ThreadPoolExecutor(threads)

    def pool_copy():
        list(pool.map(lambda s: np.copyto(work[s[0] : s[-1] + 1], img[s[0] : s[-1] + 1]), strips))

    copyN = px / best_time(pool_copy, repeat=rep, min_time=0.1) / 1e6
    src = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, "float"))
    src.set_pixels(oiio.ROI(), img)
    dst = oiio.ImageBuf(oiio.ImageSpec(w, h, 3, "float"))
    oiio_copy = {
        n: px
        / best_time(
            lambda n=n: oiio.ImageBufAlgo.copy(dst, src, nthreads=n), repeat=rep, min_time=0.1
        )
        / 1e6
        for n in (1, 0)
    }
    rows, raw = (
        [],
        {
            "image": [w, h],
            "threads": threads,
            "copy_Mpix_s": {
                "numpy 1 thread": copy1,
                f"numpy {threads} threads": copyN,
                "OIIO 1 thread": oiio_copy[1],
                "OIIO all threads": oiio_copy[0],
            },
            "views": {},
        },
    )
    with tempfile.TemporaryDirectory() as tmp:
        for view in registry.VIEWS:
            tf = view_transforms.view_transform("sRGB", view)
            cpu = ocio_cpu(tf)

            def one(cpu=cpu):
                np.copyto(work, img)
                cpu.applyRGB(work.reshape(-1, 3))

            def many(cpu=cpu):
                np.copyto(work, img)
                list(
                    pool.map(lambda s: cpu.applyRGB(work[s[0] : s[-1] + 1].reshape(-1, 3)), strips)
                )

            # The copy again, right before this view: the ratio is robust to load changes.
            copy_now = px / best_time(lambda: np.copyto(work, img), repeat=rep, min_time=0.1) / 1e6
            c_sec = px / copy_now / 1e6
            v1 = px / max(best_time(one, repeat=rep, min_time=0.1, max_calls=2) - c_sec, 1e-9) / 1e6
            vN = (
                px
                / max(
                    best_time(many, repeat=rep, min_time=0.1, max_calls=2) - px / copyN / 1e6, 1e-9
                )
                / 1e6
            )
            path = os.path.join(tmp, f"view{len(raw['views'])}.ctf")
            g = ocio.GroupTransform()
            g.appendTransform(tf)
            g.write("Color Transform Format", path, ocio.Config.CreateRaw())
            o = {}
            for n in (1, 0):
                o[n] = (
                    px
                    / best_time(
                        lambda n=n, path=path: oiio.ImageBufAlgo.ociofiletransform(
                            dst, src, path, unpremult=False, nthreads=n
                        ),
                        repeat=rep,
                        min_time=0.1,
                        max_calls=2,
                    )
                    / 1e6
                )
            raw["views"][view] = {
                "ocio_1": v1,
                "ocio_pool": vN,
                "oiio_1": o[1],
                "oiio_all": o[0],
                "copy_1_adjacent": copy_now,
            }
            rows.append([view, v1, vN, o[1], o[0], copy_now, v1 / copy_now, o[0] / oiio_copy[0]])
    pool.shutdown()
    v = raw["views"].get(HEADLINE_VIEW)
    headline = (
        None
        if v is None
        else {
            "image": [w, h],
            "threads": threads,
            "view": HEADLINE_VIEW,
            "ocio_1_Mpix_s": v["ocio_1"],
            "oiio_all_Mpix_s": v["oiio_all"],
            "copy_1_Mpix_s": v["copy_1_adjacent"],
        }
    )
    fig, ax = plt.subplots(figsize=(8, 4))
    names = list(raw["views"])
    xs = np.arange(len(names))
    for i, (k, label) in enumerate(
        [
            ("ocio_1", "OCIO CPU, 1 thread"),
            ("ocio_pool", f"OCIO CPU, {threads}-thread strip pool"),
            ("oiio_1", "oiiotool engine (OIIO IBA), 1 thread"),
            ("oiio_all", "oiiotool engine (OIIO IBA), all threads"),
        ]
    ):
        ax.bar(xs + (i - 1.5) * 0.2, [raw["views"][v][k] for v in names], 0.2, label=label)
    ax.axhline(copy1, color="k", ls="--", lw=1, label=f"memory copy, 1 thread ({copy1:.0f})")
    ax.axhline(
        oiio_copy[0],
        color="grey",
        ls=":",
        lw=1,
        label=f"OIIO copy, all threads ({oiio_copy[0]:.0f})",
    )
    ax.set_yscale("log")
    ax.set_xticks(xs)
    ax.set_xticklabels(names, fontsize=8)
    ax.set_ylabel("Mpixel/s")
    ax.set_title(f"Views on a {w}×{h} float RGB image vs a memory copy")
    ax.legend(fontsize=7)
    img_md = ctx.savefig(fig, "throughput.png")
    return Section(
        "\n".join(
            [
                "## 4. Throughput against the physical limit",
                "",
                "Each view of `view_transforms.view_transform('sRGB', view)` (CIE-XYZ-D65 → "
                f"sRGB-encoded) on a {w}×{h} float32 RGB image of interference colours "
                f"({px * 12 / 2**20:.0f} MiB). The bound is a plain memory copy of the same "
                f"buffer: numpy `copyto` {copy1:.0f} Mpixel/s on one thread, {copyN:.0f} on "
                f"{threads} threads; OIIO `ImageBufAlgo.copy` {oiio_copy[1]:.0f} (1 thread) / "
                f"{oiio_copy[0]:.0f} (all threads). OCIO's CPU processor applies single-threaded "
                "per call, so 'all threads' is either a thread pool of "
                f"{threads} over image strips (OCIO releases the GIL) or OIIO's "
                "`ImageBufAlgo.ociofiletransform` — the engine behind "
                "`oiiotool --ociofiletransform`, run on the view written as a CTF file — with "
                "nthreads = 0 (all).",
                "",
                table(
                    [
                        "view",
                        "OCIO 1 thread",
                        f"OCIO pool ×{threads}",
                        "OIIO 1 thread",
                        "OIIO all",
                        "copy, 1 thread (just before)",
                        "OCIO 1 thread ÷ copy",
                        "OIIO all ÷ OIIO copy",
                    ],
                    rows,
                ),
                "",
                "All speeds in Mpixel/s. The OCIO columns exclude the copy that restores the input "
                "before each run (measured and subtracted).",
                "",
                img_md,
            ]
        ),
        {"throughput": raw},
        {"throughput": headline},
    )

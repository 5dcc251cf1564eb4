"""Benchmark: the film's Blender material against Principled BSDF's own thin film.

The test scene of tests/test_blender.py (``evaluation/blender_scene.py``: a mirror sphere,
roughness 0, in a uniform white world, orthographic camera, Cycles on the CPU, no
denoising), with a soap-like film on glass (n = 1.33 on 1.5, in air), its thickness
ramping from 0.05 um at the left to 0.95 um at the right (and, for two more rows, from
1 um to 3 um):

- **ours**: the script of :func:`ocio_thinfilm.export.hosts.blender.blender_script` over tables
  made by :mod:`evaluation.materials` (colour-science's exact TMM, 256 x 128 over
  0-1 um; for the thicker films 768 x 128 over 0-3 um);
- **Principled**: Blender's Principled BSDF, black base, IOR 1.5, ``Thin Film IOR`` 1.33,
  ``Thin Film Thickness`` from the same ramp (nm);
- **exact**: colour-science's TMM at each pixel's thickness and angle (clamped at 0 per
  channel where it is outside BT.709: Cycles clamps negative closure colours);
- and the node group of a free-standing soap film (n = 1.33 in air) against its exact
  reflectance, in Cycles and in EEVEE (headless: EGL, on Mesa's llvmpipe here).

Prints and writes reports/bench_blender.json (``_reports.write_json``) and
reports/bench_blender.md: DeltaE2000
(p50 / p99 / max over the sphere away from its silhouette) of ours and Principled's
against the exact film and against each other, and the Cycles render time of each
(median of ``--runs`` renders of the same scene in one Blender, after a warm-up render);
with ``--update-docs`` also the picture docs/gallery/blender_soap.png (ours | Principled, sRGB), and
docs/gallery/blender_bubble.png: the same sphere with a free-standing soap film (n = 1.33
in air), reflection only (the scene of tests/test_blender.py's exact-reflectance test).

Usage: PYTHONPATH=. python benchmarks/bench_blender.py [--size 128] [--samples 16] [--runs 7]
[--update-docs]
"""

from __future__ import annotations

import argparse
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/

from benchmarks import _reports  # noqa: E402  (after the path above)

REPORT = ROOT / "reports"
PICTURE = ROOT / "docs" / "gallery" / "blender_soap.png"
BUBBLE = ROOT / "docs" / "gallery" / "blender_bubble.png"
RAMP = (0.05, 0.95)
#: The thicker films' ramp, over a 0-3 um table of 768 x 128.
THICK = (1.0, 3.0)


def _stats(de):
    p50, p99, top = np.percentile(de, [50, 99, 100])
    return {"p50": round(float(p50), 3), "p99": round(float(p99), 3), "max": round(float(top), 3)}


def _png(images, path):
    import colour
    import OpenImageIO as oiio

    row = np.concatenate(images, axis=1).repeat(2, axis=0).repeat(2, axis=1)
    code = colour.cctf_encoding(np.clip(row, 0, 1), function="sRGB")
    out = oiio.ImageBuf(oiio.ImageSpec(row.shape[1], row.shape[0], 3, oiio.UINT8))
    out.set_pixels(oiio.ROI(), np.round(code * 255).astype(np.uint8))
    path.parent.mkdir(parents=True, exist_ok=True)
    if not out.write(str(path)):
        raise OSError(f"cannot write {path}: {oiio.geterror()}")


def measure(size: int, samples: int, runs: int) -> tuple[dict, dict]:
    """The result, and the pictures' images: ``"soap"`` (:data:`PICTURE`: ours,
    Principled) and ``"bubble"`` (:data:`BUBBLE`)."""
    from evaluation import blender, materials

    if blender.bpy_python() is None:
        blender.install_bpy()
    job = {"samples": samples, "runs": runs + 1, "size": size, "ramp_um": RAMP}
    with tempfile.TemporaryDirectory(prefix="bench-blender-") as work:
        ours, exact, ours_answer = blender.render_film(
            Path(work), materials.SOAP_ON_GLASS, "SoapOnGlass", **job
        )
        ours_image = blender.read_exr(Path(work) / "SoapOnGlass_CYCLES.exr")

        def principled_render(ramp, runs):
            out = Path(work) / "principled.exr"
            answer = blender.render(
                {
                    "engine": "CYCLES",
                    "size": size,
                    "samples": samples,
                    "runs": runs,
                    "out": str(out),
                    "material": {"kind": "principled", "ior": 1.5, "film_ior": 1.33},
                    "thickness_um": list(ramp),
                }
            )
            return blender.read_exr(out), answer

        principled_image, principled_answer = principled_render(RAMP, runs + 1)
        thick = {**job, "runs": 1, "ramp_um": THICK, "range_um": (0.0, 3.0)}
        thick_ours, thick_exact, _ = blender.render_film(
            Path(work), materials.SOAP_ON_GLASS, "Thick", table_size=(768, 128), **thick
        )
        thick_principled = principled_render(THICK, 1)[0]
        bubble, bubble_exact, _ = blender.render_film(
            Path(work), materials.SOAP_BUBBLE, "Bubble", **job
        )
        bubble_image = blender.read_exr(Path(work) / "Bubble_CYCLES.exr")
        once = {**job, "runs": 1}
        eevee, eevee_exact, _ = blender.render_film(
            Path(work), materials.SOAP_BUBBLE, "Bubble", engine="BLENDER_EEVEE", **once
        )
    _, _, disc, _ = blender.sphere_pixels(size)
    principled = principled_image[disc]
    thick_clipped = np.clip(thick_exact, 0, None)
    clipped = np.clip(exact, 0, None)  # Cycles clamps negative closure colours to 0
    ours_s = np.median(ours_answer["seconds"][1:])
    principled_s = np.median(principled_answer["seconds"][1:])
    pictures = {"soap": [ours_image, principled_image], "bubble": [bubble_image]}
    return {
        "blender": ours_answer["version"],
        "size": size,
        "samples": samples,
        "pixels": int(disc.sum()),
        "delta_e": {
            "ours_vs_exact": _stats(materials.delta_e(ours, clipped)),
            "principled_vs_exact": _stats(materials.delta_e(principled, clipped)),
            "ours_vs_principled": _stats(materials.delta_e(ours, principled)),
            "thick_ours_vs_exact": _stats(materials.delta_e(thick_ours, thick_clipped)),
            "thick_principled_vs_exact": _stats(
                materials.delta_e(thick_principled[disc], thick_clipped)
            ),
            "bubble_vs_exact": _stats(materials.delta_e(bubble, np.clip(bubble_exact, 0, None))),
            "bubble_eevee_vs_exact": _stats(
                materials.delta_e(eevee, np.clip(eevee_exact, 0, None))
            ),
        },
        "seconds": {"ours": round(ours_s, 4), "principled": round(principled_s, 4)},
        "ratio": round(ours_s / principled_s, 3),
    }, pictures


def markdown(result: dict) -> str:
    lines = [
        f"Blender {result['blender']}, Cycles CPU, {result['size']}x{result['size']} px, "
        f"{result['samples']} samples, {result['pixels']} pixels compared.",
        "",
        "| DeltaE2000 | p50 | p99 | max |",
        "| --- | ---: | ---: | ---: |",
    ]
    names = {
        "ours_vs_exact": "node group vs exact",
        "principled_vs_exact": "Principled thin film vs exact",
        "ours_vs_principled": "node group vs Principled",
        "thick_ours_vs_exact": "node group vs exact, 1-3 um",
        "thick_principled_vs_exact": "Principled thin film vs exact, 1-3 um",
        "bubble_vs_exact": "node group vs exact, free-standing soap film (reflection)",
        "bubble_eevee_vs_exact": "the same in EEVEE",
    }
    for key, name in names.items():
        s = result["delta_e"][key]
        lines.append(f"| {name} | {s['p50']:.2f} | {s['p99']:.2f} | {s['max']:.2f} |")
    sec = result["seconds"]
    lines += [
        "",
        f"Render time (median): node group {1000 * sec['ours']:.0f} ms, Principled thin film "
        f"{1000 * sec['principled']:.0f} ms: {result['ratio']:.2f}x.",
    ]
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", type=int, default=128)
    parser.add_argument("--samples", type=int, default=16)
    parser.add_argument("--runs", type=int, default=7)
    _reports.add_update_docs(parser)
    args = parser.parse_args()
    result, pictures = measure(args.size, args.samples, args.runs)
    REPORT.mkdir(exist_ok=True)
    _reports.write_json("blender", result, indent=2)
    text = markdown(result)
    (REPORT / "bench_blender.md").write_text(text)
    print(text)
    if args.update_docs:
        _png(pictures["soap"], PICTURE)
        _png(pictures["bubble"], BUBBLE)
        print(f"wrote {PICTURE.relative_to(ROOT)} and {BUBBLE.relative_to(ROOT)}")
    else:
        print(
            f"{PICTURE.relative_to(ROOT)} and {BUBBLE.relative_to(ROOT)} not written "
            "(--update-docs writes them)"
        )


if __name__ == "__main__":
    main()

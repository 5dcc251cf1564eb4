"""Benchmark: the noise of a free-standing film (a bubble) in Blender, ours vs Principled.

The bubble scene of ``evaluation/blender_scene.py`` (``"scene": "bubble"``): a unit sphere
of soap film (n = 1.33 in air, thickness ramping from 0.1 um at the left to 0.9 um at
the right) in front of an emitting checker backdrop, under a world whose colour varies
with the direction; orthographic camera, ``--size`` pixels square. Materials:

- **ours**: the script of :func:`ocio_thinfilm.export.hosts.blender.blender_script` over
  tables made by :mod:`evaluation.materials` (colour-science's TMM, 256 x 128 over
  0-1 um, R and T), in each closure structure of :data:`STRUCTURES`;
- **Principled**: Blender's nearest bubble, a Principled BSDF with its thin film
  (``Thin Film IOR`` 1.33, ``Thin Film Thickness`` from the same ramp in nm) on a
  transmissive IOR 1.0 surface (Transmission Weight 1, Roughness 0, white base).

The noise: RMSE (linear RGB, all channels, over the sphere's disc inside radius 0.95)
of each render against the same material's converged render of the same scene: Cycles
(CPU, no denoising, no adaptive sampling) at 32 and 128 samples against ``--reference``
samples, EEVEE at 16 against 64 (each EEVEE render method of :data:`METHODS`; EEVEE
does not pick closures at random, so the Mix structure is not rendered there). Cycles
renders with ``--seeds`` seeds: the table gives the mean and the spread (min-max) of the
RMSE over the seeds, the noise of the measure itself.

Colour: a flat patch of the film at normal incidence (``"shape": "plane"``), in a white
world before a black backdrop (what reaches the camera is R) and in a black world before
a white backdrop (T), rendered with the written material (Cycles 1024 samples, EEVEE
16, the chosen render method), against colour-science's exact R and T: DeltaE2000 max
over the patch's columns (one thickness each; their mean colour: Cycles picks R or T at
random per sample, so one pixel is noisy and the column's mean is not).

Writes reports/bench_bubbles.json (``_reports.write_json``) and reports/bench_bubbles.md;
with ``--update-docs`` also docs/gallery/blender_bubbles.png (ours top, Principled bottom;
Cycles 32, Cycles 128, EEVEE 16 in each one's render method (ours Blended, Principled
Dithered), the converged Cycles render; sRGB).

Usage: PYTHONPATH=. python benchmarks/bench_bubbles.py [--size 64] [--reference 1024]
[--seeds 3] [--only-patch] [--update-docs] (``--only-patch``: redo the colour check, keep
the last run's noise table and draw no picture)
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # the evaluation package beside benchmarks/

from benchmarks import _reports  # noqa: E402  (after the path above)

REPORT = ROOT / "reports"
PICTURE = ROOT / "docs" / "gallery" / "blender_bubbles.png"
RAMP = (0.1, 0.9)
#: Closure structures of our group tried (evaluation/blender_scene.py's ``restructure``).
STRUCTURES = {
    "add": "ours: Glossy(R) + Transparent(T), Add Shader",
    "mix": "ours: Mix Shader, factor avg T / (avg R + avg T), of Glossy and Transparent",
}
#: EEVEE render methods tried.
METHODS = ("BLENDED", "DITHERED")
PRINCIPLED = "Principled: transmission 1, IOR 1.0, roughness 0, thin film"
EEVEE_REFERENCE = 64


def _png(rows, path):
    import colour
    import OpenImageIO as oiio

    image = np.concatenate([np.concatenate(row, axis=1) for row in rows], axis=0)
    image = image.repeat(2, axis=0).repeat(2, axis=1)
    code = colour.cctf_encoding(np.clip(image, 0, 1), function="sRGB")
    out = oiio.ImageBuf(oiio.ImageSpec(image.shape[1], image.shape[0], 3, oiio.UINT8))
    out.set_pixels(oiio.ROI(), np.round(code * 255).astype(np.uint8))
    path.parent.mkdir(parents=True, exist_ok=True)
    if not out.write(str(path)):
        raise OSError(f"cannot write {path}: {oiio.geterror()}")


def series(material, engine, size, reference, runs, work, tag, **job):
    """Render ``reference`` samples, then ``runs`` = [(samples, seed)]: the images."""
    from evaluation import blender

    ref = work / f"{tag}_ref.exr"
    outs = [work / f"{tag}_{samples}_{seed}.exr" for samples, seed in runs]
    blender.render(
        {
            "engine": engine,
            "size": size,
            "samples": reference,
            "seed": 1000,
            "out": str(ref),
            "material": material,
            "thickness_um": list(RAMP),
            "scene": "bubble",
            "series": [[s, seed, str(o)] for (s, seed), o in zip(runs, outs, strict=True)],
            **job,
        },
        timeout=3600,
    )
    return blender.read_exr(ref), {
        run: blender.read_exr(o) for run, o in zip(runs, outs, strict=True)
    }


def rmse(image, reference, disc):
    """Root mean square difference over the disc's pixels, all channels."""
    return float(np.sqrt(np.mean((image[disc] - reference[disc]) ** 2)))


def noise(materials_, size, reference, seeds, work):
    """The RMSE table: per material, Cycles 32 / 128 (mean, min, max) and EEVEE 16."""
    from evaluation import blender

    disc = blender.sphere_pixels(size)[2]
    runs = [(s, seed) for s in (32, 128) for seed in range(seeds)]
    result, pictures = {}, {}
    for name, (material, job, methods) in materials_.items():
        ref, images = series(
            material, "CYCLES", size, reference, runs, work, f"c{len(result)}", **job
        )
        row = {}
        for samples in (32, 128):
            values = [rmse(images[(samples, seed)], ref, disc) for seed in range(seeds)]
            row[f"cycles_{samples}"] = {
                "mean": round(float(np.mean(values)), 5),
                "min": round(min(values), 5),
                "max": round(max(values), 5),
            }
        pictures[name] = [images[(32, 0)], images[(128, 0)]]
        for method in methods:
            eref, eimages = series(
                material,
                "BLENDER_EEVEE",
                size,
                EEVEE_REFERENCE,
                [(16, 0)],
                work,
                f"e{len(result)}{method}",
                render_method=method,
                **job,
            )
            row[f"eevee_16_{method.lower()}"] = round(rmse(eimages[(16, 0)], eref, disc), 5)
            if method == methods[0]:
                pictures[name].append(eimages[(16, 0)])
        pictures[name].append(ref)
        result[name] = row
        print(name, json.dumps(row), flush=True)
    return result, pictures


def patch_colour(script, name, work):
    """DeltaE2000 max of the written material's flat patch against exact R and T."""
    from evaluation import blender, materials

    size = 32
    c = -blender.FRAME / 2 + blender.FRAME * (np.arange(size) + 0.5) / size
    x = np.broadcast_to(c, (size, size))
    inside = np.abs(x) < 0.9
    inside &= inside.T
    thickness = RAMP[0] + (x + 1) / 2 * (RAMP[1] - RAMP[0])
    found = {}
    for quantity, world, back in (("reflectance", 1.0, 0.0), ("transmittance", 0.0, 1.0)):
        exact = materials.film_rgb(materials.SOAP_BUBBLE, thickness[inside], 1.0, quantity=quantity)
        for engine, samples in (("CYCLES", 1024), ("BLENDER_EEVEE", 16)):
            out = work / f"patch_{quantity}_{engine}.exr"
            blender.render(
                {
                    "engine": engine,
                    "size": size,
                    "samples": samples,
                    "out": str(out),
                    "material": {"kind": "script", "script": str(script), "name": name},
                    "thickness_um": list(RAMP),
                    "shape": "plane",
                    "world": [world] * 3,
                    "backdrop": [back] * 3,
                }
            )
            # a column is one thickness: its mean (Cycles picks R or T per sample)
            rows = blender.read_exr(out)[inside.any(axis=1)]
            got = rows[:, inside.any(axis=0)].mean(axis=0)
            column = exact.reshape(-1, inside.any(axis=0).sum(), 3)[0]
            de = materials.delta_e(got, np.clip(column, 0, None))
            found[f"{quantity}_{engine.lower()}"] = round(float(de.max()), 3)
    return found


def patch_only() -> dict:
    """The colour check alone, with the script as written."""
    from evaluation import materials
    from ocio_thinfilm.export.hosts.blender import blender_name

    with tempfile.TemporaryDirectory(prefix="bench-bubbles-") as tmp:
        work = Path(tmp)
        script = materials.write_film_folder(
            work / "Bubble",
            materials.SOAP_BUBBLE,
            "Bubble",
            (0.0, 1.0),
            256,
            128,
            transmittance=True,
        )
        return patch_colour(script, blender_name("Bubble"), work)


def measure(size: int, reference: int, seeds: int) -> tuple[dict, list]:
    """The result, and the picture's rows (ours, Principled) for :data:`PICTURE`."""
    from evaluation import blender, materials
    from ocio_thinfilm.export.hosts.blender import blender_name

    if blender.bpy_python() is None:
        blender.install_bpy()
    with tempfile.TemporaryDirectory(prefix="bench-bubbles-") as tmp:
        work = Path(tmp)
        script = materials.write_film_folder(
            work / "Bubble",
            materials.SOAP_BUBBLE,
            "Bubble",
            (0.0, 1.0),
            256,
            128,
            transmittance=True,
        )
        ours = {"kind": "script", "script": str(script), "name": blender_name("Bubble")}
        variants = {
            label: (ours, {"structure": key}, METHODS if key == "add" else ())
            for key, label in STRUCTURES.items()
        }
        # Principled's default render method (Dithered) first: the picture's
        variants[PRINCIPLED] = (
            {"kind": "principled_bubble", "film_ior": 1.33},
            {},
            METHODS[::-1],
        )
        table, pictures = noise(variants, size, reference, seeds, work)
        colour_check = patch_colour(script, blender_name("Bubble"), work)
    rows = [pictures[STRUCTURES["add"]], pictures[PRINCIPLED]]
    return {
        "version": blender.BPY_VERSION,
        "size": size,
        "reference": reference,
        "eevee_reference": EEVEE_REFERENCE,
        "seeds": seeds,
        "rmse": table,
        "patch_delta_e": colour_check,
    }, rows


def markdown(result: dict) -> str:
    """The RMSE table and the patch's colour check as markdown."""
    lines = [
        f"Blender {result['version']}, {result['size']}x{result['size']} px, RMSE (linear RGB) "
        f"over the bubble against the converged render (Cycles {result['reference']} samples, "
        f"EEVEE {result['eevee_reference']}); Cycles: mean (min-max) over "
        f"{result['seeds']} seeds.",
        "",
        "| material | Cycles 32 | Cycles 128 | EEVEE 16 Blended | EEVEE 16 Dithered |",
        "| --- | ---: | ---: | ---: | ---: |",
    ]
    for name, row in result["rmse"].items():
        cells = [
            f"{row[k]['mean']:.4f} ({row[k]['min']:.4f}-{row[k]['max']:.4f})"
            for k in ("cycles_32", "cycles_128")
        ]
        cells += [
            f"{row[f'eevee_16_{m.lower()}']:.4f}" if f"eevee_16_{m.lower()}" in row else "-"
            for m in METHODS
        ]
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    p = result["patch_delta_e"]
    lines += [
        "",
        "Flat patch at normal incidence, DeltaE2000 max against the exact film: "
        f"R {p['reflectance_cycles']:.2f} (Cycles), {p['reflectance_blender_eevee']:.2f} "
        f"(EEVEE); T {p['transmittance_cycles']:.2f} (Cycles), "
        f"{p['transmittance_blender_eevee']:.2f} (EEVEE).",
    ]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--reference", type=int, default=1024)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--only-patch", action="store_true")
    _reports.add_update_docs(parser)
    args = parser.parse_args()
    rows = None
    if args.only_patch:
        result = json.loads(_reports.json_path("bubbles").read_text())
        result["patch_delta_e"] = patch_only()
    else:
        result, rows = measure(args.size, args.reference, args.seeds)
    REPORT.mkdir(exist_ok=True)
    _reports.write_json("bubbles", result, indent=2)
    text = markdown(result)
    (REPORT / "bench_bubbles.md").write_text(text + "\n")
    print(text)
    if rows is not None:
        if args.update_docs:
            _png(rows, PICTURE)
            print(f"wrote {PICTURE.relative_to(ROOT)}")
        else:
            print(f"{PICTURE.relative_to(ROOT)} not written (--update-docs writes it)")


if __name__ == "__main__":
    main()

"""The thinfilm Mitsuba 3 BSDF: its speed against Mitsuba's built-in BSDFs, its accuracy
at four angles, and the picture of docs/mitsuba.md.

    python benchmarks/fig_mitsuba.py            # all three, writes docs/gallery/mitsuba_films.png
    python benchmarks/fig_mitsuba.py --no-figure

Speed: the plate of evaluation/mitsuba_scenes.py (a flat film filling the frame under the
white sky, 30 degrees) rendered with the plugin and with ``dielectric``,
``thindielectric`` and ``conductor`` in the same run, in ``scalar_spectral`` (32 x 32,
16 spp) and ``llvm_ad_spectral`` (128 x 128, 16 spp; the plugin in
``tfm.evaluated_mode()``, the built-ins both as Mitsuba runs them and in evaluated mode).
Each time is the best of two renders (the first JIT render compiles its kernels).
Accuracy: DeltaE2000 of the frame's mean colour against ``film_angle_XYZ`` at 0/30/60/80
degrees (the tests' check, with more samples: 16 x 16 (scalar) or 32 x 32 (JIT) pixels,
64 spp). The variants run in subprocesses (one
variant per process; an unusable LLVM aborts only its process). Results also go to
reports/mitsuba.json and
its tables into docs/mitsuba.md (tests/test_mitsuba.py checks the quote).
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FILMS = ROOT / "docs" / "films.toml"
FIGURE = ROOT / "docs" / "gallery" / "mitsuba_films.png"
REPORT = ROOT / "reports" / "mitsuba.json"

#: (film, thickness um) measured at four angles
ACCURACY = [("SoapFilm", 0.3), ("AnodisedTitanium", 0.1), ("OilOnWater", 0.4)]
ANGLES = (0.0, 30.0, 60.0, 80.0)


def _worker(variant: str, job: str) -> dict:
    import mitsuba as mi
    import numpy as np

    mi.set_variant(variant)
    sys.path.insert(0, str(ROOT))
    from evaluation.mitsuba_scenes import delta_e, plate_XYZ
    from ocio_thinfilm.export.hosts import mitsuba as tfm
    from ocio_thinfilm.lut.material_tables import film_angle_XYZ
    from ocio_thinfilm.physics.films import read_films

    tfm.register()
    jit = variant.startswith("llvm")
    out: dict = {"variant": variant}
    if job == "speed":
        size = 128 if jit else 32
        cases = {
            "thinfilm SoapFilm": (tfm.bsdf(FILMS, "SoapFilm", thickness=0.3), jit),
            "thinfilm AnodisedTitanium": (tfm.bsdf(FILMS, "AnodisedTitanium", thickness=0.1), jit),
            "dielectric": ({"type": "dielectric"}, False),
            "thindielectric": ({"type": "thindielectric"}, False),
            "conductor": ({"type": "conductor", "eta": 2.7, "k": 3.8}, False),
        }
        if jit:
            cases["dielectric, evaluated mode"] = ({"type": "dielectric"}, True)
            cases["conductor, evaluated mode"] = (
                {"type": "conductor", "eta": 2.7, "k": 3.8},
                True,
            )
        times = {}
        for name, (bsdf, evaluated) in cases.items():
            best = min(
                plate_XYZ(bsdf, 30.0, size=size, spp=16, evaluated=evaluated)[1] for _ in range(2)
            )
            times[name] = best
        out.update(size=size, spp=16, seconds=times)
    else:
        films = read_films(FILMS)
        size = 32 if jit else 16
        result = {}
        for key, t in ACCURACY:
            row = {}
            for angle in ANGLES:
                ref = film_angle_XYZ(films[key], [t], [np.cos(np.radians(angle))])[0][0, 0]
                XYZ, _ = plate_XYZ(
                    tfm.bsdf(FILMS, key, thickness=t),
                    angle,
                    side="reflect",
                    size=size,
                    spp=64,
                    evaluated=jit,
                )
                row[f"{angle:g}"] = round(delta_e(XYZ, ref), 3)
            result[f"{key} {t:g} um"] = row
        out.update(size=size, spp=64, delta_e=result)
    return out


def _figure(variant: str, path: Path) -> dict:
    """A soap bubble (thickness 0.05-0.9 um from its top down) and an anodised titanium
    plate (0-0.4 um from left to right) under a sky-and-ground environment."""
    import time

    import mitsuba as mi
    import numpy as np

    mi.set_variant(variant)
    from ocio_thinfilm.export.hosts import mitsuba as tfm

    tfm.register()
    T = mi.ScalarTransform4f
    # lat-long environment: a bright sky with a sun-lit band, a darker ground (linear sRGB)
    h, w = 64, 128
    elevation = np.linspace(np.pi / 2, -np.pi / 2, h)[:, None, None]
    azimuth = np.linspace(0, 2 * np.pi, w)[None, :, None]
    sky = np.where(
        elevation > 0,
        np.array([0.35, 0.55, 0.95]) * (0.6 + 0.8 * np.cos(elevation)),
        np.array([0.12, 0.1, 0.08]) + 0.05 * np.cos(azimuth),
    )
    sky = sky + 6.0 * np.exp(-((elevation - 0.5) ** 2 + (azimuth - 2.0) ** 2) / 0.02)
    env = mi.Bitmap(np.ascontiguousarray(sky.astype(np.float32)))
    bubble_ramp = mi.Bitmap(np.linspace(0.05, 0.9, 64, dtype=np.float32).reshape(64, 1))
    plate_ramp = mi.Bitmap(np.linspace(0.0, 1.0, 64, dtype=np.float32).reshape(1, 64))
    scene = {
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 8},
        "sky": {"type": "envmap", "bitmap": env},
        "sensor": {
            "type": "perspective",
            "fov": 40,
            "to_world": T().look_at(origin=[0, 0.6, 4.2], target=[0, 0.1, 0], up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": 320, "height": 200, "rfilter": {"type": "box"}},
            "sampler": {"type": "ldsampler", "sample_count": 64},
        },
        "bubble": {
            "type": "sphere",
            # its pole (texture v = 0) up: the thickness ramp runs from the top down
            "to_world": T().translate([-0.75, 0.2, 0])
            @ T().rotate([1, 0, 0], -90)
            @ T().scale(0.7),
            "bsdf": tfm.bsdf(
                FILMS,
                "SoapFilm",
                thickness={"type": "bitmap", "bitmap": bubble_ramp, "raw": True},
            ),
        },
        "plate": {
            "type": "rectangle",
            "to_world": T().translate([0.85, 0.15, 0])
            @ T().rotate([0, 1, 0], -25)
            @ T().scale(0.6),
            "bsdf": tfm.bsdf(
                FILMS,
                "AnodisedTitanium",
                thickness={"type": "bitmap", "bitmap": plate_ramp, "raw": True},
                thickness_scale="range",
            ),
        },
        "floor": {
            "type": "rectangle",
            "to_world": T().translate([0, -0.5, 0]) @ T().rotate([1, 0, 0], -90) @ T().scale(6),
            "bsdf": {
                "type": "diffuse",
                "reflectance": {"type": "checkerboard", "to_uv": T().scale(12)},
            },
        },
    }
    start = time.perf_counter()
    with tfm.evaluated_mode() if variant.startswith("llvm") else _null():
        image = mi.render(mi.load_dict(scene))
    seconds = time.perf_counter() - start
    path.parent.mkdir(parents=True, exist_ok=True)
    mi.util.write_bitmap(str(path), image)  # PNG: sRGB-encoded 8 bit
    return {"figure": str(path.relative_to(ROOT)), "variant": variant, "seconds": seconds}


def _null():
    import contextlib

    return contextlib.nullcontext()


def _run(variant: str, job: str) -> dict | None:
    run = subprocess.run(
        [sys.executable, __file__, "--worker", variant, job],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    if run.returncode != 0:
        lines = run.stderr.strip().splitlines() or ["no message"]
        why = lines[0] if lines[0].startswith("LLVM ERROR") else lines[-1]
        print(f"{variant} {job}: failed ({run.returncode}): {why}")
        return None
    return json.loads(run.stdout.strip().splitlines()[-1])


DOC = ROOT / "docs" / "mitsuba.md"


def doc_blocks(report: dict) -> dict[str, str]:
    """The tables docs/mitsuba.md quotes, from the report (tests check the quote)."""
    accuracy = ["| variant | film | " + " | ".join(f"{a:g}°" for a in ANGLES) + " |"]
    accuracy.append("| --- | --- |" + " --- |" * len(ANGLES))
    speed = ["| variant | pixels, spp | BSDF | seconds | × `dielectric` |"]
    speed.append("| --- | --- | --- | --- | --- |")
    for variant in ("scalar_spectral", "llvm_ad_spectral"):
        result = report.get(f"{variant} accuracy")
        if result:
            for film, row in result["delta_e"].items():
                cells = " | ".join(f"{v:.2f}" for v in row.values())
                accuracy.append(f"| `{variant}` | {film} | {cells} |")
        result = report.get(f"{variant} speed")
        if result:
            base = result["seconds"]["dielectric"]
            for name, secs in result["seconds"].items():
                size = f"{result['size']}², {result['spp']}"
                speed.append(f"| `{variant}` | {size} | {name} | {secs:.2f} | {secs / base:.1f} |")
    return {"accuracy": "\n".join(accuracy), "speed": "\n".join(speed)}


def write_doc(report: dict) -> None:
    """Put :func:`doc_blocks` between docs/mitsuba.md's markers."""
    import re

    text = DOC.read_text()
    for name, block in doc_blocks(report).items():
        text = re.sub(
            rf"(<!-- mitsuba:{name}:begin -->\n).*?(\n<!-- mitsuba:{name}:end -->)",
            lambda m, block=block: m.group(1) + block + m.group(2),
            text,
            flags=re.S,
        )
    DOC.write_text(text)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-figure", action="store_true")
    parser.add_argument("--worker", nargs=2, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        variant, job = args.worker
        if job == "figure":
            print(json.dumps(_figure(variant, FIGURE)))
        else:
            print(json.dumps(_worker(variant, job)))
        return
    report = {}
    for variant in ("scalar_spectral", "llvm_ad_spectral"):
        for job in ("speed", "accuracy"):
            result = _run(variant, job)
            report[f"{variant} {job}"] = result
            if result is None:
                continue
            if job == "speed":
                secs = result["seconds"]
                base = secs["dielectric"]
                print(f"{variant}: {result['size']}^2 px, {result['spp']} spp, plate at 30 deg")
                for name, s in secs.items():
                    print(f"  {name:34s} {s:8.3f} s   {s / base:7.1f} x dielectric")
            else:
                print(f"{variant}: DeltaE2000 against film_angle_XYZ at {ANGLES} deg")
                for name, row in result["delta_e"].items():
                    print(f"  {name:26s} " + "  ".join(f"{v:5.3f}" for v in row.values()))
    if not args.no_figure:
        figure = _run("llvm_ad_spectral", "figure") or _run("scalar_spectral", "figure")
        report["figure"] = figure
        if figure:
            print(f"wrote {figure['figure']} ({figure['variant']}, {figure['seconds']:.1f} s)")
    else:
        previous = json.loads(REPORT.read_text()) if REPORT.exists() else {}
        report["figure"] = previous.get("figure")
    REPORT.write_text(json.dumps(report, indent=1) + "\n")
    write_doc(report)
    print(f"wrote {REPORT.relative_to(ROOT)} and the tables of {DOC.relative_to(ROOT)}")


if __name__ == "__main__":
    main()

"""How wrong is an RGB renderer's film under a coloured light? (docs/rgb_vs_spectral.md)

Every film of docs/films.toml under five lights (D65; A, tungsten; F11, a three-band
fluorescent; CIE's LED-RGB1, an RGB LED white at 2840 K; RGB-LED-D65, an RGB LED white at
D65's chromaticity, ``ocio_thinfilm.lut.film_lights.led_spectrum``), over a grid of
thickness (200 midpoints of equal steps over the film's range) x cos theta (20 values,
0.05 to 1), three ways:

- **spectral truth**: the film's reflectance spectrum times the light's spectrum with the
  CIE 1931 2 degree CMFs (``film_lights.film_light_XYZ``: 1 nm steps or finer), the
  perfect reflector under the light at Y = 1, not adapted: the colour a spectral
  renderer records;
- **RGB path**: the film's default material table (made under D65, linear Rec.709), read
  bilinearly as a host reads it, times the light's RGB (its perfect reflector in linear
  Rec.709), channel by channel;
- **recovered**: the material table made for the light (a film file's ``illuminant``: the
  film under the light, CAT02-adapted to D65), read bilinearly and lit by a white light
  of the light's luminance, then un-adapted to the light's white (the inverse CAT02);
  and **recovered x light**: the same table lit by the light's RGB instead.

Differences are CIEDE2000 relative to the light's white: both colours through the same
CAT02 adaptation from the light's white to D65, then CIELAB (D65).
``film_lights.delta_E_under``. RGB-LED-D65 is not a colour-science illuminant, so a film
file cannot name it: its recovered table is the same construction
(``film_light_XYZ`` at the table's nodes, CAT02-adapted), not the package's.

Writes reports/bench_rgb_vs_spectral.json (``_reports.write_json``) and prints the table; with
``--update-docs`` also the table of docs/rgb_vs_spectral.md and
docs/gallery/rgb_vs_spectral.png (strips at normal incidence: for the soap film, left,
and anodised titanium, right, one block per light in the order above, each block the
spectral truth, the RGB path and the recovered table from top to bottom; every colour
adapted to D65 as the comparison, exposed so the film's brightest truth under D65 is
Y = 0.5, constant-lightness clip to sRGB).

Usage: PYTHONPATH=. python benchmarks/bench_rgb_vs_spectral.py [--update-docs] [--films A,B]
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
FILMS_TOML = ROOT / "docs" / "films.toml"
DOC = ROOT / "docs" / "rgb_vs_spectral.md"
PICTURE = ROOT / "docs" / "gallery" / "rgb_vs_spectral.png"
BEGIN, END = "<!-- rgb-vs-spectral:begin -->", "<!-- rgb-vs-spectral:end -->"
#: The lights, in the table's order.
LIGHTS = ("D65", "A", "FL11", "LED-RGB1", "RGB-LED-D65")
#: Samples of the comparison grid.
THICKNESSES = 200
COSINES = np.linspace(0.05, 1.0, 20)
#: The picture: films, columns per strip, rows per strip, gaps.
PICTURE_FILMS = ("SoapFilm", "AnodisedTitanium")
STRIP_WIDTH, STRIP_HEIGHT, GAP = 384, 16, 8
#: The brightest spectral truth under D65 of a film in the picture is at this Y.
EXPOSURE_Y = 0.5
SPACE = "sRGB"  # linear Rec.709: the renderer's working space


def sample_grid(film):
    """(thickness_um, cos_theta) of the comparison: midpoints of equal thickness steps."""
    lo, hi = film.range_um
    t = lo + (np.arange(THICKNESSES) + 0.5) * (hi - lo) / THICKNESSES
    return t, COSINES


def tables(film, lights):
    """The film's material tables at the default resolution: light -> (H, W, 3) XYZ
    relative to D65 (the light CAT02-adapted to D65, as the table a film file's
    ``illuminant`` makes)."""
    from ocio_thinfilm.lut import film_lights, material_tables

    W, H = material_tables.default_resolution(film)
    t = material_tables.axis_nodes(*film.range_um, W)
    c = material_tables.axis_nodes(0.0, 1.0, H)
    out = {}
    for name in lights:
        if name == film_lights.LED_NAME:
            out[name] = film_lights.film_light_XYZ(film, t, c, [name], film.adaptation)[0]
        else:
            lit = dataclasses.replace(film, illuminant=name)
            out[name] = material_tables.film_angle_XYZ(lit, t, c)[0]
    return out, (W, H)


def stats(dE):
    """p50 / p95 / max, rounded to 3 decimals."""
    values = np.asarray(dE, dtype=np.float64).reshape(-1)
    return [round(float(np.percentile(values, q)), 3) for q in (50, 95)] + [
        round(float(values.max()), 3)
    ]


def measure_film(film):
    """Every light's figures for one film, and its tables (for the picture)."""
    from ocio_thinfilm import reproducible
    from ocio_thinfilm.colour import colorimetry
    from ocio_thinfilm.lut import film_lights

    t, c = sample_grid(film)
    T, C = np.meshgrid(t, c)
    truth = reproducible.canonical(film_lights.film_light_XYZ(film, t, c, LIGHTS))
    tabs, size = tables(film, LIGHTS)
    table_d65 = colorimetry.XYZ_to_RGB(film_lights.table_lookup(tabs["D65"], film.range_um, T, C))
    rows = []
    for k, name in enumerate(LIGHTS):
        A = film_lights.scene_adaptation(name, film.adaptation)
        rgb_path = film_lights.rgb_path_XYZ(table_d65, name, SPACE)
        read = film_lights.table_lookup(tabs[name], film.range_um, T, C)  # adapted to D65
        recovered = reproducible.matmul(read, reproducible.inv3(A).T)
        under_light = film_lights.rgb_path_XYZ(colorimetry.XYZ_to_RGB(read, SPACE), name, SPACE)
        rows.append(
            {
                "light": name,
                "rgb_path": stats(film_lights.delta_E_under(rgb_path, truth[k], name)),
                "recovered": stats(film_lights.delta_E_under(recovered, truth[k], name)),
                "recovered_x_light": stats(film_lights.delta_E_under(under_light, truth[k], name)),
            }
        )
    return rows, size, tabs


def light_rows():
    """Each light's RGB in linear Rec.709 (the RGB path's multiplier) and its xy."""
    from ocio_thinfilm.lut import film_lights

    out = []
    for name in LIGHTS:
        white = film_lights.light_white_XYZ(name)
        out.append(
            {
                "light": name,
                "xy": [round(float(v), 4) for v in white[:2] / white.sum()],
                "rgb": [round(float(v), 4) for v in film_lights.light_RGB(name, SPACE)],
            }
        )
    return out


def table_markdown(result):
    """docs/rgb_vs_spectral.md's table, from the JSON."""

    def fmt(v):
        return " / ".join(f"{x:.2f}" for x in v)

    lines = [
        "| film | light | RGB path | recovered (white light) | recovered × light RGB |",
        "|---|---|---|---|---|",
    ]
    for film in result["films"]:
        for r in film["lights"]:
            lines.append(
                f"| {film['film']} | {r['light']} | {fmt(r['rgb_path'])} | "
                f"{fmt(r['recovered'])} | {fmt(r['recovered_x_light'])} |"
            )
    lines.append("")
    lines.append("The lights as an RGB renderer stores them (linear Rec.709, Y = 1):")
    lines.append("")
    lines.append("| light | x, y | RGB |")
    lines.append("|---|---|---|")
    for r in result["lights"]:
        xy = ", ".join(f"{v:.4f}" for v in r["xy"])
        rgb = ", ".join(f"{v:.3f}" for v in r["rgb"])
        lines.append(f"| {r['light']} | {xy} | {rgb} |")
    return "\n".join(lines)


def strips(film, tabs):
    """The picture's column for one film: linear Rec.709 (H, STRIP_WIDTH, 3), adapted."""
    from ocio_thinfilm import reproducible
    from ocio_thinfilm.colour import colorimetry
    from ocio_thinfilm.lut import film_lights

    lo, hi = film.range_um
    t = lo + (np.arange(STRIP_WIDTH) + 0.5) * (hi - lo) / STRIP_WIDTH
    one = np.ones_like(t)
    truth = film_lights.film_light_XYZ(film, t, [1.0], LIGHTS)[:, 0]
    table_d65 = colorimetry.XYZ_to_RGB(film_lights.table_lookup(tabs["D65"], film.range_um, t, one))
    exposure = EXPOSURE_Y / float(truth[0, :, 1].max())
    blocks = []
    for k, name in enumerate(LIGHTS):
        A = film_lights.scene_adaptation(name, film.adaptation)
        rgb_path = film_lights.rgb_path_XYZ(table_d65, name, SPACE)
        recovered = film_lights.table_lookup(tabs[name], film.range_um, t, one)  # adapted
        rows = [
            reproducible.matmul(truth[k], A.T),
            reproducible.matmul(rgb_path, A.T),
            recovered,
        ]
        for XYZ in rows:
            rgb = colorimetry.XYZ_to_RGB(XYZ * exposure, SPACE)
            blocks.append(np.repeat(rgb[None], STRIP_HEIGHT, axis=0))
            blocks.append(np.full((1, STRIP_WIDTH, 3), np.nan))  # hairline between strips
        blocks[-1] = np.full((GAP, STRIP_WIDTH, 3), np.nan)
    return np.concatenate(blocks[:-1], axis=0)


def write_picture(films, tabs, path):
    """docs/gallery/rgb_vs_spectral.png (module docstring); ``tabs``: key -> the film's
    tables (:func:`tables`)."""
    from ocio_thinfilm import registry, reproducible
    from ocio_thinfilm.colour import clip, encodings
    from ocio_thinfilm.io import images

    columns = [strips(films[key], tabs[key]) for key in PICTURE_FILMS]
    gap = np.full((columns[0].shape[0], GAP * 2, 3), np.nan)
    linear = np.concatenate([columns[0], gap, columns[1]], axis=1)
    background = np.isnan(linear[..., 0])
    clipped = clip.clip_RGB(np.nan_to_num(linear), "sRGB")
    code = encodings.encode(reproducible.snap(clipped), registry.as_display("sRGB").encoding)
    code = np.where(background[..., None], 1.0, np.clip(code, 0.0, 1.0))
    pixels = np.round(reproducible.snap(code) * 255.0).astype(np.uint8)
    images.write_image(path, pixels, dtype="uint8")
    return path


def main():
    sys.path.insert(0, str(ROOT))
    from benchmarks import _reports
    from ocio_thinfilm.lut import film_lights
    from ocio_thinfilm.physics import films as films_module

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    _reports.add_update_docs(parser)
    parser.add_argument("--films", help="comma-separated keys of docs/films.toml (default all)")
    args = parser.parse_args()
    films = films_module.read_films(FILMS_TOML)
    keys = args.films.split(",") if args.films else list(films)
    assert LIGHTS[-1] == film_lights.LED_NAME
    result = {
        "method": "benchmarks/bench_rgb_vs_spectral.py (module docstring)",
        "grid": {"thicknesses": THICKNESSES, "cos_theta": [0.05, 1.0, len(COSINES)]},
        "led": {
            "name": film_lights.LED_NAME,
            "model": "Ohno 2005, colour.colorimetry.sd_multi_leds_Ohno2005",
            "peaks_nm": list(film_lights.LED_PEAKS_NM),
            "half_spectral_widths_nm": list(film_lights.LED_WIDTHS_NM),
            "peak_power_ratios": list(film_lights.LED_POWER_RATIOS),
        },
        "lights": light_rows(),
        "films": [],
    }
    if args.update_docs and keys != list(films):
        raise SystemExit("--update-docs needs every film (no --films)")
    kept = {}
    for key in keys:
        start = time.perf_counter()
        rows, size, tabs = measure_film(films[key])
        result["films"].append({"film": key, "table": list(size), "lights": rows})
        if key in PICTURE_FILMS:
            kept[key] = tabs
        print(f"{key}: {time.perf_counter() - start:.0f} s", file=sys.stderr)
    print(table_markdown(result))
    if keys != list(films):
        print("(--films: reports/bench_rgb_vs_spectral.json left as it was)")
        return
    _reports.write_json("rgb_vs_spectral", result, indent=1)
    _reports.update_section(DOC, BEGIN, END, table_markdown(result), update=args.update_docs)
    if args.update_docs:
        write_picture(films, kept, PICTURE)
        print(f"wrote {PICTURE.relative_to(ROOT)}")
    else:
        print(f"{PICTURE.relative_to(ROOT)} not redrawn (--update-docs draws it)")


if __name__ == "__main__":
    main()

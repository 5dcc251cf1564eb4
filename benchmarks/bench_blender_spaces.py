"""Benchmark: the soap film's out-of-Rec.709 blues in Blender's working spaces.

A soap film (n = 1.33, free-standing, in air) at 0.25 um reflects blues outside
Rec.709 (a negative red near normal incidence). The package writes its tables
(``export material``: ``export_material`` with ``--space`` Linear Rec.709 (sRGB),
Linear Rec.2020 and ACEScg in one folder, ``--gamut keep`` and ``--gamut clip``; clip
only for the spaces with a display's primaries); a reflection-only script over them
(:func:`ocio_thinfilm.export.hosts.blender.blender_script` without the transmittance
table) puts the film on the mirror sphere of tests/test_blender.py (uniform white world,
orthographic camera, Cycles CPU, 1 sample, ``--size`` px) in a Blender 5 scene of each
working space; the script loads that space's tables. Each render is converted to linear
BT.709 (colour-science, CAT02 for ACEScg's white, as the tables were made) and compared
with colour-science's exact, unclamped reflectance (:mod:`evaluation.materials`):
DeltaE2000 p50 / max over the disc, and at its centre pixel (normal incidence).

Writes reports/bench_blender_spaces.json (``_reports.write_json``) and
reports/bench_blender_spaces.md; never a tracked doc.

Usage: PYTHONPATH=. python benchmarks/bench_blender_spaces.py [--size 65]
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
THICKNESS = 0.25
FILMS = (
    "[materials.Soapy]\nn = 1.33\n\n"
    '[films.Soap]\nstack = ["air", "Soapy", "air"]\nrange_um = [0, 1]\n'
)
#: Blender 5's working spaces and the registry's names of their tables' spaces.
WORKING = {
    "Linear Rec.709": "Linear Rec.709 (sRGB)",
    "Linear Rec.2020": "Linear Rec.2020",
    "ACEScg": "ACEScg",
}


def _folder(work: Path, gamut: str) -> tuple[Path, list[str]]:
    """Export the film's tables in the spaces ``gamut`` allows; write the script."""
    from ocio_thinfilm.export import material
    from ocio_thinfilm.export.hosts.blender import BlenderTables, blender_script
    from ocio_thinfilm.physics import films

    films_file = work / "films.toml"
    films_file.write_text(FILMS)
    film = films.read_films(films_file)["Soap"]
    spaces = [s for s in WORKING.values() if gamut == "keep" or material.gamut_display(s)]
    out = work / gamut
    material.export_material(film, out, space=spaces, gamut=gamut, size="256x128")
    entries = []
    for i, space in enumerate(spaces):
        stem = material.space_stem("ThinFilm_User_Soap", space, first=i == 0)
        table = material.material_table(film, space=space, width=256, height=128, gamut=gamut)
        entries.append(BlenderTables(space, f"{stem}_R.exr", None, material.outside_gamut(table)))
    script = out / "Soap_reflection.py"
    first = entries[0]
    script.write_text(
        blender_script(
            "Soap",
            first.reflectance,
            None,
            film.range_um,
            space=first.space,
            outside=first.outside,
            alternates=entries[1:],
        )
    )
    return script, spaces


def measure(size: int) -> dict:
    import colour

    from evaluation import blender, materials

    if blender.bpy_python() is None:
        blender.install_bpy()
    _, _, disc, cos_theta = blender.sphere_pixels(size)
    centre = int(np.argmax(cos_theta[disc]))
    exact = materials.film_rgb(materials.SOAP_BUBBLE, THICKNESS, cos_theta[disc])
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench-spaces-") as tmp:
        work = Path(tmp)
        for gamut in ("keep", "clip"):
            script, spaces = _folder(work, gamut)
            for working, space in WORKING.items():
                out = work / f"{gamut}_{space.replace(' ', '_')}.exr"
                answer = blender.render(
                    {
                        "engine": "CYCLES",
                        "size": size,
                        "samples": 1,
                        "out": str(out),
                        "material": {
                            "kind": "script",
                            "script": str(script),
                            "name": "Thin Film Soap",
                        },
                        "thickness_um": [THICKNESS, THICKNESS],
                        "working_space": working,
                    }
                )
                got = blender.read_exr(out)[disc]
                if working != "Linear Rec.709":
                    got = colour.RGB_to_RGB(
                        got,
                        materials.COLOUR_SPACES[space],
                        "ITU-R BT.709",
                        chromatic_adaptation_transform="CAT02",
                    )
                de = materials.delta_e(got, exact)
                rows.append(
                    {
                        "gamut": gamut,
                        "working_space": working,
                        "tables": space if space in spaces else spaces[0],
                        "p50": round(float(np.median(de)), 2),
                        "max": round(float(de.max()), 2),
                        "centre": round(float(de[centre]), 2),
                        "said": [line for line in answer["said"] if "built" not in line],
                    }
                )
                print(json.dumps(rows[-1]), flush=True)
    outside = float(np.mean((exact < 0).any(axis=1)))
    return {"size": size, "thickness_um": THICKNESS, "outside_709": round(outside, 3), "rows": rows}


def markdown(result: dict) -> str:
    """The DeltaE table as markdown."""
    lines = [
        f"Soap film (n = 1.33, in air) at {result['thickness_um']} um on the mirror sphere, "
        f"Cycles, {result['size']} px; {100 * result['outside_709']:.0f} % of the disc's exact "
        "colours are outside Rec.709.",
        "",
        "| export | scene working space | tables loaded | DeltaE2000 p50 | max | centre |",
        "| --- | --- | --- | ---: | ---: | ---: |",
    ]
    for row in result["rows"]:
        lines.append(
            f"| --gamut {row['gamut']} | {row['working_space']} | {row['tables']} | "
            f"{row['p50']:.2f} | {row['max']:.2f} | {row['centre']:.2f} |"
        )
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--size", type=int, default=65)
    args = parser.parse_args()
    result = measure(args.size)
    REPORT.mkdir(exist_ok=True)
    _reports.write_json("blender_spaces", result, indent=2)
    text = markdown(result)
    (REPORT / "bench_blender_spaces.md").write_text(text + "\n")
    print(text)


if __name__ == "__main__":
    main()

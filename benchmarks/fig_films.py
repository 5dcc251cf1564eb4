"""Figure of docs/films.md: the paper's model against the exact one, and temper colours.

Strips of display colour (sRGB, the constant-lightness clip) against physical thickness:

1. a free soap film (the built-in ``soap film``: water's dispersion) in air, 0-1.5 um:
   the paper's Eq. 7 (equal amplitudes, peak 1) and the exact film, the latter shown at
   the paper's mean brightness (scaled so both have the same average Y over the strip);
2. mineral oil (n = 1.47) on water at 30 degrees, the same two;
3. haematite (Fe2O3) growing on iron, 0-300 nm, exact, as reflected (no scaling): the
   temper colours;

and beside them each strip's CIE 1976 chroma C*ab at the same lightness scale: how far
the paper's model overstates the saturation. Writes docs/films.png.

Usage: python benchmarks/fig_films.py
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

FILMS = """
[materials.MineralOil]
n = 1.47
[films.Soap]
stack = ["air", "soap film", "air"]
[films.SoapPaper]
stack = ["air", "soap film", "air"]
model = "paper"
[films.Oil]
stack = ["air", "MineralOil", "water"]
angle_deg = 30
[films.OilPaper]
stack = ["air", "MineralOil", "water"]
angle_deg = 30
model = "paper"
[films.Temper]
stack = ["air", "Fe2O3", "Fe"]
range_um = [0, 0.3]
"""


def main() -> None:
    import colour
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ocio_thinfilm.colour import clip, colorimetry
    from ocio_thinfilm.lut import film_tables
    from ocio_thinfilm.physics import films as films_module

    films = films_module.parse_films(FILMS, "figure.toml")
    width = 600

    def strip(key):
        film = films[key]
        t = np.linspace(*film.range_um, width)
        XYZ = film_tables.film_XYZ(film, t)
        return t, XYZ

    def show(XYZ):
        rgb = clip.clip_RGB(colorimetry.XYZ_to_RGB(XYZ, "sRGB"), "sRGB")
        return colour.cctf_encoding(np.clip(rgb, 0, 1), function="sRGB")

    def chroma(XYZ):
        Lab = colour.XYZ_to_Lab(
            XYZ, colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
        )
        return np.hypot(Lab[..., 1], Lab[..., 2])

    rows = []
    for exact, paper, label in (
        ("Soap", "SoapPaper", "soap film in air"),
        ("Oil", "OilPaper", "oil (1.47) on water, 30°"),
    ):
        t, e = strip(exact)
        _, p = strip(paper)
        gain = p[:, 1].mean() / e[:, 1].mean()
        rows.append((f"{label}: paper (Eq. 7)", t, p))
        rows.append((f"{label}: exact, scaled to the paper's mean Y (x{gain:.1f})", t, e * gain))
    t, temper = strip("Temper")
    rows.append(("Fe2O3 on iron: exact, as reflected (temper colours)", t, temper))

    fig, axes = plt.subplots(
        len(rows), 2, figsize=(11, 1.1 * len(rows) + 0.6), gridspec_kw={"width_ratios": [3, 2]}
    )
    for (label, t, XYZ), (a, b) in zip(rows, axes, strict=True):
        a.imshow(np.repeat(show(XYZ)[None], 24, axis=0), extent=(t[0], t[-1], 0, 1), aspect="auto")
        a.set_yticks([])
        a.set_title(label, fontsize=8, loc="left")
        b.plot(t, chroma(XYZ), lw=1)
        b.set_ylabel("C*ab", fontsize=7)
        b.tick_params(labelsize=7)
        a.tick_params(labelsize=7)
    axes[-1, 0].set_xlabel("physical thickness (um)", fontsize=8)
    axes[-1, 1].set_xlabel("physical thickness (um)", fontsize=8)
    fig.tight_layout()
    out = ROOT / "docs" / "films.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()

"""Frame time of the three.js film module beside three.js's own iridescence.

The scene of tests/test_three_material.py (a mirror sphere of 512 x 256 segments filling a
512 x 512 canvas, uniform white environment), in headless Chromium on SwiftShader (WebGL2
on the CPU: absolute times are far from a GPU's; the ratio is the point). The same
``MeshPhysicalMaterial`` draws with the film (the table's R as its Fresnel term) and with
``iridescence = 1`` (Belcour & Barla's model, three.js's ``evalIridescence``); each frame
ends in a 1-pixel ``readPixels`` so that it is finished. The page runs in Chromium's
virtual time (its clock stands still while script runs), so each time is the difference of
two whole runs' wall-clock times: with ``FRAMES`` extra frames and with none.

Writes reports/bench_three_material.json (``_reports.write_json``); never a tracked doc.

Run: ``PYTHONPATH=. python benchmarks/bench_three_material.py [FRAMES]``.
"""

from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # benchmarks._reports, the evaluation package

from benchmarks import _reports  # noqa: E402  (after the path above)
from evaluation import browser, materials, three_film  # noqa: E402
from ocio_thinfilm.export.hosts.three import three_module  # noqa: E402

STACK = materials.SOAP_BUBBLE  # n = 1.33 in air
RANGE_UM = (0.0, 1.0)
SIZE = 512


def _run(chromium: str, three: Path, draw: str, frames: int) -> float:
    """Seconds Chromium takes to open the page and draw ``frames`` extra frames."""
    tmp = Path(tempfile.mkdtemp(prefix="bench-three-"))
    site = tmp / "site"
    module = three_module("Soap", "Soap_R.exr", RANGE_UM)
    three_film.write_site(site, three, module, SIZE, [0.4], frames + 1)
    rgb = materials.table(STACK, RANGE_UM, 64, 32)
    materials.write_table(
        site / "Soap_R.exr", rgb, key="Soap", quantity="reflectance", range_um=RANGE_UM
    )
    with browser.serve(site) as url:
        dom, stderr, seconds = browser.dump_dom(
            chromium,
            f"{url}index.html?draw={draw}",
            tmp / "profile",
            f"--window-size={SIZE},{SIZE}",
            timeout=600,
        )
    shutil.rmtree(tmp, ignore_errors=True)
    out = browser.page_readback(dom, stderr)
    if "error" in out or out.get("drawn") != draw:
        sys.exit(out.get("error", "the page drew nothing"))
    return seconds


def main(frames: int = 100) -> None:
    chromium = browser.chromium()
    if chromium is None:
        sys.exit("no chromium")
    three = browser.install_three()
    ms = {}
    for draw in ("film", "iridescence"):
        runs = [
            (_run(chromium, three, draw, frames) - _run(chromium, three, draw, 0)) for _ in range(2)
        ]
        ms[draw] = min(runs) / frames * 1000.0
    print(
        f"three.js {browser.THREE_VERSION}, {SIZE}x{SIZE} px, SwiftShader (CPU), {frames} "
        f"frames, best of 2:\n"
        f"  film module (table R)              {ms['film']:7.2f} ms/frame\n"
        f"  MeshPhysicalMaterial, iridescence 1 {ms['iridescence']:6.2f} ms/frame\n"
        f"  ratio film / iridescence           {ms['film'] / ms['iridescence']:7.2f}"
    )
    _reports.write_json(
        "three_material",
        {
            "three": browser.THREE_VERSION,
            "size": SIZE,
            "frames": frames,
            "ms_per_frame": ms,
            "ratio": ms["film"] / ms["iridescence"],
        },
        indent=2,
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100)

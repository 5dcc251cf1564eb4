"""Benchmark of the numeric core: a script that prints numbers.

    python benchmarks/bench_core.py [--repeats N]

1. Single-film spectra, 4096 thicknesses x 421 wavelengths (360-780 nm, 1 nm):
   the paper's closed form (``spectra.two_beam_reflectance``, Eq. 7) and the exact
   Airy sum (``exact.airy_reflectance``, s and p averaged) against
   colour-science's transfer-matrix method ``colour.phenomena.thin_film_tmm`` on the
   same grid, in the same run. Best of several repeats; the ratio is the speed-up.
   The goal is >= 20x for the closed form. Also checks that Airy and
   colour's TMM agree (max |dR|) so the comparison is like for like.
2. The constant-lightness clip, XYZ and RGB forms, on a 4096 x 2160 float32 image
   of out-of-gamut-heavy colours, in Mpixel/s (best of repeats), with the
   per-channel clamp and a memory copy of the same buffer for scale.

Not a timed test: numbers depend on the machine and its load. Writes
reports/bench_core.json.
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from benchmarks import _reports  # noqa: E402  (after the path above)
from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.physics import exact, spectra  # noqa: E402


def best_of(fn, repeats):
    """Best wall time of ``repeats`` calls (after one warm-up call) and the last result."""
    result = fn()
    best = np.inf
    for _ in range(repeats):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best, result


def bench_spectra(repeats):
    import colour

    n_film = 1.33
    thickness = np.linspace(0.0, 2000.0, 4096)  # physical thickness, nm
    wl = np.arange(360.0, 781.0, 1.0)
    t_opt = spectra.optical_thickness(thickness, n_film)

    t_two_beam, _ = best_of(lambda: spectra.two_beam_reflectance(t_opt, wl), repeats)
    t_airy, R_airy = best_of(lambda: exact.airy_reflectance(thickness, wl, n_film), repeats)
    t_tmm, (R_tmm, _) = best_of(
        lambda: colour.phenomena.thin_film_tmm([1.0, n_film, 1.0], thickness, wl),
        max(2, repeats // 2),
    )
    R_tmm = R_tmm.mean(axis=-1)[:, 0, :].T  # (W, A, T, 2) -> (T, W), unpolarised
    print(
        f"Single film, {thickness.size} thicknesses x {wl.size} wavelengths "
        f"({thickness.size * wl.size / 1e6:.2f} M spectral samples), n = {n_film}:"
    )
    print(f"  colour.phenomena.thin_film_tmm       {t_tmm * 1e3:9.1f} ms")
    print(
        f"  spectra.two_beam_reflectance (Eq. 7) {t_two_beam * 1e3:9.1f} ms   "
        f"{t_tmm / t_two_beam:6.1f}x faster  (goal: >= 20x)"
    )
    print(
        f"  exact.airy_reflectance (exact)     {t_airy * 1e3:9.1f} ms   "
        f"{t_tmm / t_airy:6.1f}x faster"
    )
    print(f"  max |R_airy - R_tmm| = {np.abs(R_airy - R_tmm).max():.2e}")
    return t_tmm / t_two_beam, t_tmm / t_airy


def bench_clip(repeats):
    height, width = 2160, 4096
    rng = np.random.default_rng(0)
    # Soap-film colours over 0-2 um (35 % out of sRGB) jittered in Y, tiled to 4K.
    t = np.linspace(0.0, 2660.0, width)
    row = colorimetry.film_XYZ(t)
    gain = rng.uniform(0.2, 1.2, (height, 1, 1))
    XYZ = (row[None, :, :] * gain).astype(np.float32)
    RGB = colorimetry.XYZ_to_RGB(XYZ).astype(np.float32)
    outside = np.mean(~clip.in_gamut(RGB))
    mpix = height * width / 1e6
    print(
        f"Clip, {width} x {height} float32 image ({mpix:.1f} Mpixel, "
        f"{outside:.0%} of pixels outside sRGB):"
    )
    results = {}
    for name, fn in (
        ("clip_XYZ (paper's XYZ form)", lambda: clip.clip_XYZ(XYZ)),
        ("clip_RGB (RGB form)", lambda: clip.clip_RGB(RGB)),
        ("clamp_RGB (baseline)", lambda: clip.clamp_RGB(RGB)),
        ("memory copy", lambda: RGB.copy()),
    ):
        seconds, _ = best_of(fn, repeats)
        results[name] = mpix / seconds
        print(f"  {name:30s} {seconds * 1e3:8.1f} ms  {mpix / seconds:8.1f} Mpixel/s")
    return results


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timed repeats (best is kept)")
    args = parser.parse_args(argv)
    print(
        f"python {platform.python_version()}, numpy {np.__version__}, "
        f"{os.cpu_count()} CPUs, {platform.machine()}"
    )
    ratio_closed, ratio_airy = bench_spectra(args.repeats)
    print()
    clip_rates = bench_clip(max(1, args.repeats // 2))
    print()
    verdict = "PASS" if ratio_closed >= 20 else "FAIL"
    print(
        f"closed form vs thin_film_tmm: {ratio_closed:.1f}x ({verdict}, goal >= 20x); "
        f"Airy: {ratio_airy:.1f}x"
    )
    result = {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "cpus": os.cpu_count(),
        "repeats": args.repeats,
        "closed_form_over_tmm": ratio_closed,
        "airy_over_tmm": ratio_airy,
        "goal_closed_form_over_tmm": 20.0,
        "clip_mpix_per_s": clip_rates,
    }
    _reports.write_json("core", result)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

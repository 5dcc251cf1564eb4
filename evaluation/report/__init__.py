"""The ``report`` sub-command: error against run time, peers, stability, throughput.

``ocio-thinfilm report [--out reports] [--quick]`` measures everything it writes, in
one run, on the machine it runs on, and writes ``<out>/report.md``, PNG plots
(matplotlib, Agg) and ``<out>/report.json`` with the raw numbers. Nothing in the
report is typed in: every error and every speed is measured here, speeds are given
as ratios to a reference measured in the same run, and the machine (CPU model,
cores, library versions) is described at the top.

Sections
--------
1. Error against run time for each knob a user can turn (ΔE2000 mean / p99 / max
   against a high-accuracy reference; cost), with a Pareto plot per knob and the
   defaults (read from the functions' signatures) marked:
   spectral step with and without band-limited integration; 1D table size and
   spacing; 3D LUT size, domain/shaper and interpolation; analytic per-pixel
   evaluation against LUT application.
2. Peers on the same data: (a) gamut mapping -- the constant-lightness clip, the
   per-channel clamp, OCIO's ACES 1.3 gamut compression and a CSS Color 4 style
   OKLCh chroma reduction; (b) exact band-limited integration against the Gaussian
   fits of the CIE matching functions of Belcour & Barla (2017) used by MaterialX
   and the glTF sample viewer; (c) the closed-form film against colour-science's
   transfer-matrix method.
3. Stability on stiff and extreme inputs, as case -> expected -> observed. The cases
   are defined once, in :mod:`evaluation.stability`; every row names the
   test in ``tests/test_stability.py`` that asserts it independently.
4. Throughput against the bandwidth bound (a memory copy of the same image), one
   thread and all threads.

Modules
-------
- :mod:`.run`: :func:`run_report` and :data:`SECTIONS` (the driver).
- :mod:`.context`: :class:`~.context.Context` (shared by the sections) and
  :class:`~.context.Section` (what each returns: markdown, raw numbers, headline facts).
- :mod:`.measure`: timing, statistics, ΔE, OCIO speed, :func:`machine_description`,
  :func:`fmt`; :mod:`.datasets`: test inputs; :mod:`.plots`: the Pareto plot.
- :mod:`.peers`: the peer algorithms (Belcour & Barla fits, CSS Color 4 OKLCh mapping).
- One module per section: :mod:`.spectral_step` (1a), :mod:`.table1d` (1b),
  :mod:`.lut3d` (1c), :mod:`.analytic_vs_lut` (1d), :mod:`.gamut` (2a),
  :mod:`.gaussian` (2b), :mod:`.tmm` (2c), :mod:`.stability_table` (3),
  :mod:`.throughput` (4).
- :mod:`.headline`: the headline, from the facts the sections store in
  ``report.json["headline"]`` under explicit ids.

References
----------
- Smits, B. E., Meyer, G. W. (1990). Newton's Colors: Simulating Interference
  Phenomena in Realistic Image Synthesis. Eurographics Workshop on Photosimulation.
- Belcour, L., Barla, P. (2017). A Practical Extension to Microfacet Theory for the
  Modeling of Varying Iridescence. ACM Transactions on Graphics 36(4), 65. The
  Gaussian fits of the XYZ sensitivities in Fourier space as shipped in the Khronos
  glTF sample viewer (``source/Renderer/shaders/iridescence.glsl``,
  ``evalSensitivity``) and MaterialX (``libraries/pbrlib/genglsl/lib/
  mx_microfacet_specular.glsl``, ``mx_eval_sensitivity``).
- W3C CSS Color Module Level 4, section 13.2 "CSS Gamut Mapping to an RGB
  Destination" (binary search in OKLCh, JND 0.02 in deltaEOK, epsilon 0.0001).
- Ottosson, B. (2020). A perceptual color space for image processing (Oklab).
"""

from __future__ import annotations

from evaluation.report.measure import fmt, machine_description
from evaluation.report.peers import (
    belcour_barla_film_XYZ,
    belcour_barla_sensitivity,
    oklch_gamut_map_RGB,
)
from evaluation.report.run import SECTIONS, run_report
from evaluation.report.stability_table import stability_rows
from evaluation.stability import spectral_white_XYZ

__all__ = [
    "run_report",
    "SECTIONS",
    "belcour_barla_sensitivity",
    "belcour_barla_film_XYZ",
    "oklch_gamut_map_RGB",
    "machine_description",
    "stability_rows",
    "spectral_white_XYZ",
    "fmt",
]

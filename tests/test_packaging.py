"""What the package needs and what it ships.

SciPy is not a runtime dependency: colour-science runs without it (it substitutes a stand-in
for ``scipy.interpolate`` and warns), and every colour-science call the package makes (all
of them in :mod:`ocio_thinfilm.colour.colorimetry`, plus the demo's sRGB encoding) gives
the same bits with SciPy hidden. The tests' reference integrator, colour-science's
``sd_to_XYZ`` on a 0.1 nm grid, does need it: SciPy is in the ``test`` extra.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

# Run in a child process with SciPy hidden: ``import scipy`` raises ImportError there, as in
# an environment without it, and colour-science takes its no-SciPy path.
_HIDE_SCIPY = 'import sys; sys.modules["scipy"] = None\n'

_PRODUCT_CALLS = '''
import json, sys
import numpy as np
from ocio_thinfilm.colour import colorimetry
from ocio_thinfilm.physics import sampling
from ocio_thinfilm.cli import demo

out = {
    "film_XYZ": colorimetry.film_XYZ(np.linspace(0.0, 3000.0, 301)),
    "film_XYZ_fine": colorimetry.film_XYZ(np.linspace(0.0, 3000.0, 31), step=0.5),
    "morpho_XYZ": colorimetry.morpho_XYZ(np.linspace(0.0, 80.0, 17)),
    "weights_1nm": colorimetry.spectral_weights(sampling.wavelength_grid(step=1.0)),
    "cmfs_at": colorimetry.cmfs_at([380.5, 455.25, 555.0, 779.5]),
    "locus": colorimetry.spectral_locus_XYZ(),
    "dE": colorimetry.delta_E2000([[0.2, 0.3, 0.4], [0.5, 0.5, 0.5]],
                                  [[0.21, 0.3, 0.4], [0.5, 0.45, 0.55]]),
    "demo_sRGB": demo._encode(np.linspace(0.0, 1.0, 11)[:, None].repeat(3, 1)),
}
for space in colorimetry.RGB_SPACES:
    out["matrix " + space] = colorimetry.matrix_XYZ_to_RGB(space)
    out["white " + space] = colorimetry.white_XYZ(space)
out = {k: np.asarray(v, np.float64).tolist() for k, v in out.items()}
out["scipy"] = type(sys.modules.get("scipy")).__name__
print(json.dumps(out))
'''


def _child(code: str) -> subprocess.CompletedProcess:
    env = dict(os.environ, OCIO_THINFILM_CACHE="0",  # compute, do not read the disk cache
               PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=env, cwd=ROOT, timeout=300)


def test_the_package_needs_no_scipy():
    """Reference: the same calls in a child process with SciPy installed and visible."""
    hidden = _child(_HIDE_SCIPY + _PRODUCT_CALLS)
    assert hidden.returncode == 0, hidden.stderr
    shown = _child(_PRODUCT_CALLS)
    assert shown.returncode == 0, shown.stderr
    without, with_ = json.loads(hidden.stdout), json.loads(shown.stdout)
    # colour-science noticed the absence and substituted its stand-in
    assert without.pop("scipy") == "MagicMock" and with_.pop("scipy") == "module"
    assert without.keys() == with_.keys()
    for key in with_:
        assert np.array_equal(np.asarray(without[key]), np.asarray(with_[key])), key


def test_the_tests_reference_integrator_needs_scipy():
    """colour-science's ``sd_to_XYZ`` of a spectrum on a 0.1 nm grid (as
    tests/test_colorimetry.py calls it) fails without SciPy: why the ``test`` extra has it."""
    code = '''
import numpy as np, colour
from ocio_thinfilm.physics import sampling
wl = sampling.wavelength_grid(step=0.1)
sd = colour.SpectralDistribution(np.ones(wl.size), wl)
print(colour.sd_to_XYZ(sd, colour.MSDS_CMFS["CIE 1931 2 Degree Standard Observer"],
                       colour.SDS_ILLUMINANTS["D65"], method="Integration"))
'''
    assert _child(code).returncode == 0
    hidden = _child(_HIDE_SCIPY + code)
    assert hidden.returncode != 0 and "Mock" in hidden.stderr, hidden.stderr[-2000:]

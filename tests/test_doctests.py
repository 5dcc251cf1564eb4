"""The examples in the numeric core's docstrings run (as ``pytest --doctest-modules``
would), so the documentation cannot drift from the code. Their expected values are
independent of the code: hand-computed (optical path, quarter wave, Eq. 9's peak,
Eq. 14 at normal incidence) or documented elsewhere (colour-science's thin_film_tmm
doctest value for a 250 nm film of index 1.5; the D65 white; the luminance a clip
keeps)."""

from __future__ import annotations

import doctest

import pytest

from ocio_thinfilm.colour import clip, colorimetry
from ocio_thinfilm.physics import spectra

MODULES = [spectra, colorimetry, clip]


@pytest.mark.parametrize("module", MODULES, ids=lambda m: m.__name__)
def test_docstring_examples(module):
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
    assert result.attempted > 0
    assert result.failed == 0

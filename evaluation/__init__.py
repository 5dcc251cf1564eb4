"""Evaluation code: what the tests, the benchmarks and the report measure against.

Not part of the shipped package: a top-level package of the repository, beside
``benchmarks/``, that imports :mod:`ocio_thinfilm` (which never imports it; the
``report`` command loads it from a checkout). The tests find it on the repository root
(``pythonpath`` in pyproject.toml); the benchmarks put the root on ``sys.path``.

- :mod:`.colours`: the test-colour sets (object and monochromatic colours).
- :mod:`.stability`: the stability cases, defined once (the films, the clip's extreme
  XYZ inputs, the shipped OCIO clip transform: input, expected behaviour, a check that
  can fail, the covering test), run by tests/test_stability.py and listed in the
  report's stability table.
- :mod:`.formatting`: the number format of the report and of the stability cases.
- :mod:`.report`: the ``report`` sub-command (a package: driver, sections, peers,
  measurement helpers, headline).
- :mod:`.gpu`: the headless GPU renderer used by tests/test_gpu.py.
- :mod:`.browser`: headless Chromium, a localhost server and three.js from npm, for the
  tests of the browser pages (docs/knobs.html, docs/glsl.md's three.js page).
- :mod:`.views`: the committed config's views applied the way a host does (OCIO's CPU
  processor), the extreme inputs, colour-science's decoding of display code values.
- :mod:`.truth`: the independent truths in one declared mapping: colour-science's names
  of each gamut and log curve, OCIO's built-in display transforms, the HDR displays'
  H.273 code points (tests/test_truth.py: each covers exactly the registry's entries).
- :mod:`.materials`: films' reflectance and transmittance colours from colour-science
  alone (exact TMM, CMFs, illuminant, RGB colourspaces) and their material tables as
  EXRs: the truth the renderer tests compare with.
- :mod:`.blender`: PyPI ``bpy`` in its own venv and the test scene
  (``blender_scene.py``, run by that venv's Python) of tests/test_blender.py.
"""

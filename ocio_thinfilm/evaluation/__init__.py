"""Evaluation code: what the tests, the benchmarks and the report measure against.

Not part of the shipped path (tables, LUTs, config, export, render never import it).

- :mod:`.colours`: the test-colour sets (object and monochromatic colours).
- :mod:`.stability`: the clip's extreme XYZ cases (input, expected behaviour, check),
  run by tests/test_stability.py and listed in the report's stability table.
"""

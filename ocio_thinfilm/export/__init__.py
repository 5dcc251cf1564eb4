"""Stage 6: the files users load.

- :mod:`.files` -- standalone table and clip LUTs (``export film|morpho|clip``), the ``luts/`` set;
- :mod:`.view` -- display/view LUTs through OCIO's Baker (``export view``);
- :mod:`.bake` -- the config folder and the set, written safely (``bake``).
"""

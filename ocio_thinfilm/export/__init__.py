"""Stage 6: the files users load.

Every file the package writes is written here (the stages before it hand over data and OCIO
objects).

- :mod:`.files` -- standalone table and clip LUTs (``export film|morpho|clip``);
- :mod:`.view` -- display/view LUTs through OCIO's Baker (``export view``);
- :mod:`.shader` -- the clip and compression views as GLSL and DCTL code, no LUT
  (``export shader``);
- :mod:`.bake` -- the config folder and the ``luts/`` set, written safely (``bake``);
- :mod:`.merged` -- a studio config with the additions (``bake --into``) and ``.ocioz``
  archives.
"""

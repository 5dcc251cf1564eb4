"""Stage 6: the files users load.

Every file the package writes is written here (the stages before it hand over data and OCIO
objects).

- :mod:`.files` -- standalone table and clip LUTs (``export film|morpho|clip``);
- :mod:`.view` -- display/view LUTs through OCIO's Baker (``export view``; its shaper:
  :mod:`.view_shaper`, its fitted tables: :mod:`.view_fit`);
- :mod:`.shader` -- the clip and compression views as GLSL and DCTL code, no LUT
  (``export shader``; the code's parts: :mod:`.shader_parts`, in the tokens of
  :mod:`.shader_language`);
- :mod:`.knob_page` -- ``docs/knobs.html``, a WebGL2 page that draws test colours
  through the exported GLSL, to choose the compression's knobs (its style sheet and
  script: :mod:`.knob_page_script`);
- :mod:`.hosts` -- a film's material tables in renderers: a Blender script, a three.js
  module, a glTF binary, a MaterialX document, a Mitsuba 3 BSDF;
- :mod:`.material` -- a film as a renderer's material: its reflectance (and
  transmittance) over thickness x view angle as float EXRs (``export material``);
- :mod:`.material_cost` -- what such a table costs (memory, time), checked before it
  is computed;
- :mod:`.bake` -- the config folder and the ``luts/`` set, written safely (``bake``);
- :mod:`.merged` -- a studio config with the additions (``bake --into``) and ``.ocioz``
  archives.
"""

"""Stage 4: tables and LUTs as OCIO transforms.

- :mod:`.ocio_ops` -- the one implementation of each OCIO op helper (a leaf);
- :mod:`.tables` -- the 1D thin-film tables (pixel value -> exact XYZ);
- :mod:`.film_tables` -- the tables of users' films (physical thickness -> XYZ);
- :mod:`.material_tables` -- a film's colour over thickness x view angle (the
  material tables of ``export material``);
- :mod:`.material_engine` -- their numeric core: a group of rows evaluated from the
  stack's phasor coefficients, on any number of threads with the same bits;
- :mod:`.film_lights` -- a film under a coloured light against an RGB renderer's;
- :mod:`.khr_iridescence` -- what glTF viewers draw for ``KHR_materials_iridescence``
  (three.js r187's model in numpy);
- :mod:`.iridescence_fit` -- its parameters fitted to an exact film (``.glb`` fallback);
- :mod:`.display_transforms` -- display matrices and encodings, the ACES baseline;
- :mod:`.grid` -- where the gamut maps' LUT nodes go: charts, node layouts, shapers;
- :mod:`.node_fit` -- the clip's black pass as planar geometry, and the fit of its
  nodes outside the gamut (Smits & Meyer 1990, Section 3.2's faces through black);
- :mod:`.storage` -- 16-bit codes that half-float textures keep;
- :mod:`.clip_lut` -- the clip (Section 3.2) baked into two 3D LUTs;
- :mod:`.compress_lut` -- the soft compression: a LUT before each of the clip's;
- :mod:`.options` -- the bake's knobs as one validated object (``MapOptions``);
- :mod:`.view_transforms` -- every view: CIE-XYZ-D65 -> display code values;
- :mod:`.lattice_fit` -- lattice regression (Garcia & Gupta 2009): node values whose
  interpolation best fits a map at given colours (the portable display LUTs).
"""

__all__ = [
    "ocio_ops",
    "tables",
    "film_tables",
    "material_tables",
    "material_engine",
    "film_lights",
    "khr_iridescence",
    "iridescence_fit",
    "display_transforms",
    "grid",
    "node_fit",
    "storage",
    "clip_lut",
    "compress_lut",
    "options",
    "view_transforms",
    "lattice_fit",
]

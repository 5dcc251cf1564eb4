"""Stage 4: tables and LUTs as OCIO transforms.

- :mod:`.ocio_ops` -- the one implementation of each OCIO op helper (a leaf);
- :mod:`.tables` -- the 1D thin-film tables (pixel value -> exact XYZ);
- :mod:`.display_transforms` -- display matrices and encodings, the ACES baseline;
- :mod:`.clip_lut` -- the clip baked into two 3D LUTs;
- :mod:`.view_transforms` -- every view: CIE-XYZ-D65 -> display code values.
"""

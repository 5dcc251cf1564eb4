"""Precomputed tables (paper Section 2.1) and the 3D LUT of the clip, as OCIO transforms.

Stage 4 of the pipeline. INTERFACE CONTRACT (the renderer and the report use exactly
these names; the implementation is filled in by the LUT/config work):

- ``BUILT``: list of strings, one per table or LUT *computed* in this process
  (e.g. ``"film:phase-change:<size>"``, ``"morpho:<size>"``, ``"clip3d:sRGB:<size>"``);
  cached results are not re-appended. Tests use it to prove a scene builds only
  what it needs.
- ``film_table(kind, ...) -> Table1D`` for ``kind`` in ``("phase-change", "no-phase-change")``:
  pixel value = optical thickness t' = n t cos(theta_t) in micrometres -> exact XYZ.
- ``morpho_table(...) -> Table1D``: pixel value = cos(theta) of the viewing angle
  (facing ratio, N.V) -> exact XYZ of the Morpho multilayer (Eq. 9 + 14).
- ``Table1D``: ``.kind``, ``.values`` (XYZ array), ``.transform()`` (an OCIO transform
  from the pixel encoding, all three channels equal, to CIE-XYZ-D65), ``.lookup(x)``
  (numpy evaluation of the same interpolation).
- ``clip_transform(display, size=...)``: OCIO transform CIE-XYZ-D65 -> display-linear
  RGB, constant-lightness clipped (the 3D LUT with its shaper).
- ``view_transform(display, view)``: OCIO transform CIE-XYZ-D65 -> display-encoded RGB
  for ``view`` in ``VIEWS``.
- ``apply(transform, pixels)``: apply an OCIO transform to a float32 (..., 3) array
  with OCIO's CPU processor; returns a new array.
"""

VIEWS = ("Constant-Lightness Clip", "Channel Clamp", "ACES Gamut Compression", "Raw")

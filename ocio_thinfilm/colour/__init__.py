"""Stage 2-3: spectra -> CIE XYZ -> display RGB (:mod:`.colorimetry`), and the
constant-lightness parallelepiped clip of Section 3.2 (:mod:`.clip`)."""

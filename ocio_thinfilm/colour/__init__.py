"""Stage 2-3: spectra -> CIE XYZ -> display RGB, and the gamut maps on the paper's ray.

- :mod:`.colorimetry` -- reflectance spectra -> CIE XYZ -> linear RGB (Section 2.1);
- :mod:`.encodings` -- the SDR displays' encodings in float64 (the LUT builders' curves);
- :mod:`.clip` -- the constant-lightness parallelepiped clip of Smits & Meyer (1990),
  Section 3.2, its two factors (the faces through black, through white) and baselines;
- :mod:`.compress` -- the soft constant-lightness compression on the same ray, and its
  two squeezes;
- :mod:`.views` -- each view kind's map in closed form (the clip, the compression, the
  clamp);
- :mod:`.adaptation` -- the von Kries chromatic adaptation (a film's illuminant to
  D65, the ACES whites);
- :mod:`.log_curves` -- the log curves of the encoded input spaces, encoded and
  decoded by the kind of each registry curve.
"""

__all__ = ["colorimetry", "adaptation", "encodings", "clip", "compress", "views", "log_curves"]

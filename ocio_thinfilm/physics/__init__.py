"""Stage 1: thin-film reflectance spectra (Smits & Meyer 1990, Section 2).

- :mod:`.spectra` -- the paper's models: two-beam films (Eq. 5-8), optical thickness
  (Eq. 10/11), the multilayer of Eq. 9 and the Morpho geometry of Eq. 14;
- :mod:`.exact` -- exact optics used as references: the Airy sum with Fresnel
  amplitudes, transfer matrices;
- :mod:`.airy` -- the Airy sum's arithmetic (real, pointwise and band-limited), the
  kernel of :func:`.exact.airy_reflectance`;
- :mod:`.phasor` -- a stack at one angle as coefficients of its varying layer's phasor
  (the exact engine of the material tables, reproducible complex arithmetic);
- :mod:`.sampling` -- wavelength grids, argument checks and the band-limited
  integration every model shares;
- :mod:`.materials` -- optical constants n + ik of real materials (a package: the model,
  its readers and the built-in library, one module each);
- :mod:`.film_file` -- users' film files (TOML): stacks of those materials, as
  :class:`~.film_file.Film` objects;
- :mod:`.films` -- a film's spectra (the exact and the paper's model, its wavelength
  grid);
- :mod:`.light` -- the names of the light a film is seen under (illuminant, adaptation).
"""

"""Stage 1: thin-film reflectance spectra (Smits & Meyer 1990, Section 2, Eq. 5-14): :mod:`.spectra`."""

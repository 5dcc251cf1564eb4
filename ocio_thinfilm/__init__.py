"""ocio-thinfilm: Smits & Meyer's "Newton's Colors" (1990) as a colour-managed tool.

Pipeline stages, one module each:

- :mod:`.spectra`      thin-film reflectance spectra (paper Section 2, Eq. 5-14)
- :mod:`.colorimetry`  spectra -> CIE XYZ -> linear RGB (Section 2.1)
- :mod:`.clip`         constant-lightness parallelepiped clip (Section 3.2)
- :mod:`.tables`       1D tables and the 3D clip LUT as OCIO transforms
- :mod:`.config`       the drop-in OpenColorIO config
- :mod:`.export`       the ``bake`` and ``export`` commands
- :mod:`.render`       the paper's example scenes (Section 4)
- :mod:`.report`       error against run time, and stability
- :mod:`.cli`          the ``ocio-thinfilm`` command
"""

__version__ = "0.1.0"

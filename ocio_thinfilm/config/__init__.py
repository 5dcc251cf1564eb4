"""The drop-in OpenColorIO config: data -> factories -> config -> validate -> files.

In the style of OpenColorIO-Config-ACES:

- :mod:`.data` -- the config described as plain data (:func:`config_data`), from the
  registry, the thin-film tables and the clip LUTs;
- :mod:`.factories` -- one OCIO object from one dict;
- :mod:`.generate` -- :func:`generate_config` (validated);
- :mod:`.merge` -- the same additions merged into an existing config (``bake --into``).

This stage turns data into OCIO ``Config`` objects and writes nothing: the files are
``ocio_thinfilm.export``'s (:mod:`ocio_thinfilm.export.bake`,
:mod:`ocio_thinfilm.export.merged`).

The public names of :mod:`.data`, :mod:`.factories` and :mod:`.generate` are
importable from this package.
"""

from ocio_thinfilm.config.data import *  # noqa: F401,F403
from ocio_thinfilm.config.data import __all__ as _data_all
from ocio_thinfilm.config.factories import *  # noqa: F401,F403
from ocio_thinfilm.config.factories import __all__ as _factories_all
from ocio_thinfilm.config.generate import *  # noqa: F401,F403
from ocio_thinfilm.config.generate import __all__ as _generate_all

__all__ = [*_data_all, *_factories_all, *_generate_all]

"""``python -m ocio_thinfilm`` is the ``ocio-thinfilm`` command."""

from ocio_thinfilm.cli.main import main

raise SystemExit(main())

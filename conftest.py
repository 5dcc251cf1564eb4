"""pytest at the repository root: ``python -m ocio_thinfilm`` runs the command when
imported, so ``--doctest-modules`` does not collect it."""

collect_ignore = ["ocio_thinfilm/__main__.py"]

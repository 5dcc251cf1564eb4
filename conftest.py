"""pytest at the repository root: ``python -m ocio_thinfilm`` runs the command when
imported, so ``--doctest-modules`` does not collect it; ``evaluation/blender_scene.py`` is
the script Blender's own Python runs (it imports ``bpy``, which lives in its own venv:
:mod:`evaluation.blender`)."""

collect_ignore = ["ocio_thinfilm/__main__.py", "evaluation/blender_scene.py"]

"""File output shared by every command: safe writes and image I/O (OpenImageIO).

One implementation, used by ``bake``, ``export``, ``render``, ``demo`` and ``report``,
one topic per module:

- :mod:`.transactions` -- every output written aside, checked, fsynced, then renamed
  into place; several files committed together (:class:`Transaction`), so a failure
  anywhere leaves every previous output as it was;
- :mod:`.durable` -- the checked low-level writes (every write, fsync and close; XML
  parsed to its end);
- :mod:`.destinations` -- regular files replaced atomically, special files
  (``/dev/null``, a FIFO, ``/dev/stdout``) written through, links followed;
- :mod:`.ownership` -- output directories written only if missing, empty or holding
  the marker :data:`MARKER` of an earlier run (only its listed files are touched);
- :mod:`.temporaries` -- temporary names and the removal of killed runs' leftovers;
- :mod:`.signals` -- SIGINT/SIGTERM held back while a commit renames;
- :mod:`.faults` -- a test hook that kills the process at a named commit step;
- :mod:`.images` -- OpenImageIO reads and checked writes.
"""

from __future__ import annotations

from ocio_thinfilm.io.destinations import StrPath, check_output_file, check_writable, is_stdout
from ocio_thinfilm.io.durable import check_xml, write_bytes
from ocio_thinfilm.io.images import read_image, write_image
from ocio_thinfilm.io.ownership import MARKER, claim_directory
from ocio_thinfilm.io.signals import deferred_signals
from ocio_thinfilm.io.temporaries import TMP_PREFIX, clean_stale
from ocio_thinfilm.io.transactions import (
    Transaction,
    atomic_directory,
    atomic_file,
    transaction,
    write_text,
)

__all__ = [
    "StrPath",
    "MARKER",
    "TMP_PREFIX",
    "Transaction",
    "transaction",
    "atomic_file",
    "atomic_directory",
    "claim_directory",
    "check_writable",
    "check_output_file",
    "check_xml",
    "clean_stale",
    "is_stdout",
    "write_bytes",
    "write_text",
    "write_image",
    "read_image",
    "deferred_signals",
]

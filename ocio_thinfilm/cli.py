"""The ``ocio-thinfilm`` command line.

Each sub-command lives in the module of its pipeline stage, which exposes
``register(subparsers)``; this module only collects them and turns errors into a
one-line message with exit code 2.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from . import __version__
from .io import UsageError

#: Modules that contribute sub-commands, in the order ``--help`` lists them.
COMMAND_MODULES = ("demo", "export", "render", "report")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="ocio-thinfilm",
        description="Thin-film interference colours (Smits & Meyer 1990) for "
                    "OpenColorIO pipelines: spectra, constant-lightness gamut clip, "
                    "LUTs, an OCIO config and the paper's example scenes.")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in COMMAND_MODULES:
        try:
            module = importlib.import_module(f"ocio_thinfilm.{name}")
        except ModuleNotFoundError as error:
            if error.name != f"ocio_thinfilm.{name}":
                raise
            continue
        module.register(sub)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return int(args.func(args) or 0)
    except (UsageError, ValueError) as error:
        print(f"ocio-thinfilm {args.command}: error: {error}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # e.g. `ocio-thinfilm demo | head`
        sys.stderr.close()
        return 0
    except OSError as error:
        print(f"ocio-thinfilm {args.command}: error: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"ocio-thinfilm {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())

"""The ``ocio-thinfilm`` command line.

Each sub-command lives in the module of its pipeline stage, which exposes
``register(subparsers)``; this module only collects them and holds the contract every
command keeps:

- **Errors** are one line on stderr, ``ocio-thinfilm <command>: error: <message>``,
  naming the option and what it allows, and exit code 2 (argparse's usage block is
  folded into that line: the message ends with where to find ``--help``). A command
  with sub-commands is named by both words (``ocio-thinfilm export view: error: ...``),
  its sub-parsers raise the same one-line errors, and an option the sub-command does
  not take is ``unrecognized arguments: --option ...``.
- **Signals.** SIGINT (Ctrl-C), SIGTERM and SIGHUP, at any moment, print
  ``ocio-thinfilm <command>: interrupted`` (``... interrupted by SIGTERM``) and exit
  with 128 + the signal number (130, 143, 129); every output is then either the old
  file or the new one (:mod:`.io` commits with signals held back) and no temporary is
  left. A signal that a shell set to be ignored (``nohup``, background jobs) stays
  ignored. Run as the program (``main()`` with no arguments), the process ends with
  ``os._exit`` right after flushing its output, so there is no interpreter shutdown
  during which a signal could kill it silently.
- Anything unexpected is one line too (exit 1); ``OCIO_THINFILM_DEBUG=1`` shows the
  traceback. This module imports only the standard library at import time, so the
  handlers are in place before the heavy imports (numpy, colour-science, OCIO) start.
"""

from __future__ import annotations

import os
import signal
import sys
import warnings
from collections.abc import Sequence
from typing import TYPE_CHECKING

from ocio_thinfilm import __version__

if TYPE_CHECKING:
    import argparse

#: Modules that contribute sub-commands, in the order ``--help`` lists them.
COMMAND_MODULES = ("cli.demo", "cli.export", "cli.render", "cli.report")
PROG = "ocio-thinfilm"
_HANDLED = ("SIGINT", "SIGTERM", "SIGHUP")


class Interrupted(KeyboardInterrupt):
    """Raised by the signal handler: a KeyboardInterrupt that knows its signal.

    Parameters
    ----------
    signum : int, optional
        The signal's number (default SIGINT).

    Attributes
    ----------
    signum : int
        The signal's number.
    """

    def __init__(self, signum=signal.SIGINT):
        super().__init__(signum)
        self.signum = signum


class _ParseError(Exception):
    def __init__(self, prog, message):
        super().__init__(message)
        self.prog = prog


_state = {"interrupted": None}


def _handler(signum, frame):
    if _state["interrupted"] is not None:
        return  # already unwinding: let the clean-up finish
    _state["interrupted"] = signum
    raise Interrupted(signum)


def _install_handlers() -> dict:
    previous = {}
    for name in _HANDLED:
        sig = getattr(signal, name, None)
        if sig is None:
            continue
        try:
            current = signal.getsignal(sig)
            if current is signal.SIG_IGN:
                continue  # nohup / background job: keep ignoring
            previous[sig] = current
            signal.signal(sig, _handler)
        except (ValueError, OSError):  # not the main thread
            pass
    return previous


def _restore_handlers(previous: dict) -> None:
    for sig, handler in previous.items():
        try:
            signal.signal(sig, handler if handler is not None else signal.SIG_DFL)
        except (ValueError, OSError, TypeError):
            pass


def _parser_class():
    import argparse

    class Parser(argparse.ArgumentParser):
        """argparse with one-line errors (raised, printed by :func:`main`)."""

        def error(self, message):
            raise _ParseError(self.prog, _explain(self, message))

    return Parser


def _explain(parser, message: str) -> str:
    """Return argparse's message, made to say what is allowed and where the help is."""
    import argparse
    import re

    m = re.match(r"argument (\S+?)(?:/\S+)?: invalid (float|int) value: (.*)", message)
    if m:
        what = "a number" if m.group(2) == "float" else "an integer"
        message = f"{m.group(1)} must be {what}, got {m.group(3)}"
    m = re.match(r"argument (\S+?)(?:/\S+)?: expected (\w+) arguments?", message)
    if m:
        for action in parser._actions:
            if m.group(1) in action.option_strings and isinstance(action.metavar, tuple):
                message += f" ({' '.join(action.metavar)})"
    m = re.match(r"argument (\S+): invalid choice: (\S+) \(choose from (.*)\)", message)
    if m and m.group(1) in ("COMMAND", "command"):
        message = f"unknown command {m.group(2)}; choose from {m.group(3).replace(chr(39), '')}"
    elif m and any(  # a command's own sub-command (export TABLE)
        a.metavar == m.group(1) and a.nargs == argparse.PARSER for a in parser._actions
    ):
        message = (
            f"unknown {m.group(1)} {m.group(2)}; choose from {m.group(3).replace(chr(39), '')}"
        )
    m = re.match(r"the following arguments are required: (.*)", message)
    if m:
        for action in parser._actions:
            if action.metavar == m.group(1) or action.dest == m.group(1):
                message += f" ({action.help})" if action.help else ""
    return f"{message} (see '{parser.prog} --help')"


def build_parser() -> argparse.ArgumentParser:
    """Build the ``ocio-thinfilm`` parser with every command module's sub-command.

    A command module that is not installed (:data:`COMMAND_MODULES`) is left out.

    Returns
    -------
    argparse.ArgumentParser
        The parser; its errors raise instead of exiting (:func:`main` prints them on
        one line).
    """
    import argparse
    import importlib

    parser = _parser_class()(
        prog=PROG,
        description="Thin-film interference colours (Smits & Meyer 1990) for "
        "OpenColorIO pipelines: spectra, constant-lightness gamut clip, "
        "LUTs, an OCIO config and the paper's example scenes.",
    )
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
    assert isinstance(parser, argparse.ArgumentParser)
    return parser


#: Library parameters whose option has another name (``dest`` of the argparse action),
#: for every command (key None) and for one command.
PARAMETER_DEST = {
    None: {"value_range": "range", "fmt": "format", "out_dir": "out", "shaper": "resolve_shaper"},
    "bake": {"source": "into"},
    "export": {"path": "out", "thickness_um": "thickness", "workers": "jobs"},
}


def _option_message(parser, command, error) -> str:
    """Return a :class:`~ocio_thinfilm.checks.ParameterError`'s message naming an option.

    The option of ``command`` for the parameter (``value_range`` -> ``--range``); the
    parameter's own name when the command has no such option.
    """
    sub = parser
    for word in command.split() if command else ():
        sub = sub._subparsers._group_actions[0].choices.get(word) if sub._subparsers else None
        if sub is None:
            break
    first = command.split()[0] if command else None
    dest = PARAMETER_DEST.get(first, {}).get(error.parameter) or PARAMETER_DEST[None].get(
        error.parameter, error.parameter
    )
    for action in sub._actions if sub is not None else ():
        if action.dest == dest:
            longest = max(action.option_strings, key=len, default=None)
            return error.for_option(longest or str(action.metavar or dest))
    return str(error)


def _error(command, message) -> None:
    where = PROG if command is None else f"{PROG} {command}"
    text = " ".join(str(message).split())  # one line, whatever the message held
    print(f"{where}: error: {text}", file=sys.stderr)


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``ocio-thinfilm`` with ``argv``.

    Errors are one line on stderr; SIGINT, SIGTERM and SIGHUP print ``interrupted``
    (see the module docstring).

    Parameters
    ----------
    argv : sequence of str, optional
        The arguments after the program name. ``None`` (default): the process's own,
        run as the program -- the process then ends with ``os._exit`` at exit, right
        after flushing its output (a signal arriving meanwhile still sets the exit
        code).

    Returns
    -------
    int
        The exit code: 0, 1 for an unexpected failure, 2 for bad input, 128 + n for
        signal n.

    Raises
    ------
    SystemExit
        For ``--help`` and ``--version`` when ``argv`` is given.
    """
    as_program = argv is None
    if as_program:
        # colour-science warns on import that SciPy is absent; nothing the command calls
        # needs it (tests/test_dependencies.py), so the program's stderr stays clean
        warnings.filterwarnings("ignore", message='"SciPy" related API features')
    _state.update(interrupted=None, late=None, command=None)
    previous = _install_handlers()
    code = 1
    try:
        code = _main(argv, _set)
    except SystemExit as error:  # --help, --version
        code = error.code if isinstance(error.code, int) else (0 if error.code is None else 1)
        if not as_program:
            raise
    except KeyboardInterrupt as error:
        signum = getattr(error, "signum", signal.SIGINT)
        name = signal.Signals(signum).name if signum != signal.SIGINT else None
        command = _state.get("command")
        where = PROG if command is None else f"{PROG} {command}"
        print(f"{where}: interrupted" + (f" by {name}" if name else ""), file=sys.stderr)
        code = 128 + int(signum)
    finally:
        if as_program:
            _exit_soon(code)
        else:
            _restore_handlers(previous)
    return code


def _interrupt_behind(error: BaseException) -> KeyboardInterrupt | None:
    """Return the KeyboardInterrupt that ``error`` was raised from or while handling.

    Our signal handlers raise one; ``None`` if there is none in the chain.
    """
    seen = set()
    current: BaseException | None = error
    while current is not None and id(current) not in seen:
        if isinstance(current, KeyboardInterrupt):
            return current
        seen.add(id(current))
        current = current.__cause__ or current.__context__
    return None


def _set(name):
    _state["command"] = name


def _main(argv, set_command) -> int:
    from ocio_thinfilm.checks import ParameterError, UsageError

    parser = build_parser()
    try:
        args, extra = parser.parse_known_args(argv)
        # a command with sub-commands (export view) is named by both words
        words = (getattr(args, "command", None), getattr(args, "subcommand", None))
        command = " ".join(w for w in words if w) or None
        set_command(command)
        if extra:
            prog = PROG if command is None else f"{PROG} {command}"
            raise _ParseError(
                prog, f"unrecognized arguments: {' '.join(extra)} (see '{prog} --help')"
            )
    except _ParseError as error:
        print(f"{error.prog}: error: {' '.join(str(error).split())}", file=sys.stderr)
        return 2
    if not getattr(args, "func", None):
        group = parser._subparsers
        assert group is not None  # build_parser added the sub-commands
        names = ", ".join(sorted(map(str, group._group_actions[0].choices or ())))
        _error(None, f"no command given; choose from {names} (see '{PROG} --help')")
        return 2
    try:
        return int(args.func(args) or 0)
    except ParameterError as error:
        _error(command, _option_message(parser, command, error))
        return 2
    except (UsageError, ValueError) as error:
        _error(command, error)
        return 2
    except BrokenPipeError:  # e.g. `ocio-thinfilm demo | head`
        try:
            sys.stderr.close()
        except OSError:
            pass
        return 0
    except OSError as error:
        _error(command, error)
        return 2
    except MemoryError:
        _error(command, "out of memory")
        return 2
    except KeyboardInterrupt:
        raise
    except Exception as error:  # noqa: BLE001 -- one line for the farm's logs
        interrupt = _interrupt_behind(error)
        if interrupt is not None:
            # a signal that arrived while a C extension was being imported surfaces as
            # its ImportError ("initialization failed") raised from the interrupt
            raise interrupt from None
        ocio = sys.modules.get("PyOpenColorIO")
        if ocio is not None and isinstance(error, ocio.Exception):
            _error(command, f"OpenColorIO: {error}")
            return 2
        if os.environ.get("OCIO_THINFILM_DEBUG"):
            raise
        _error(
            command,
            f"internal error: {type(error).__name__}: {error} "
            "(OCIO_THINFILM_DEBUG=1 shows the traceback)",
        )
        return 1


def _exit_soon(code: int) -> None:
    """End the program soon: flush, then ``os._exit`` at the first atexit call.

    No interpreter shutdown, during which a signal would kill the process silently.
    """
    import atexit

    def record(signum, frame):
        _state["late"] = signum

    for name in _HANDLED:
        sig = getattr(signal, name, None)
        if sig is not None and signal.getsignal(sig) is _handler:
            signal.signal(sig, record)

    def finish():
        late = _state.get("late")
        final = code
        if late is not None and code == 0:
            command = _state.get("command")
            print(f"{PROG}{'' if command is None else ' ' + command}: interrupted", file=sys.stderr)
            final = 128 + int(late)
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except Exception:  # noqa: BLE001 -- a closed pipe: nothing more to say
                pass
        os._exit(final)

    atexit.register(finish)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())

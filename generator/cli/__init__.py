"""The ``ocioforge`` command: a thin group whose commands are imported only when run."""

from __future__ import annotations

import importlib
import os
import signal
import sys
import threading

import click

from generator.files import CannotWrite, Refused, Stopped, deferring, stop, stop_signal
from generator.ocio.environment import set_aside

#: Command name -> module under generator.cli, with its one-line help.
COMMANDS = {
    "build": "Build an OCIO config (and its LUTs) from a spec.",
    "init": "Write the embedded default spec, commented, to a file.",
    "matrix": "Print the 3x3 matrix from one colour space's linear RGB to another's.",
    "bake": "Bake a transform from a colour space to a display into a LUT file (.cube, .spi3d, .clf).",
    "pack": "Bake a show's LUT pack (its spec's [[lut_pack]] tables) into a folder, errors measured.",
    "verify": "Verify a built config: images through OCIO engines against the spec's own evaluation.",
    "plot": "Draw the CIE 1931 chromaticity diagram of a built config's colour spaces.",
    "info": "Describe a colour space or display, the library's or a spec's: gamut, white, curve, matrix.",
    "list": "List the library's colour spaces, displays and curves, or a spec's own.",
    "convert": "Convert image sequences through a config (in parallel, or on a Dask cluster), verified.",
}


class LazyGroup(click.Group):
    """The ocioforge group: each command's module imported only when that command runs."""

    def list_commands(self, ctx):
        """The command names, in the order the help lists them."""
        return list(COMMANDS)

    def get_command(self, ctx, name):
        """The command called ``name``, its module imported now; None for an unknown name."""
        if name not in COMMANDS:
            return None
        return importlib.import_module(f"generator.cli.{name.replace('-', '_')}").command

    def format_commands(self, ctx, formatter):
        """The help's command list, from :data:`COMMANDS` (no module imported)."""
        with formatter.section("Commands"):
            formatter.write_dl([(name, text) for name, text in COMMANDS.items()], col_max=12)

    def resolve_command(self, ctx, args):
        """The command ``args`` names; a usage error naming the allowed ones for an unknown name."""
        if args and not args[0].startswith("-") and args[0] not in COMMANDS:
            raise click.UsageError(f"no command {args[0]!r}; allowed: {', '.join(COMMANDS)}")
        return super().resolve_command(ctx, args)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="ocioforge", prog_name="ocioforge")
def cli():
    """ocioforge: OpenColorIO configs and LUTs from a declarative spec, checked by numbers."""


def printable(text: str) -> str:
    """``text`` with every character a terminal would not print as itself (a newline in a path)
    escaped as Python writes it, so that a message stays one line; a byte of a path that is not
    UTF-8 (which Python holds as a lone surrogate) as that byte, ``\\xff``."""
    return "".join(
        c if c.isprintable() else f"\\x{ord(c) - 0xDC00:02x}" if 0xDC80 <= ord(c) <= 0xDCFF else repr(c)[1:-1]
        for c in str(text)
    )


class StandardOutputFailed(Exception):
    """Standard output could not take a command's report (a full device): the OSError it raised."""


def say(text: str) -> None:
    """Print a command's report on standard output; a failure there is :class:`StandardOutputFailed`,
    told apart from the failure of a file's write (both are OSErrors naming no path). A reader
    that stopped reading (``| head``) is BrokenPipeError, as before."""
    try:
        click.echo(text)
    except BrokenPipeError:
        raise
    except OSError as error:
        raise StandardOutputFailed(error) from None


def fail(message: str) -> None:
    """One line on stderr and exit status 2 (bad input)."""
    click.echo(f"error: {printable(message)}", err=True)
    sys.exit(2)


class _Given:
    """A parameter type refusing an empty value (``-o ""`` had meant the default)."""

    def convert(self, value, param, ctx):
        """``value``, refused when empty."""
        if value == "":
            self.fail("is empty; give a value", param, ctx)
        return super().convert(value, param, ctx)


class GivenPath(_Given, click.Path):
    """A path: anything but empty."""


class ConfigPath(GivenPath):
    """A built config: its config.ocio, or the build's folder holding one."""

    def convert(self, value, param, ctx):
        """The config.ocio ``value`` names (itself, or the one in a build's folder)."""
        from generator.ocio.write import CONFIG_FILENAME

        if isinstance(value, str) and os.path.isdir(value):
            if not os.path.isfile(os.path.join(value, CONFIG_FILENAME)):
                self.fail(
                    f"{value!r} is a folder without {CONFIG_FILENAME}; allowed: a config file, or a "
                    f"build's folder holding {CONFIG_FILENAME}",
                    param,
                    ctx,
                )
            value = os.path.join(value, CONFIG_FILENAME)
        if isinstance(value, str) and os.path.exists(value):
            from generator.files import not_readable

            why = not_readable(value)
            if why is not None:
                self.fail(
                    f"{value!r} {why}; allowed: a config file, or a build's folder holding {CONFIG_FILENAME}",
                    param,
                    ctx,
                )
        return super().convert(value, param, ctx)


class Name(_Given, click.types.StringParamType):
    """A name or keyword: surrounding blanks dropped (as a name is written anywhere else), then
    anything but empty."""

    def convert(self, value, param, ctx):
        """``value`` without surrounding blanks, refused when empty."""
        return super().convert(value.strip() if isinstance(value, str) else value, param, ctx)


NAME = Name()


class Command(click.Command):
    """A command refusing an option given twice (the last had silently won)."""

    def parse_args(self, ctx, args):
        """Parse ``args``; a usage error when a single-valued option is given twice."""
        _, _, order = self.make_parser(ctx).parse_args(args=[*args])  # (list: the command module)
        single = [p for p in order if isinstance(p, click.Option) and not (p.is_flag or p.multiple or p.count)]
        repeated = next((p for i, p in enumerate(single) if p in single[:i]), None)
        if repeated is not None:
            raise click.UsageError(f"{repeated.opts[-1]} is given more than once; allowed: once", ctx)
        return super().parse_args(ctx, args)


def _stop(signum, frame) -> None:
    """SIGTERM and SIGINT end the command as an exception would, so staged output is removed;
    the signal is recorded first, so that nothing is renamed into place even when the exception
    is swallowed (raised inside a weakref callback, it is only printed)."""
    stop(signum)
    if deferring():  # renaming into place: the rename's end raises Stopped
        return
    if signum == signal.SIGINT:
        raise KeyboardInterrupt
    raise SystemExit(128 + signum)


#: The signals that end a command, removing what it staged.
STOP_SIGNALS = (signal.SIGTERM, signal.SIGINT)


def main(argv=None) -> None:
    """Run a command; on the main thread, SIGTERM and Ctrl-C end it as an exception would
    (staged output removed), the previous handlers restored after."""
    stop(0)  # a stop recorded in an earlier run in this process is not this one's
    if threading.current_thread() is not threading.main_thread():
        _run(argv)
        return
    previous = {signum: signal.signal(signum, _stop) for signum in STOP_SIGNALS}
    try:
        _run(argv)
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)


def _stopped(signum: int) -> None:
    """Exit as a shell reports a signal, 128 + its number; Ctrl-C with one line (not bad input)."""
    if signum == signal.SIGINT:
        click.echo("error: interrupted", err=True)
    sys.exit(128 + signum)


def _run(argv) -> None:
    try:
        _checked_run(argv)
    except KeyboardInterrupt:  # what was staged is gone
        _stopped(signal.SIGINT)
    except Stopped as stopped:
        _stopped(stopped.signum)
    except SystemExit:
        if not stop_signal():
            raise
    if stop_signal():  # the exception the signal raised was swallowed; nothing was renamed into place
        _stopped(stop_signal())


def _checked_run(argv) -> None:
    """Run the command, its bad input (argument, path, environment) one ``error:`` line, exit 2."""
    from generator.colour_science import skip_plotting
    from generator.heap import keep_freed_memory
    from generator.spec.schema import SpecError

    try:
        _check_environment()
        skip_plotting()
        keep_freed_memory()
        with set_aside(), cli.make_context("ocioforge", [*(sys.argv[1:] if argv is None else argv)]) as ctx:
            cli.invoke(ctx)
    except click.exceptions.NoArgsIsHelpError as error:
        say(error.ctx.get_help())
    except click.UsageError as error:
        fail(error.format_message().replace("\n", " "))
    except (SpecError, CannotWrite, Refused) as error:
        fail(str(error))
    except StandardOutputFailed as failed:  # Python's own flush at exit must not fail a second time
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        fail(
            f"standard output: {failed.args[0].strerror or failed.args[0]} (files the command wrote are complete; "
            "what it printed is lost); allowed: an output with room for it (a file, a pipe or /dev/null)"
        )
    except BrokenPipeError:  # the reader stopped reading (| head): no message, as a shell's tools
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(128 + signal.SIGPIPE)
    except OSError as error:  # a path that cannot be read or resolved: too long, a loop, gone
        fail(_os_error(error))
    except click.exceptions.Exit as exit_:
        sys.exit(exit_.exit_code)


def _os_error(error: OSError) -> str:
    """What an OSError says about its path, or about the working directory when it names none
    and that is gone."""
    if error.filename is None:
        try:
            os.getcwd()
        except OSError:
            return f"the working directory: {error.strerror}; allowed: run ocioforge in a folder that exists"
    name = "" if error.filename is None else f"{os.fsdecode(error.filename)}: "
    return f"{name}{error.strerror or error}"


#: The last second of year 9999, the latest date the plots' metadata and Python's datetime
#: hold (a later SOURCE_DATE_EPOCH overflowed them with a traceback).
LATEST_EPOCH = 253402300799


def _check_environment() -> None:
    """What the environment must give a command: an open standard output, and a SOURCE_DATE_EPOCH
    that is unset (or empty) or an integer (reproducible-builds.org: a malformed one is an error; numpy's
    f2py, imported by colour-science, failed on it with a traceback)."""
    if sys.stdout is None:
        fail("standard output is closed; allowed: a command with its output open (a file, a pipe or /dev/null)")
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if epoch == "":  # CI services export it empty: unset (f2py, which colour-science imports, fails on it)
        del os.environ["SOURCE_DATE_EPOCH"]
    elif epoch is not None and not (epoch.isascii() and epoch.isdigit() and int(epoch) <= LATEST_EPOCH):
        fail(
            f"SOURCE_DATE_EPOCH={epoch!r} is not a whole number of seconds since 1970 up to the end of year "
            f"9999; allowed: unset, or such a number (0 to {LATEST_EPOCH})"
        )

"""The ``ocioforge`` command: a thin group whose commands are imported only when run."""

from __future__ import annotations

import importlib
import os
import signal
import sys
import threading

import click

# A command multiplies 3×3 matrices, never large ones, so OpenBLAS's thread pool (numpy
# starts it on import, which no module above makes) is not started: numpy's import took
# 100 ms rather than 160 on a 2-core machine (the gain varies with the machine and OpenBLAS).
# A setting in the environment is kept.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

#: Command name -> module under generator.cli, with its one-line help.
COMMANDS = {
    "build": "Build an OCIO config (and its LUTs) from a spec.",
    "init": "Write the embedded default spec, commented, to a file.",
    "matrix": "Print the 3x3 matrix from one colour space's linear RGB to another's.",
    "bake": "Bake a transform from a colour space to a display into a LUT file (.cube, .spi3d, .clf).",
    "verify": "Verify a built config: images through OCIO engines against the spec's own evaluation.",
    "plot": "Draw the CIE 1931 chromaticity diagram of a built config's colour spaces.",
    "info": "Describe a library colour space: gamut, white, curve, matrices.",
    "list": "List the library's colour spaces, displays and curves.",
}


class LazyGroup(click.Group):
    def list_commands(self, ctx):
        return list(COMMANDS)

    def get_command(self, ctx, name):
        if name not in COMMANDS:
            return None
        return importlib.import_module(f"generator.cli.{name.replace('-', '_')}").command

    def format_commands(self, ctx, formatter):
        with formatter.section("Commands"):
            formatter.write_dl([(name, text) for name, text in COMMANDS.items()], col_max=12)

    def resolve_command(self, ctx, args):
        if args and not args[0].startswith("-") and args[0] not in COMMANDS:
            raise click.UsageError(f"no command {args[0]!r}; allowed: {', '.join(COMMANDS)}")
        return super().resolve_command(ctx, args)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="ocioforge", prog_name="ocioforge")
def cli():
    """ocioforge: OpenColorIO configs and LUTs from a declarative spec, checked by numbers."""


def fail(message: str) -> None:
    """One line on stderr and exit status 2 (bad input)."""
    click.echo(f"error: {message}", err=True)
    sys.exit(2)


def _terminated(signum, frame) -> None:
    """SIGTERM ends the command as an exception would, so staged output is removed."""
    raise SystemExit(128 + signum)


def main(argv=None) -> None:
    """Run a command; on the main thread, SIGTERM ends it as an exception would (staged
    output removed), the previous handler restored after."""
    if threading.current_thread() is not threading.main_thread():
        _run(argv)
        return
    previous = signal.signal(signal.SIGTERM, _terminated)
    try:
        _run(argv)
    finally:
        signal.signal(signal.SIGTERM, previous)


def _run(argv) -> None:
    from generator.colour_science import skip_plotting
    from generator.files import CannotWrite
    from generator.spec.schema import SpecError

    skip_plotting()
    try:
        cli.main(args=argv, prog_name="ocioforge", standalone_mode=False)
    except click.exceptions.Abort:  # Ctrl-C: what was staged is gone; 128 + SIGINT, as a shell reports it
        click.echo("error: interrupted", err=True)
        sys.exit(128 + signal.SIGINT)
    except click.exceptions.NoArgsIsHelpError as error:
        click.echo(error.ctx.get_help())
    except click.UsageError as error:
        fail(error.format_message().replace("\n", " "))
    except (SpecError, CannotWrite) as error:
        fail(str(error))
    except click.exceptions.Exit as exit_:
        sys.exit(exit_.exit_code)

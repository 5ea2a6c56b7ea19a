"""Which config a convert run uses, and the names it is given, checked against it before any
frame is read.

``--config`` (a config file or a build's folder), else ``$OCIO``, else the embedded default
spec built once into the user's cache folder (``$XDG_CACHE_HOME/ocioforge``, by default
``~/.cache/ocioforge``), in a folder named after the generator's own sources, so that a
changed generator builds it anew and never reads an older build.
"""

from __future__ import annotations

import difflib
import hashlib
import os
from pathlib import Path

from generator.files import Refused, not_readable
from generator.ocio.write import build, for_folder
from generator.spec.load import load as load_spec
from generator.spec.schema import SpecError
from generator.verify.run import load as load_built

#: The default config's folder name inside the cache (the embedded spec's name).
DEFAULT_NAME = "ocioforge-studio"


def cache_folder() -> Path:
    """Where ocioforge caches files: ``$XDG_CACHE_HOME/ocioforge``, else ``~/.cache/ocioforge``."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "ocioforge"


def _sources_digest() -> str:
    """Twelve hex digits of the SHA-256 of the generator's sources and data (what a build depends on)."""
    root = Path(__file__).resolve().parents[1]
    digest = hashlib.sha256()
    for path in sorted(p for p in root.rglob("*") if p.suffix in (".py", ".toml", ".csv") and p.is_file()):
        digest.update(str(path.relative_to(root)).encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()[:12]


def default_config(announce=lambda text: None) -> Path:
    """The default spec's config, built into the cache the first time (``announce`` told)."""
    folder = cache_folder() / f"default-{_sources_digest()}" / DEFAULT_NAME
    config = folder / "config.ocio"
    if not config.is_file():
        announce(f"building the default config into {folder} (once)")
        try:
            build(for_folder(load_spec(), folder), folder)
        except Refused:  # another run built it first
            if not config.is_file():
                raise
    return config


def choose(given: str | None, announce=lambda text: None) -> str:
    """The config path: ``given``, else ``$OCIO`` (an ``ocio://`` builtin too), else the default."""
    if given:
        return given
    env = os.environ.get("OCIO", "").strip()
    return env if env else str(default_config(announce))


def load(path: str, verify: bool):
    """The loaded config; with ``verify``, also the spec beside it, checked as ``ocioforge verify``
    checks it (a config its stored spec builds). SpecError when either cannot be had."""
    import PyOpenColorIO as ocio

    if verify:
        load_built(path)  # raises SpecError naming what is missing or different
    elif not path.startswith("ocio://"):
        why = not_readable(path)
        if why is not None:
            raise SpecError(
                path,
                "-",
                f"no such config file (it {why}); allowed: a config file, a build's folder, or $OCIO naming one",
            )
    try:
        return ocio.Config.CreateFromFile(path)
    except Exception as error:  # PyOpenColorIO.Exception
        raise SpecError(path, "-", f"OpenColorIO cannot load it: {str(error).splitlines()[0]}") from None


def _near(name: str, names: list[str]) -> str:
    close = difflib.get_close_matches(name, names, n=3, cutoff=0.6)
    return f" (did you mean {', '.join(map(repr, close))}?)" if close else ""


def colour_space(cfg, name: str, option: str) -> str:
    """``name`` (a colour space, alias or role) as the config names it; SpecError otherwise."""
    space = cfg.getColorSpace(name)
    if space is None:
        names = list(cfg.getColorSpaceNames())
        raise SpecError(
            option,
            name,
            f"is no colour space, alias or role of the config{_near(name, names)}; "
            "allowed: `ocioforge list`, or the config's own names",
        )
    return space.getName()


def display_view(cfg, display: str, view: str | None) -> tuple[str, str]:
    """``display`` and ``view`` (None: the display's default view) as the config has them."""
    import PyOpenColorIO as ocio

    displays = list(cfg.getDisplaysAll())
    if display not in displays:
        raise SpecError(
            "--display",
            display,
            f"is no display of the config{_near(display, displays)}; allowed: {', '.join(displays)}",
        )
    views = list(cfg.getViews(ocio.VIEW_DISPLAY_DEFINED, display)) + list(cfg.getViews(ocio.VIEW_SHARED, display))
    chosen = view if view is not None else cfg.getDefaultView(display)
    if chosen not in views:
        raise SpecError("--view", chosen, f"is no view of {display!r}; allowed: {', '.join(views)}")
    return display, chosen

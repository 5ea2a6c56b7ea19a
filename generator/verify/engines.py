"""PyOpenColorIO in this process: the engine hosts embed, with their default
optimisation flags, and a lossless one.

OCIO's default flags (what hosts use) add, to the lossless set, fast
approximations of log, exp and pow, a fast inverse of 1D LUTs, and LUT
composition; where a default-flags check exceeds its tolerance while the
lossless one passes, :func:`explain_default_flags` names the flag and the
operator responsible, measured, rather than widening any tolerance.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import PyOpenColorIO as ocio

from generator.verify.check import KINDS, LUT, VIEW, Check
from generator.verify.judge import Output
from generator.verify.looks import LOOK

ENGINE_NAMES = ("ocio", "oiiotool", "ocioconvert", "blender", "gpu")


def load_config(config_path: str | Path):
    """The config at ``config_path``, freshly loaded by PyOpenColorIO."""
    return ocio.Config.CreateFromFile(str(config_path))


def uncached_config(config_path: str | Path):
    """The config with OCIO's processor cache off, for processors of single operators: OCIO
    caches a Lut1DTransform's processor by a key its values are not in, so the second of two
    tables of one length (a view's hue table and its inverse) got the first's processor."""
    cfg = load_config(config_path)
    cfg.setProcessorCacheFlags(ocio.PROCESSOR_CACHE_OFF)
    return cfg


#: The configs of the running verification, by (path, processor cache on): loaded once, so the
#: in-process engines and the explanations share each one's processors (:func:`run_config`).
_RUN_CONFIGS: dict[tuple[str, bool], object] = {}


def clear_caches() -> None:
    """Forget OCIO's caches (it caches LUT files by path) and the running verification's configs:
    a verification reads the files as they are when it starts."""
    ocio.ClearAllCaches()
    _RUN_CONFIGS.clear()


def run_config(config_path: str | Path, cached: bool = True):
    """The config at ``config_path``, loaded once until :func:`clear_caches` (``cached=False``:
    :func:`uncached_config`'s, for processors of single operators)."""
    key = (str(config_path), cached)
    if key not in _RUN_CONFIGS:
        _RUN_CONFIGS[key] = load_config(config_path) if cached else uncached_config(config_path)
    return _RUN_CONFIGS[key]


def processor(cfg, check: Check, config_dir: Path):
    """The OCIO processor ``check`` exercises."""
    if check.kind == VIEW:
        return cfg.getProcessor(check.src, check.display, check.view, ocio.TRANSFORM_DIR_FORWARD)
    if check.kind == LOOK:  # the look alone, in its process space
        return cfg.getProcessor(
            ocio.LookTransform(src=check.src, dst=check.dst, looks=check.item.removeprefix("look "))
        )
    if check.kind == LUT:
        path = config_dir / check.lut
        if not path.is_file():
            raise FileNotFoundError(f"missing LUT file {check.lut}")
        interpolation = {"linear": ocio.INTERP_LINEAR, "tetrahedral": ocio.INTERP_TETRAHEDRAL}[check.interpolation]
        return cfg.getProcessor(ocio.FileTransform(src=str(path), interpolation=interpolation))
    return cfg.getProcessor(check.src, check.dst)


def apply(cpu, values: np.ndarray) -> np.ndarray:
    """``values`` (n, 3) through a CPU processor, in float32 as hosts run it."""
    pixels = np.ascontiguousarray(values, dtype=np.float32).copy()
    cpu.applyRGB(pixels)
    return pixels.astype(np.float64)


@dataclass(frozen=True)
class OcioEngine:
    """PyOpenColorIO's CPU processor with the given optimisation flags."""

    name: str
    flags: str
    kinds: tuple = KINDS

    def missing(self, config_path: Path) -> str:
        """Never missing: PyOpenColorIO is a dependency."""
        return ""

    def version(self) -> str:
        """PyOpenColorIO's version and the optimisation flags."""
        return f"PyOpenColorIO {ocio.__version__}, {self.flags}"

    def optimisation(self):
        """The OCIO optimisation flags this engine names."""
        return getattr(ocio, self.flags)

    def run(self, config_path: Path, checks: list[Check], workdir: Path) -> list[list[Output]]:
        """Each check's probes through its processor, one output each (an error names what OCIO raised)."""
        cfg = run_config(config_path)
        out = []
        for check in checks:
            try:
                cpu = processor(cfg, check, config_path.parent).getOptimizedCPUProcessor(self.optimisation())
                out.append([Output(apply(cpu, check.probes.values))])
            except Exception as error:  # OCIO raises its own types; each names the problem
                out.append([Output(None, error=f"{type(error).__name__}: {error}")])
        return out


#: The flags OCIO's default set adds to the lossless one, each a possible cause of a difference.
DEFAULT_EXTRAS = (
    "OPTIMIZATION_FAST_LOG_EXP_POW",
    "OPTIMIZATION_LUT_INV_FAST",
    "OPTIMIZATION_COMP_LUT1D",
    "OPTIMIZATION_COMP_SEPARABLE_PREFIX",
)


def isolate(cfg, transforms: list, values: np.ndarray, exact, odd, error_of) -> tuple[float, str, float]:
    """The transform of a chain that alone, evaluated by ``odd`` while every other is evaluated
    by ``exact`` (each ``(processor, values) -> values``), gives the check's largest error; that
    error; and the chain's own error run operator by operator with ``exact`` alone (a chain OCIO
    evaluates differently whole, merging its operators, departs by itself, and then names no
    operator). ``cfg`` should be :func:`uncached_config`'s."""
    processors = [cfg.getProcessor(t) for t in transforms]

    def run(index: int) -> np.ndarray:
        current = values
        for position, proc in enumerate(processors):
            current = (odd if position == index else exact)(proc, current)
        return current

    worst = (-1.0, "")
    for index, transform in enumerate(transforms):
        direction = (
            "inverse" if getattr(transform, "getDirection", lambda: None)() == ocio.TRANSFORM_DIR_INVERSE else ""
        )
        worst = max(worst, (error_of(run(index)), f"{type(transform).__name__} {direction}".strip()))
    return (*worst, error_of(run(-1)))


def cpu_with(flags):
    """An evaluator for :func:`isolate`: a processor's CPU processor with ``flags``, made once
    per processor (isolate runs each operator once per operator of the chain, and making a CPU
    processor of a 117³ table took 2 ms)."""
    made: dict = {}

    def evaluate(proc, values):
        if proc not in made:
            made[proc] = proc.getOptimizedCPUProcessor(flags)
        return apply(made[proc], values)

    return evaluate


def explain_default_flags(config_path: Path, check: Check, error_of) -> str:
    """Why the default flags miss ``check``'s tolerance: the default flag whose removal
    brings the error within it, and the operator of the chain whose fast evaluation alone
    gives the largest error. ``error_of(values)`` is the check's worst error for an engine
    output. "" when no single flag explains it (the failure is then the config's)."""
    cfg = run_config(config_path, cached=False)
    proc = processor(cfg, check, config_path.parent)
    default = ocio.OPTIMIZATION_DEFAULT
    for name in DEFAULT_EXTRAS:
        without = ocio.OptimizationFlags(int(default) & ~int(getattr(ocio, name)))
        error = error_of(apply(proc.getOptimizedCPUProcessor(without), check.probes.values))
        if error <= check.tolerance:
            transforms = list(proc.createGroupTransform())
            alone, op, split = isolate(
                cfg, transforms, check.probes.values, cpu_with(without), cpu_with(default), error_of
            )
            if split > check.tolerance:
                return (
                    f"OCIO default flags: {name} (its operator not isolated: the chain run operator by operator "
                    f"departs {split:.2g} by itself); without the flag: {error:.2g}"
                )
            return f"OCIO default flags: {name} in {op} (alone: {alone:.2g}); without the flag: {error:.2g}"
    return ""


IN_PROCESS = (
    OcioEngine("ocio default", "OPTIMIZATION_DEFAULT", (*KINDS, LOOK)),
    OcioEngine("ocio lossless", "OPTIMIZATION_LOSSLESS", (*KINDS, LOOK)),
)

"""Command-line hosts: oiiotool and ocioconvert, through real image files.

Every check's probes are written as a float32 OpenEXR file; the host converts
it and the verifier reads the result back. oiiotool is the one the openimageio
package installs beside this Python (it brings its own OCIO; any oiiotool on
PATH otherwise): every check in float EXR, and every display/view a second
time into a 16-bit TIFF. ocioconvert is the system's (Debian's, OCIO 2.1), not
the one the opencolorio wheel installs beside this Python.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from generator.verify import images
from generator.verify.check import KINDS, LUT, VIEW, Check
from generator.verify.judge import Output

#: What OCIO prints when a library is older than the config it is asked to read.
TOO_NEW = "not able to load that config version"
#: Seconds one host process may take before it is stopped (a hung host fails its checks).
HOST_TIMEOUT = 600


class NotRunnable(RuntimeError):
    """The host is there but cannot run this config (e.g. its OCIO predates the config version)."""


def _beside_python(name: str) -> str | None:
    beside = Path(sys.executable).parent / name
    return str(beside) if beside.is_file() else shutil.which(name)


def _outside_python(name: str) -> str | None:
    here = Path(sys.executable).parent.resolve()
    dirs = [d for d in os.environ.get("PATH", "").split(os.pathsep) if d and Path(d).resolve() != here]
    return shutil.which(name, path=os.pathsep.join(dirs))


def installed(executable: str | None, name: str) -> str:
    """``executable``, a host program found on PATH; NotRunnable when it was not found."""
    if executable is None:
        raise NotRunnable(f"{name} is not installed")
    return executable


def ocio_in(text: str) -> str:
    """The OpenColorIO version a host's own words name ("OpenColorIO 2.1.2, color config: ..."), or ""."""
    found = re.search(r"OpenColorIO v?(\d+\.\d+(?:\.\d+)?)", text)
    return found.group(1) if found else ""


def linked_ocio(executable: str) -> str:
    """The version of the OpenColorIO library ``executable`` loads, from the file the dynamic
    loader finds (Debian's libOpenColorIO.so.2.1 is libOpenColorIO.so.2.1.2); "" when it loads
    none (a build holding OCIO statically, a script) or ldd is not there."""
    ldd = shutil.which("ldd")
    if ldd is None or executable is None:
        return ""
    for line in run_host([ldd, executable]).stdout.splitlines():
        if "libOpenColorIO" in line and "=>" in line:
            path = os.path.realpath(line.split("=>")[1].split(" (")[0].strip())
            found = re.search(r"\.so\.(\d+(?:\.\d+)+)$", path)
            if found:
                return found.group(1)
    return ""


def run_host(command: list[str], env: dict | None = None) -> subprocess.CompletedProcess:
    """Run a host program, output captured; a time-out is reported as a failed run."""
    try:
        return subprocess.run(command, capture_output=True, text=True, env=env, timeout=HOST_TIMEOUT, check=False)
    except subprocess.TimeoutExpired:
        return subprocess.CompletedProcess(command, -1, "", f"timed out after {HOST_TIMEOUT} s")


def _message(result: subprocess.CompletedProcess) -> str:
    text = (result.stderr + "\n" + result.stdout).strip()
    lines = [line for line in text.splitlines() if "error" in line.lower()] or text.splitlines() or ["no output"]
    return lines[0]


def write_inputs(checks: list[Check], workdir: Path, prefix: str) -> list[Path]:
    """Each check's probes written as a float EXR in ``workdir``, named by ``prefix`` and position."""
    paths = []
    for index, check in enumerate(checks):
        path = workdir / f"{prefix}-{index:04d}-in.exr"
        images.write(path, check.probes.values)
        paths.append(path)
    return paths


def read_output(path: Path, check: Check, variant: str, failure: str) -> Output:
    """A host's output file read back for ``check``, or the error (``failure``, the host's message) if it wrote none."""
    if not path.is_file():
        return Output(None, variant, error=failure or f"no output written ({path.name})")
    try:
        values, step = images.read(path, len(check.probes.values))
    except OSError as error:
        return Output(None, variant, error=str(error))
    return Output(values, variant, step)


@dataclass(frozen=True)
class OiiotoolEngine:
    """OpenImageIO's oiiotool (``--colorconvert``, ``--ociodisplay``, ``--ociofiletransform``), to float EXR and integer files."""

    name: str = "oiiotool"
    kinds: tuple = KINDS

    def executable(self) -> str | None:
        """The oiiotool beside this Python (pip's openimageio) or on PATH, or None."""
        return _beside_python("oiiotool")

    def missing(self, config: Path) -> str:
        """Why oiiotool cannot run here, or ""."""
        return (
            ""
            if self.executable()
            else "oiiotool is not installed (pip package openimageio or Debian's openimageio-tools)"
        )

    def version(self) -> str:
        """oiiotool's version and the OpenColorIO it was built with."""
        exe = installed(self.executable(), "oiiotool")
        oiio = run_host([exe, "--version"]).stdout.strip()  # --help names the OCIO it runs, in 2.4 and 3.x
        return f"OpenImageIO {oiio}, OCIO {ocio_in(run_host([exe, '--help']).stdout) or 'unknown'} ({exe})"

    def _ops(self, check: Check, stem: Path) -> list[str]:
        if check.kind == VIEW:
            return [
                "--iscolorspace",
                check.src,
                "--ociodisplay",
                check.display,
                check.view,
                "-o",
                f"{stem}.exr",
                "-o:datatype=uint16",
                f"{stem}.tif",
            ]
        if check.kind == LUT:
            return ["--ociofiletransform", Path(check.lut).name, "-o", f"{stem}.exr"]
        return ["--colorconvert", check.src, check.dst, "-o", f"{stem}.exr"]

    def _command(self, config: Path) -> list[str]:
        """oiiotool reading ``config``, with its frame wildcards off: a colour space, display or
        view name that reads as a path with a '#' ('Cam #1/A') is a name, not a file sequence."""
        return [installed(self.executable(), "oiiotool"), "--wildcardoff", "--colorconfig", str(config)]

    def run(self, config: Path, checks: list[Check], workdir: Path) -> list[list[Output]]:
        """Every check through one oiiotool command, read back from each file variant."""
        loaded = run_host([*self._command(config), "--echo", "ok"])
        if TOO_NEW in loaded.stdout + loaded.stderr:
            raise NotRunnable(_message(loaded))
        inputs = write_inputs(checks, workdir, "oiiotool")
        stems = [workdir / f"oiiotool-{i:04d}-out" for i in range(len(checks))]
        failures = {}
        start = 0
        while start < len(checks):
            command = self._command(config)
            for index in range(start, len(checks)):
                command += [str(inputs[index]), *self._ops(checks[index], stems[index])]
            result = run_host(command)
            done = next((i for i in range(start, len(checks)) if not Path(f"{stems[i]}.exr").is_file()), len(checks))
            if done < len(checks):
                failures[done] = _message(result)
            start = done + 1
        out = []
        for index, check in enumerate(checks):
            found = [read_output(Path(f"{stems[index]}.exr"), check, "EXR float", failures.get(index, ""))]
            if check.kind == VIEW:
                found.append(read_output(Path(f"{stems[index]}.tif"), check, "TIFF uint16", failures.get(index, "")))
            out.append(found)
        return out


@dataclass(frozen=True)
class SystemOiiotoolEngine(OiiotoolEngine):
    """The system's oiiotool (Debian's), outside this Python environment, with the OCIO it links."""

    name: str = "oiiotool system"
    #: Beside pip's oiiotool: where its OCIO 2.1 cannot load a newer config, the run does not fail.
    extra = True

    def executable(self) -> str | None:
        """The oiiotool on PATH outside this Python environment, or None."""
        return _outside_python("oiiotool")


def oiiotool_engines() -> tuple:
    """The oiiotool beside this Python (or on PATH) and, when another one is installed outside
    this Python environment (Debian's, running its own OCIO), that one too, as its own engine."""
    ours, system = OiiotoolEngine(), SystemOiiotoolEngine()
    found, other = ours.executable(), system.executable()
    if found and other and os.path.realpath(found) != os.path.realpath(other):
        return (ours, system)
    return (ours,)


@dataclass(frozen=True)
class OcioconvertEngine:
    """The system's ocioconvert, one process per check, to a float EXR."""

    name: str = "ocioconvert"
    kinds: tuple = KINDS

    def executable(self) -> str | None:
        """The system's ocioconvert (not this Python environment's), or None."""
        return _outside_python("ocioconvert")

    def missing(self, config: Path) -> str:
        """Why ocioconvert cannot run here, or ""."""
        return "" if self.executable() else "ocioconvert is not installed (Debian's opencolorio-tools)"

    def version(self) -> str:
        """Where the ocioconvert run is (it prints no version)."""
        exe = installed(self.executable(), "ocioconvert")
        return f"OCIO {linked_ocio(exe) or 'unknown'} ({exe}, the system's, outside this Python environment)"

    def _command(self, check: Check, source: Path, target: Path, config: Path) -> list[str]:
        exe = installed(self.executable(), "ocioconvert")
        if check.kind == VIEW:
            return [exe, "--view", str(source), check.src, str(target), check.display, check.view]
        if check.kind == LUT:
            return [exe, "--lut", str(config.parent / check.lut), str(source), str(target)]
        return [exe, str(source), check.src, str(target), check.dst]

    def run(self, config: Path, checks: list[Check], workdir: Path) -> list[list[Output]]:
        """Each check through its own ocioconvert process, read back from a float EXR."""
        inputs = write_inputs(checks, workdir, "ocioconvert")
        targets = [workdir / f"ocioconvert-{i:04d}-out.exr" for i in range(len(checks))]
        env = {**os.environ, "OCIO": str(config)}  # OCIO's overrides set aside by verify()
        commands = [self._command(c, s, t, config) for c, s, t in zip(checks, inputs, targets)]
        first = next((i for i, c in enumerate(checks) if c.kind != LUT), None)
        if first is not None:  # one process tells whether this OCIO reads the config at all
            probe = run_host(commands[first], env)
            if TOO_NEW in probe.stdout + probe.stderr:
                raise NotRunnable(_message(probe))
        with ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
            results = list(pool.map(lambda command: run_host(command, env), commands))
        loading = [r for c, r in zip(checks, results) if c.kind != LUT]  # --lut reads no config
        if loading and all(TOO_NEW in r.stdout + r.stderr for r in loading):
            raise NotRunnable(_message(loading[0]))
        return [
            [read_output(t, c, "EXR float", _message(r) if r.returncode else "")]
            for c, t, r in zip(checks, targets, results)
        ]

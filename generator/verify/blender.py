"""Blender as a host: the config through $OCIO, every display/view saved as a render.

One Blender run (``--factory-startup``, background) takes every view check:
each probe image is loaded as a float EXR in its source colour space, and
saved through the scene's display and view as a 16-bit PNG
(:mod:`generator.verify.blender_job`). Blender embeds its own OCIO (Debian's
3.4 has 2.1) and applies its processors with the default optimisation flags.
"""

from __future__ import annotations

import json
import os
import shutil
from dataclasses import dataclass
from pathlib import Path

from generator.verify.check import VIEW, Check
from generator.verify.hosts import (
    TOO_NEW,
    NotRunnable,
    installed,
    linked_ocio,
    read_output,
    run_host,
    write_inputs,
)
from generator.verify.judge import Output
from generator.verify.paths import RAW

SCRIPT = Path(__file__).with_name("blender_job.py")


@dataclass(frozen=True)
class BlenderEngine:
    """Blender converts every image to the scene_linear role when it loads it, so its
    Raw view shows scene_linear values, not the file's: a Raw view is checked only from
    the scene_linear role's space, where the two agree. It lists no inactive space, so
    views are not checked from one (an inactive compositing_log role's space)."""

    name: str = "blender"
    kinds: tuple = (VIEW,)

    def supports(self, check: Check, spec) -> bool:
        """Whether Blender can run ``check``: no view from an inactive space; Raw from scene_linear alone."""
        inactive = set()
        for name in spec.inactive:
            try:
                inactive.add(spec.space(name).name)
            except KeyError:  # a generated space: never a view's input
                continue
        if check.src in inactive:
            return False
        if check.view != RAW:
            return True
        scene_linear = dict(spec.roles).get("scene_linear", "")
        try:
            return spec.space(scene_linear).name == check.src
        except KeyError:
            return False

    def executable(self) -> str | None:
        """The blender on PATH, or None."""
        return shutil.which("blender")

    def missing(self, config: Path) -> str:
        """Why Blender cannot run here, or ""."""
        return "" if self.executable() else "blender is not installed (Debian's blender)"

    def version(self) -> str:
        """The first line of ``blender --version``."""
        exe = installed(self.executable(), "blender")
        result = run_host([exe, "--version"])
        ocio = linked_ocio(exe) or "unknown (linked in)"  # Debian's links the system's OCIO
        return f"{(result.stdout.strip().splitlines() or ['blender'])[0]}, OCIO {ocio}"

    def run(self, config: Path, checks: list[Check], workdir: Path) -> list[list[Output]]:
        """Each check's probes through Blender's view transform, read back from 16-bit PNGs."""
        sources: dict[tuple[str, int], Check] = {}
        for check in checks:
            sources.setdefault((check.src, id(check.probes)), check)
        unique = list(sources.values())
        inputs = dict(zip(sources, write_inputs(unique, workdir, "blender")))
        outputs = [workdir / f"blender-{i:04d}-out.png" for i in range(len(checks))]
        jobs = [
            {
                "input": str(inputs[(c.src, id(c.probes))]),
                "src": c.src,
                "display": c.display,
                "view": c.view,
                "output": str(out),
            }
            for c, out in zip(checks, outputs)
        ]
        request, status_path = workdir / "blender-jobs.json", workdir / "blender-status.json"
        request.write_text(json.dumps({"jobs": jobs, "status": str(status_path)}), encoding="utf-8")
        env = {**os.environ, "OCIO": str(config)}  # OCIO's overrides set aside by verify()
        result = run_host(
            [
                installed(self.executable(), "blender"),
                "-b",
                "--factory-startup",
                "--python",
                str(SCRIPT),
                "--",
                str(request),
            ],
            env,
        )
        if TOO_NEW in result.stdout + result.stderr:
            raise NotRunnable(next(line for line in (result.stdout + result.stderr).splitlines() if TOO_NEW in line))
        try:
            status = json.loads(status_path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            message = (result.stderr or result.stdout or "no output").strip().splitlines()[-1]
            status = {str(out): f"Blender did not finish: {message}" for out in outputs}
        return [
            [read_output(out, c, "PNG uint16", "" if status.get(str(out)) == "ok" else status.get(str(out), ""))]
            for c, out in zip(checks, outputs)
        ]

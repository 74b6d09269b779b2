"""stochtex: colour-mapped noise vector fields (Grenier et al. 2022), filtered,
and the studies of procedural textures' artifacts (Tavernier 2017), over numpy.

    import stochtex
    image = stochtex.render("camouflage", size=256, filter="smooth", scale=4)
    # float32 (256, 256, 3), linear-light RGB, row 0 on top

Every render, statistic and study runs in the C++ library (the same code as
the `stochtex` command), with the GIL released. Bad input raises
stochtex.InputError (a ValueError) with the library's message; its
`parameter` is the keyword at fault, or None where the message names a file
and JSON pointer. docs/PYTHON.md has the whole interface.
"""
from __future__ import annotations

import json
import os
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np

from . import _stochtex
from ._stochtex import (  # noqa: F401 (re-exported)
    FootprintStatistics,
    GpuUnavailable,
    ImageStream,
    InputError,
    InstanceStatistics,
    Pattern,
    PatternView,
    Renderer,
    Shadertoy,
    TextureSource,
    ZoomTexture,
    band_rows,
    encode_image,
    presets,
    read_image,
    write_image,
)
from . import studies  # noqa: F401 (re-exported)

__all__ = [
    "FootprintStatistics",
    "GpuUnavailable",
    "ImageStream",
    "InputError",
    "InstanceStatistics",
    "band_rows",
    "colormap",
    "encode_image",
    "example",
    "Pattern",
    "PatternView",
    "Renderer",
    "Shadertoy",
    "TextureSource",
    "ZoomTexture",
    "pattern",
    "presets",
    "read_image",
    "render",
    "studies",
    "write_image",
]

PatternSource = Union[Pattern, str, "os.PathLike[str]", Mapping[str, Any]]


def pattern(source: PatternSource, *, seed: Optional[int] = None) -> Pattern:
    """A Pattern from a preset name, a pattern or graph file's path, its JSON
    text, or a dict of the file's members (docs/PATTERNS.md)."""
    if isinstance(source, Pattern):
        if seed is not None:
            raise TypeError("pattern: give the seed where the Pattern is made (Pattern.preset/load/parse take seed=)")
        return source
    if isinstance(source, Mapping):
        return Pattern.parse(json.dumps(source), source="<dict>", seed=seed)
    if isinstance(source, os.PathLike):
        return Pattern.load(os.fspath(source), seed=seed)
    if isinstance(source, str):
        if source.lstrip().startswith("{"):
            return Pattern.parse(source, source="<inline JSON>", seed=seed)
        if source in presets():
            return Pattern.preset(source, seed=seed)
        return Pattern.load(source, seed=seed)
    raise TypeError(f"pattern: expected a Pattern, a preset name, a path, JSON text or a dict, got {type(source).__name__}")


def _json(spec: Union[str, Mapping[str, Any]]) -> str:
    if isinstance(spec, Mapping):
        return json.dumps(spec)
    if isinstance(spec, str):
        return spec
    raise TypeError(f"expected JSON text or a dict, got {type(spec).__name__}")


def example(spec: Union[str, Mapping[str, Any]], *, seed: Optional[int] = None, base_dir: str = ".") -> np.ndarray:
    """A noise example (`stochtex noise`) from a NOISE object of a pattern
    file, as a dict or JSON text: float32 (W, W), before Gaussianization.
    Relative paths (an image exemplar) are against base_dir."""
    return _stochtex.example(_json(spec), source="<dict>" if isinstance(spec, Mapping) else "<json>",
                             base_dir=base_dir, seed=seed)


def colormap(spec: Union[str, Mapping[str, Any]], *, base_dir: str = ".") -> np.ndarray:
    """A colormap H (`stochtex colormap`) from a COLORMAP object, as a dict or
    JSON text: its table as float32 (Ry, Rx, 3), linear light, H(x, y) at
    row y, column x."""
    return _stochtex.colormap(_json(spec), source="<dict>" if isinstance(spec, Mapping) else "<json>",
                              base_dir=base_dir)


def render(
    source: PatternSource,
    *,
    size: Union[None, int, Sequence[int]] = None,
    scale: Optional[float] = None,
    offset: Optional[Sequence[float]] = None,
    camera: str = "zoom",
    tilt_deg: float = 60.0,
    fov_deg: float = 60.0,
    filter: str = "none",
    aniso: int = 8,
    estimator: Optional[str] = None,
    gpu: bool = False,
    threads: int = 0,
    seed: Optional[int] = None,
) -> np.ndarray:
    """One view of a pattern as float32 (height, width, 3), linear-light RGB,
    row 0 on top: `stochtex render` without the file. For several views of
    one pattern, make a Renderer once (it builds the pyramids and tables)."""
    renderer = Renderer(pattern(source, seed=seed), filter=filter, aniso=aniso, estimator=estimator, gpu=gpu)
    return renderer.render(
        size=size, scale=scale, offset=offset, camera=camera, tilt_deg=tilt_deg, fov_deg=fov_deg, threads=threads
    )

# Type stubs of the C++ extension (python/src/*.cpp); python/tests/test_stubs.py
# holds them to the module's names and signatures.
import os
from typing import Callable, ClassVar, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

class InputError(ValueError):
    parameter: Optional[str]

class GpuUnavailable(RuntimeError): ...

def presets() -> List[str]: ...
def band_rows(width: int, band: int) -> int: ...
def example(
    text: str, source: str = "<json>", base_dir: str = ".", seed: Optional[int] = None
) -> npt.NDArray[np.float32]: ...
def colormap(text: str, source: str = "<json>", base_dir: str = ".") -> npt.NDArray[np.float32]: ...
def read_image(path: str) -> npt.NDArray[np.float32]: ...
def write_image(path: str, pixels: npt.ArrayLike, *, bits: int = 8, half: bool = False) -> None: ...

class Pattern:
    @staticmethod
    def preset(name: str, seed: Optional[int] = None) -> Pattern: ...
    @staticmethod
    def load(path: str, seed: Optional[int] = None) -> Pattern: ...
    @staticmethod
    def parse(text: str, source: str = "<json>", base_dir: str = ".", seed: Optional[int] = None) -> Pattern: ...
    @property
    def name(self) -> str: ...
    @property
    def seed(self) -> int: ...
    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def scale(self) -> float: ...
    @property
    def is_graph(self) -> bool: ...

class Renderer:
    def __init__(
        self,
        pattern: Pattern,
        *,
        filter: str = "none",
        aniso: int = 8,
        estimator: Optional[str] = None,
        response: str = "prefiltered-colormap",
        covariance: bool = True,
        pack8: bool = False,
        reference_max_samples: int = 64,
        kernel: str = "simd",
        gpu: bool = False,
    ) -> None: ...
    def render(
        self,
        *,
        size: Union[None, int, Sequence[int]] = None,
        scale: Optional[float] = None,
        offset: Optional[Sequence[float]] = None,
        camera: str = "zoom",
        tilt_deg: float = 60.0,
        fov_deg: float = 60.0,
        rows: Optional[Tuple[int, int]] = None,
        threads: int = 0,
    ) -> npt.NDArray[np.float32]: ...
    def view(
        self,
        *,
        size: Union[None, int, Sequence[int]] = None,
        scale: Optional[float] = None,
        offset: Optional[Sequence[float]] = None,
        baked: bool = False,
    ) -> dict: ...
    def bake(
        self,
        path: str,
        *,
        size: Union[None, int, Sequence[int]] = None,
        scale: Optional[float] = None,
        offset: Optional[Sequence[float]] = None,
        band: int = 256,
        bits: int = 8,
        threads: int = 0,
        progress: Optional[Callable[[float, str], None]] = None,
    ) -> None: ...
    def source(
        self,
        *,
        scale: Optional[float] = None,
        offset: Optional[Sequence[float]] = None,
        camera: str = "zoom",
        tilt_deg: float = 60.0,
        fov_deg: float = 60.0,
    ) -> PatternView: ...
    @property
    def example_size(self) -> int: ...
    @property
    def device(self) -> str: ...
    @property
    def filter(self) -> str: ...

class FootprintStatistics:
    def __init__(self, pattern: Pattern, *, field: int = 0, covariance: bool = False, pack8: bool = False) -> None: ...
    def estimate(
        self, uv: npt.ArrayLike, jacobian: npt.ArrayLike, *, estimator: str = "paper", aniso: int = 1
    ) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    def exact(
        self, uv: npt.ArrayLike, jacobian: npt.ArrayLike, *, max_samples: int = 512
    ) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    @property
    def example_size(self) -> int: ...
    @property
    def max_level(self) -> int: ...

def encode_image(pixels: npt.ArrayLike, *, format: str = "png", bits: int = 8, display: bool = False) -> bytes: ...

class ImageStream:
    def __init__(self, path: str, width: int, height: int, *, channels: int = 3, bits: int = 8) -> None: ...
    def write_rows(self, rows: npt.ArrayLike) -> None: ...
    def finish(self) -> None: ...
    @property
    def rows_written(self) -> int: ...

class TextureSource: ...

class ZoomTexture(TextureSource):
    def __init__(
        self,
        *,
        scaling: str = "exponential",
        offsets: str = "none",
        interpolation: str = "linear",
        offset_seed: int = 1,
        seed: int = 1,
        image: Optional[npt.ArrayLike] = None,
        **kwargs: float,
    ) -> None: ...
    def render(
        self,
        *,
        size: Union[int, Sequence[int]] = 256,
        origin: Optional[Sequence[float]] = None,
        time: float = 0.0,
        instance: int = 0,
    ) -> npt.NDArray[np.float32]: ...

class PatternView(TextureSource): ...

class InstanceStatistics:
    def __init__(
        self,
        *,
        size: Union[int, Sequence[int]] = 256,
        origin: Optional[Sequence[float]] = None,
        time: float = 0.0,
        **kwargs: int,
    ) -> None: ...
    def merge(self, other: InstanceStatistics) -> None: ...
    @property
    def count(self) -> int: ...
    @property
    def point(self) -> Tuple[int, int]: ...
    @property
    def mean(self) -> npt.NDArray[np.float32]: ...
    @property
    def variance(self) -> npt.NDArray[np.float32]: ...
    @property
    def correlation(self) -> npt.NDArray[np.float32]: ...
    @property
    def correlation_row(self) -> npt.NDArray[np.float32]: ...
    @property
    def probe_correlation(self) -> npt.NDArray[np.float32]: ...

def instance_statistics(
    source: TextureSource,
    *,
    size: Union[int, Sequence[int]] = 256,
    origin: Optional[Sequence[float]] = None,
    time: float = 0.0,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: int,
) -> InstanceStatistics: ...
def instance_report(statistics: InstanceStatistics) -> dict: ...
def instance_chunk(
    source: TextureSource,
    index: int,
    *,
    size: Union[int, Sequence[int]] = 256,
    origin: Optional[Sequence[float]] = None,
    time: float = 0.0,
    **kwargs: int,
) -> InstanceStatistics: ...
def instance_chunk_count(
    *, size: Union[int, Sequence[int]] = 256, origin: Optional[Sequence[float]] = None, time: float = 0.0, **kwargs: int
) -> int: ...

class Shadertoy(TextureSource):
    def __init__(
        self, path: str, *, width: int = 640, height: int = 360, fps: float = 60.0, start_time: float = 0.0
    ) -> None: ...
    def frames(self, count: int, *, instance: int = 0) -> npt.NDArray[np.float32]: ...
    def reset(self, *, instance: int = 0) -> None: ...
    def next(self) -> npt.NDArray[np.float32]: ...
    @property
    def frame(self) -> int: ...
    @property
    def name(self) -> str: ...

_TableTuple = Tuple[str, str, List[Tuple[str, str, str, Union[npt.NDArray[np.float64], List[str]]]]]

def frame_analysis(
    source: TextureSource,
    *,
    analyses: Sequence[str] = ...,
    size: Union[int, Sequence[int]] = 256,
    origin: Optional[Sequence[float]] = None,
    time: Optional[float] = None,
    time_step: Optional[float] = None,
    frames: int = 8,
    instances: int = 64,
    point_x: int = -1,
    point_y: int = -1,
    progress: Optional[Callable[[float, str], None]] = None,
) -> dict: ...
def correlation(
    zoom: ZoomTexture,
    *,
    variants: Sequence[str] = ...,
    layers: Sequence[int] = ...,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: int,
) -> dict: ...
def contrast(zoom: ZoomTexture, **kwargs: int) -> dict: ...
def fractalize(
    images: Union[Mapping[str, Union[npt.ArrayLike, str, "os.PathLike[str]"]], Sequence[Union[str, "os.PathLike[str]"]]],
    *,
    layers: int = 8,
    max_scale: float = 2.0,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: int,
) -> dict: ...
def analyze(
    zoom: ZoomTexture,
    *,
    images: Optional[
        Union[Mapping[str, Union[npt.ArrayLike, str, "os.PathLike[str]"]], Sequence[Union[str, "os.PathLike[str]"]]]
    ] = None,
    layers: Sequence[int] = ...,
    coherence_layers: Sequence[int] = ...,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: int,
) -> dict: ...
def figure11(
    *,
    footprints: Sequence[int] = ...,
    reference_tolerance: float = 0.0005,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: float,
) -> dict: ...
def figures7to9(*, size: int = 384, progress: Optional[Callable[[float, str], None]] = None) -> dict: ...
def marble(
    *,
    scalings: Sequence[str] = ...,
    point: Optional[Tuple[float, float]] = None,
    method: str = "dis",
    seed: int = 1,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: float,
) -> dict: ...
def stimulus(
    *, size: int = 256, tile: int = 32, correlation: float = 0.5, seed: int = 0, mean: float = 0.5, contrast: float = 1.0
) -> npt.NDArray[np.float32]: ...
def stimuli(
    *,
    tiles: Sequence[int] = ...,
    correlations: Sequence[float] = ...,
    seed: int = 0,
    mean: float = 0.5,
    contrast: float = 1.0,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: int,
) -> dict: ...
_frame_analysis_frames: int

def flicker_pairs(
    source: TextureSource,
    first: int,
    count: int,
    *,
    size: Union[int, Sequence[int]] = 256,
    origin: Optional[Sequence[float]] = None,
    time: Optional[float] = None,
    time_step: Optional[float] = None,
    frames: int = 8,
) -> tuple: ...
def flicker_from_pairs(
    source: TextureSource,
    parts: Sequence[tuple],
    *,
    size: Union[int, Sequence[int]] = 256,
    origin: Optional[Sequence[float]] = None,
    time: Optional[float] = None,
    time_step: Optional[float] = None,
    frames: int = 8,
) -> dict: ...
def figure10(*, progress: Optional[Callable[[float, str], None]] = None, **kwargs: float) -> dict: ...
def figure12(
    pattern: Pattern,
    *,
    size: int = 640,
    tilt_deg: float = 70.0,
    aniso: int = 8,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: float,
) -> dict: ...
def figure14(
    pattern: Pattern,
    *,
    footprints: Sequence[int] = ...,
    prefilter: str = "smooth",
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: float,
) -> dict: ...
def estimator_renders(
    *,
    presets: Sequence[str] = ...,
    scales: Sequence[float] = ...,
    plane: bool = True,
    prefilter: str = "smooth",
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: float,
) -> dict: ...
def figure4(
    pattern: Pattern,
    *,
    footprints: Sequence[int] = ...,
    prefilter: str = "smooth",
    reference_tolerance: float = 0.0005,
    **kwargs: float,
) -> dict: ...
def stability(
    pattern: Pattern,
    *,
    filters: Sequence[str] = ...,
    estimators: Sequence[str] = ...,
    aniso: int = 8,
    reference_max_samples: int = 32,
    progress: Optional[Callable[[float, str], None]] = None,
    **kwargs: float,
) -> dict: ...
def stability_from_frames(
    parts: Sequence[tuple],
    pattern: Pattern,
    *,
    filters: Sequence[str] = ...,
    estimators: Sequence[str] = ...,
    aniso: int = 8,
    reference_max_samples: int = 32,
    **kwargs: float,
) -> dict: ...

class StabilitySampler:
    def __init__(
        self,
        pattern: Pattern,
        *,
        filters: Sequence[str] = ...,
        estimators: Sequence[str] = ...,
        aniso: int = 8,
        reference_max_samples: int = 32,
        **kwargs: float,
    ) -> None: ...
    def frames(
        self, first: int, count: int, *, progress: Optional[Callable[[float, str], None]] = None
    ) -> tuple: ...
    @property
    def frame_count(self) -> int: ...

def table1(
    *, count: int = 1000, footprints: Sequence[int] = ..., seed: int = 1, noise_seed: int = 1, max_samples: int = 512
) -> dict: ...
def table1_from_terms(
    terms: Sequence[Sequence[npt.ArrayLike]],
    *,
    count: int = 1000,
    footprints: Sequence[int] = ...,
    seed: int = 1,
    noise_seed: int = 1,
    max_samples: int = 512,
) -> dict: ...

class Table1Sampler:
    estimators: ClassVar[List[str]]
    terms_per_footprint: ClassVar[int]
    def __init__(
        self,
        noise: int,
        *,
        count: int = 1000,
        footprints: Sequence[int] = ...,
        seed: int = 1,
        noise_seed: int = 1,
        max_samples: int = 512,
    ) -> None: ...
    def terms(self, footprint: int, first: int, count: int) -> npt.NDArray[np.float64]: ...

"""The embarrassingly parallel studies on Dask (dask.distributed): each
splits into deterministic chunks keyed by seed and footprint range (Table 1)
or instance range (statistics over instances), which any worker computes,
and merges into exactly the single-process result.

    from dask.distributed import Client
    import functools, stochtex, stochtex.dask

    client = Client("scheduler:8786")          # or Client(LocalCluster(...))
    result = stochtex.dask.table1(client, count=100_000)
    result["data"]                             # == stochtex.studies.table1(count=100_000)["data"]

    program = functools.partial(stochtex.Shadertoy, "data/shadertoy/noise", width=128, height=128)
    stats = stochtex.dask.instance_statistics(client, program, size=128, instances=4096)
    stats.correlation                          # == studies.instance_statistics(program(), ...).correlation

    stochtex.dask.bake(client, "marble", "marble.exr", size=16384, filter="smooth")   # == stochtex bake-image

A chunk's result depends only on its key, so a lost worker's chunks are
recomputed by Dask elsewhere and the merge is unchanged. Every worker needs
stochtex importable (the same build: `pip install --no-build-isolation .`).
"""
from __future__ import annotations

import functools
import os
import pickle
from typing import Any, Callable, Dict, List, Sequence

import cloudpickle

import numpy as np

from . import _stochtex, studies

__all__ = ["bake", "flicker", "instance_statistics", "stability", "table1", "table1_chunks"]


def _in_order(client, futures: List[Any], progress: Any, step: Callable[[int], str]):
    """The futures' results in their order, each released once taken (so the
    cluster drops it), progress(fraction, step(index)) after each where
    given; on an error or an interruption the others are cancelled."""
    try:
        for index, future in enumerate(futures):
            result = future.result()
            future.release()
            if progress is not None:
                progress((index + 1) / len(futures), step(index))
            yield result
    except BaseException:
        client.cancel(futures)
        raise


def _input_error(parameter: str, message: str) -> Exception:
    # As the library raises it: the message and the keyword at fault.
    error = _stochtex.InputError(message)
    error.parameter = parameter
    return error


@functools.lru_cache(maxsize=4)
def _table1_sampler(noise: int, count: int, footprints: tuple, seed: int, noise_seed: int, max_samples: int):
    # Built once per worker process and options (two 512² examples and their
    # pyramids, a few MB); chunks of the same run reuse it.
    return studies.Table1Sampler(
        noise, count=count, footprints=list(footprints), seed=seed, noise_seed=noise_seed, max_samples=max_samples
    )


def _table1_terms(noise: int, footprint: int, first: int, size: int, options: tuple) -> np.ndarray:
    return _table1_sampler(noise, *options).terms(footprint, first, size)


def table1_chunks(count: int, footprints: Sequence[int], chunk: int) -> List[tuple]:
    """The chunks of a Table 1 run, in merge order: (noise, footprint, first, size)."""
    if chunk < 1:
        raise ValueError(f"chunk must be at least 1, got {chunk}")
    return [
        (noise, s, first, min(chunk, count - first))
        for noise in (0, 1)
        for s in footprints
        for first in range(0, count, chunk)
    ]


def table1(
    client,
    *,
    count: int = 1000,
    footprints: Sequence[int] = studies.TABLE1_FOOTPRINTS,
    seed: int = 1,
    noise_seed: int = 1,
    max_samples: int = 512,
    chunk: int = 250,
) -> Dict[str, Any]:
    """stochtex.studies.table1 with its footprints measured in chunks of
    `chunk` on the client's cluster; the result is exactly the single-process
    one (the same per-footprint terms, summed in index order)."""
    footprints = tuple(int(s) for s in footprints)
    options = (count, footprints, seed, noise_seed, max_samples)
    # Refuse bad options here, with the library's message, before any task runs.
    _table1_sampler(0, *options)
    keys = table1_chunks(count, footprints, chunk)
    futures = [
        client.submit(_table1_terms, noise, s, first, size, options, pure=True)
        for noise, s, first, size in keys
    ]
    parts = client.gather(futures)
    terms: List[List[np.ndarray]] = [[], []]
    i = 0
    for noise in (0, 1):
        for _ in footprints:
            n = -(-count // chunk)
            terms[noise].append(np.concatenate(parts[i : i + n]))
            i += n
    return studies.table1_from_terms(
        terms, count=count, footprints=footprints, seed=seed, noise_seed=noise_seed, max_samples=max_samples
    )


@functools.lru_cache(maxsize=2)
def _worker_source(recipe: bytes):
    # A source is made once per worker process and recipe (a ShaderToy
    # program compiles its shaders, a zoom texture draws its lattice); its
    # chunks reuse it. Sources serialise their own calls (a GPU source runs
    # them on its GL thread), so threads of one worker may share it.
    return pickle.loads(recipe)()


def _instance_chunk(recipe: bytes, index: int, options: Dict[str, Any]):
    return studies.instance_chunk(_worker_source(recipe), index, **options)


def _flicker_pairs(recipe: bytes, first: int, count: int, options: Dict[str, Any]):
    return studies.flicker_pairs(_worker_source(recipe), first, count, **options)


def flicker(client, make_source: Callable[[], Any], *, chunk: int = 4, progress: Any = None, **options: Any):
    """stochtex.studies.frame_analysis(make_source(), ["flicker"], **options)
    with its pairs of frames measured in parts of `chunk` pairs on the
    client's cluster (each part renders its own frames: its first again) and
    joined in order: exactly that report. make_source as for
    instance_statistics; this side makes one too (to check the options and
    name the report). A ShaderToy program renders every frame before the
    ones a part asks for (its buffers need them): its parts cost more the
    later they start."""
    if chunk < 1:
        raise _input_error("chunk", f"chunk must be at least 1 pair, got {chunk}")
    source = make_source()
    frames = options.get("frames", _stochtex._frame_analysis_frames)
    # Refuses bad options here (the run's first pair), before any task runs.
    first_part = studies.flicker_pairs(source, 0, min(chunk, frames - 1), **options)
    recipe = cloudpickle.dumps(make_source)
    ranges = [(first, min(chunk, frames - 1 - first)) for first in range(chunk, frames - 1, chunk)]
    futures = [client.submit(_flicker_pairs, recipe, first, count, options, pure=True) for first, count in ranges]
    parts = [first_part, *_in_order(client, futures, progress, lambda i: f"pairs {ranges[i][0]}… of {frames - 1}")]
    return studies.flicker_from_pairs(source, parts, **options)


def instance_statistics(client, make_source: Callable[[], Any], **options: Any):
    """stochtex.studies.instance_statistics(make_source(), **options) with its
    chunks of `chunk` instances computed on the client's cluster and merged
    in index order: exactly the single-process result (an
    InstanceStatistics). make_source is a picklable callable that makes the
    source on a worker (e.g. functools.partial(stochtex.Shadertoy, path,
    width=128, height=128), or a lambda: Dask's cloudpickle takes those);
    each worker calls it once. Memory: the driver holds the running sums and
    the chunks not yet merged; a task, one chunk's sums (4 float64 maps of
    the window and one width² matrix). progress(fraction, step), where
    given, is called on this side as chunks are merged."""
    progress = options.pop("progress", None)
    total = studies.InstanceStatistics(**options)  # refuses bad options here, before any task runs
    recipe = cloudpickle.dumps(make_source)
    count = studies.instance_chunk_count(**options)
    futures = [client.submit(_instance_chunk, recipe, index, options, pure=True) for index in range(count)]
    # Index order: the merge is the single-process fold.
    for part in _in_order(client, futures, progress, lambda i: f"chunk {i + 1} of {count}"):
        total.merge(part)
    return total


@functools.lru_cache(maxsize=2)
def _worker_renderer(recipe: bytes):
    # Built once per worker process and recipe (its pyramids and tables);
    # the bands of one bake reuse it.
    from . import pattern as _pattern

    source, seed, options = pickle.loads(recipe)
    return _stochtex.Renderer(_pattern(source, seed=seed), **options)


def _bake_band(recipe: bytes, view: Dict[str, Any], y0: int, y1: int):
    return _worker_renderer(recipe).render(rows=(y0, y1), threads=1, **view)


def bake(
    client,
    pattern: Any,
    path: str,
    *,
    size: Any = None,
    scale: Any = None,
    offset: Any = None,
    band: int = 256,
    bits: int = 8,
    seed: Any = None,
    progress: Any = None,
    pending: int = 0,
    **renderer_options: Any,
) -> None:
    """A large PNG or EXR of a pattern's zoom view (`stochtex bake-image`),
    its bands of `band` rows rendered on the cluster and written here in
    order as they arrive: the same bytes as bake-image with the same
    options (each band is its band). pattern: a preset name, a file's path
    (readable by the workers), its JSON text or a dict (a Pattern object
    does not travel); renderer_options: Renderer's (filter, aniso, ...).
    Memory: this side holds at most `pending` bands (0: two per worker
    thread), each worker one band and the pattern's runtime data."""
    from . import pattern as _pattern

    if isinstance(pattern, _stochtex.Pattern):
        raise TypeError("bake: pass the pattern as a preset name, path, JSON text or dict (a Pattern does not travel)")
    if isinstance(pattern, (str, os.PathLike)) and os.path.exists(pattern):
        pattern = os.path.abspath(os.fspath(pattern))  # the workers' working folder may differ
    spec = _pattern(pattern, seed=seed)
    view = {k: v for k, v in dict(size=size, scale=scale, offset=offset).items() if v is not None}
    if band < 1 or band > 4096:
        raise _input_error("band", f"band must be in [1, 4096] rows, got {band}")
    # The view and the options are checked here, with the library's
    # messages, before any task runs.
    shape = _stochtex.Renderer(spec, **renderer_options).view(baked=True, **view)
    width, height = shape["width"], shape["height"]
    stream = _stochtex.ImageStream(path, width, height, channels=3, bits=bits)
    recipe = cloudpickle.dumps((pattern, seed, renderer_options))
    rows = _stochtex.band_rows(width, band)  # bake-image's bands: fewer rows for a view over 16384 wide
    bands = [(y0, min(height, y0 + rows)) for y0 in range(0, height, rows)]
    if pending < 1:
        pending = 2 * max(1, sum(w["nthreads"] for w in client.scheduler_info()["workers"].values()))
    futures: List[Any] = []
    submitted = 0
    try:
        for index, (y0, y1) in enumerate(bands):
            while submitted < len(bands) and submitted < index + pending:
                a, b = bands[submitted]
                futures.append(client.submit(_bake_band, recipe, view, a, b, pure=True))
                submitted += 1
            future = futures[index]
            stream.write_rows(future.result())
            future.release()
            futures[index] = None
            if progress is not None:
                progress(y1 / height, f"rows {y0}–{y1} of {height}")
        stream.finish()
    except BaseException:
        client.cancel([f for f in futures if f is not None])
        raise


@functools.lru_cache(maxsize=2)
def _worker_stability(recipe: bytes):
    # The pattern, its filters and the ground truth, built once per worker
    # process and study; the frame ranges of one run reuse them.
    from . import pattern as _pattern

    source, options = pickle.loads(recipe)
    return studies.StabilitySampler(_pattern(source), **studies._lists(options))


def _stability_frames(recipe: bytes, first: int, count: int):
    return _worker_stability(recipe).frames(first, count)


def stability(client, pattern: Any = "marble", *, chunk: int = 4, progress: Any = None, **options: Any):
    """stochtex.studies.stability with its frames measured in ranges of
    `chunk` on the client's cluster (each range renders its first pair's
    previous frame again): exactly the single-process report. pattern: a
    preset name, a path the workers can read, JSON text or a dict. Each
    worker builds the pattern's filters and ground truth once; a task holds
    two frames per filter."""
    from . import pattern as _pattern

    if isinstance(pattern, _stochtex.Pattern):
        raise TypeError("stability: pass the pattern as a preset name, path, JSON text or dict (a Pattern does not travel)")
    if isinstance(pattern, (str, os.PathLike)) and os.path.exists(pattern):
        pattern = os.path.abspath(os.fspath(pattern))
    if chunk < 1:
        raise _input_error("chunk", f"chunk must be at least 1 frame, got {chunk}")
    spec = _pattern(pattern)
    # Refuses bad options here, with the library's message, before any task
    # runs: building the sampler checks them all (it costs the filters' tables).
    frames = studies.StabilitySampler(spec, **studies._lists(options)).frame_count
    recipe = cloudpickle.dumps((pattern, options))
    ranges = [(first, min(chunk, frames - first)) for first in range(0, frames, chunk)]
    futures = [client.submit(_stability_frames, recipe, first, count, pure=True) for first, count in ranges]
    parts = list(_in_order(client, futures, progress, lambda i: f"frames {ranges[i][0]}… of {frames}"))
    return studies.stability_from_frames(parts, spec, **options)

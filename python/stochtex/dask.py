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

A chunk's result depends only on its key, so a lost worker's chunks are
recomputed by Dask elsewhere and the merge is unchanged. Every worker needs
stochtex importable (the same build: `pip install --no-build-isolation .`).
"""
from __future__ import annotations

import functools
import pickle
from typing import Any, Callable, Dict, List, Sequence

import cloudpickle

import numpy as np

from . import studies

__all__ = ["instance_statistics", "table1", "table1_chunks"]


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


def instance_statistics(client, make_source: Callable[[], Any], **options: Any):
    """stochtex.studies.instance_statistics(make_source(), **options) with its
    chunks of `chunk` instances computed on the client's cluster and merged
    in index order: exactly the single-process result (an
    InstanceStatistics). make_source is a picklable callable that makes the
    source on a worker (e.g. functools.partial(stochtex.Shadertoy, path,
    width=128, height=128), or a lambda: Dask's cloudpickle takes those);
    each worker calls it once. Memory: the driver holds the running sums and
    the chunks not yet merged; a task, one chunk's sums (5 float64 maps of
    the window and one width² matrix). progress(fraction, step), where
    given, is called on this side as chunks are merged."""
    progress = options.pop("progress", None)
    total = studies.InstanceStatistics(**options)  # refuses bad options here, before any task runs
    recipe = cloudpickle.dumps(make_source)
    count = studies.instance_chunk_count(**options)
    futures = [client.submit(_instance_chunk, recipe, index, options, pure=True) for index in range(count)]
    try:
        for index, future in enumerate(futures):  # index order: the merge is the single-process fold
            total.merge(future.result())
            future.release()
            if progress is not None:
                progress((index + 1) / count, f"chunk {index + 1} of {count}")
    except BaseException:
        client.cancel(futures)  # a bad source or Ctrl-C: the other chunks are not wanted
        raise
    return total

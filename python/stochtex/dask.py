"""The embarrassingly parallel studies on Dask (dask.distributed): each
splits into deterministic chunks keyed by seed and footprint range, which
any worker computes, and merges into exactly the single-process result.

    from dask.distributed import Client
    import stochtex.dask

    client = Client("scheduler:8786")          # or Client(LocalCluster(...))
    result = stochtex.dask.table1(client, count=100_000)
    result["data"]                             # == stochtex.studies.table1(count=100_000)["data"]

A chunk's result depends only on its key, so a lost worker's chunks are
recomputed by Dask elsewhere and the merge is unchanged. Every worker needs
stochtex importable (the same build: `pip install --no-build-isolation .`).
"""
from __future__ import annotations

import functools
from typing import Any, Dict, List, Sequence

import numpy as np

from . import studies

__all__ = ["table1", "table1_chunks"]


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

"""Dask on local worker processes against one process (issue 35): the wall
time of Table 1's protocol and of the statistics over instances each way,
their ratio, and the overhead a chunk costs (a task that does nothing,
submitted, run and gathered through the scheduler). Prints Markdown rows for
docs/PERFORMANCE.md. Each Dask run is timed warm (a first, smaller run has
built every worker's sampler or source), and its result is checked to be the
single-process one, bit for bit.

    PYTHONPATH=build/python python3 bench/dask_scaling.py
    PYTHONPATH=build/python python3 bench/dask_scaling.py --count 4000 --instances 4096 --workers 2
"""
import argparse
import functools
import os
import platform
import time

import numpy as np
from dask.distributed import Client, LocalCluster

import stochtex
import stochtex.dask


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def timed(f):
    start = time.perf_counter()
    result = f()
    return result, time.perf_counter() - start


def noop(i):
    return i


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--count", type=int, default=2000, help="Table 1: footprints per size")
    parser.add_argument("--chunk", type=int, default=250, help="Table 1: footprints per task")
    parser.add_argument("--instances", type=int, default=2048, help="statistics: instances of the zoom texture")
    parser.add_argument("--size", type=int, default=256, help="statistics: window side")
    parser.add_argument("--instance-chunk", type=int, default=64)
    parser.add_argument("--tasks", type=int, default=400, help="empty tasks for the per-chunk overhead")
    args = parser.parse_args()

    print(f"CPU: {cpu_model()}, {os.cpu_count()} logical cores; {args.workers} Dask worker processes of 1 thread")
    zoom = functools.partial(stochtex.ZoomTexture, layers=8, offsets="hashed")
    stats = dict(size=args.size, instances=args.instances, chunk=args.instance_chunk)
    rows = []

    single_t1, t_single_t1 = timed(lambda: stochtex.studies.table1(count=args.count))
    single_st, t_single_st = timed(lambda: stochtex.studies.instance_statistics(zoom(), **stats))

    with LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None) as cluster, Client(
        cluster
    ) as client:
        # Warm: every worker builds Table 1's samplers and the zoom's lattice once.
        stochtex.dask.table1(client, count=2 * args.workers, chunk=1)
        stochtex.dask.instance_statistics(client, zoom, size=args.size, instances=4 * args.workers, chunk=1)
        spread_t1, t_spread_t1 = timed(lambda: stochtex.dask.table1(client, count=args.count, chunk=args.chunk))
        spread_st, t_spread_st = timed(lambda: stochtex.dask.instance_statistics(client, zoom, **stats))
        client.gather(client.map(noop, range(args.tasks), pure=False))  # warm the path
        _, t_tasks = timed(lambda: client.gather(client.map(noop, range(args.tasks), pure=False)))

    same_t1 = all(
        np.array_equal(v, spread_t1["data"][k], equal_nan=True) if isinstance(v, np.ndarray) else v == spread_t1["data"][k]
        for k, v in single_t1["data"].items()
    )
    same_st = all(
        np.array_equal(getattr(single_st, m), getattr(spread_st, m))
        for m in ("mean", "variance", "correlation", "correlation_row", "probe_correlation")
    )
    chunks_t1 = 2 * len(stochtex.studies.TABLE1_FOOTPRINTS) * -(-args.count // args.chunk)
    chunks_st = -(-args.instances // args.instance_chunk)
    rows.append(("Table 1, %d footprints per size" % args.count, t_single_t1, t_spread_t1, chunks_t1, same_t1))
    rows.append(
        ("statistics, %d instances of %d² zoom" % (args.instances, args.size), t_single_st, t_spread_st, chunks_st, same_st)
    )
    print()
    print("| study | one process | Dask | one process / Dask | chunks | identical |")
    print("|---|---|---|---|---|---|")
    for name, a, b, chunks, same in rows:
        print(f"| {name} | {a:.2f} s | {b:.2f} s | {a / b:.2f} | {chunks} | {'yes' if same else 'NO'} |")
    print()
    print(f"overhead per chunk: {1000 * t_tasks / args.tasks:.2f} ms (an empty task, {args.tasks} of them, "
          f"submitted, run and gathered)")
    per_footprint = t_single_t1 * (os.cpu_count() or 1) / (2 * len(stochtex.studies.TABLE1_FOOTPRINTS) * args.count)
    print(f"Table 1: {1000 * per_footprint:.3f} core-ms per footprint (one process's wall × cores / footprints)")


if __name__ == "__main__":
    main()

"""A ShaderToy program's statistics over instances (thesis §3.3): the mean,
variance and autocorrelation of the random field its instance uniform draws,
plotted with matplotlib; on a Dask cluster with --workers or --scheduler
(the same result, bit for bit). docs/PYTHON.md.

    PYTHONPATH=build/python python3 examples/shadertoy_statistics.py
    PYTHONPATH=build/python python3 examples/shadertoy_statistics.py --instances 4096 --workers 2 --check
"""
import argparse
import functools
import os
import time

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np

import stochtex
import stochtex.dask

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("program", nargs="?", default=os.path.join(HERE, "..", "data", "shadertoy", "value-noise"),
                        help="a ShaderToy program with an instance uniform (docs/SHADERTOY.md)")
    parser.add_argument("--size", type=int, default=96, help="the window's side, centred in the frame")
    parser.add_argument("--instances", type=int, default=256)
    parser.add_argument("--chunk", type=int, default=16, help="instances per chunk (a Dask task)")
    parser.add_argument("--time", type=float, default=0.0, help="seconds into the program")
    parser.add_argument("--workers", type=int, default=0, help="run on a local Dask cluster of this many processes")
    parser.add_argument("--scheduler", help="run on the Dask cluster of this scheduler (host:port)")
    parser.add_argument("--check", action="store_true", help="with Dask: also run in this process and compare")
    parser.add_argument("-o", "--output", default="shadertoy_statistics.png")
    args = parser.parse_args()

    # What makes the source, picklable, so that each Dask worker makes its own.
    make_source = functools.partial(stochtex.Shadertoy, args.program, width=args.size, height=args.size)
    options = dict(size=args.size, time=args.time, instances=args.instances, chunk=args.chunk)
    start = time.perf_counter()
    if args.workers or args.scheduler:
        from dask.distributed import Client, LocalCluster

        cluster = None if args.scheduler else LocalCluster(
            n_workers=args.workers, threads_per_worker=1, dashboard_address=None
        )
        with Client(args.scheduler or cluster) as client:
            stats = stochtex.dask.instance_statistics(client, make_source, **options)
            where = f"{len(client.scheduler_info()['workers'])} Dask workers"
        if cluster is not None:
            cluster.close()
    else:
        stats = stochtex.studies.instance_statistics(make_source(), **options)
        where = "this process"
    print(f"{stats.count} instances of {os.path.basename(os.path.normpath(args.program))} "
          f"in {where}: {time.perf_counter() - start:.1f} s")

    summary = stochtex.studies.instance_report(stats).tables["statistics.csv"]
    for key in summary:
        print(f"  {summary.headers[key]:>22} {float(summary[key][0]):10.4f} {summary.units[key]}")

    first = make_source().frames(1, instance=0)[0, :, :, 0]
    fig, axes = plt.subplots(1, 4, figsize=(16, 4.2), constrained_layout=True)
    panels = [
        (first, "instance 0", "gray", 0, 1),
        (stats.mean, f"mean over {stats.count}", "viridis", 0, 1),
        (stats.variance, "variance", "viridis", 0, None),
        (stats.correlation, f"correlation with {tuple(stats.point)}", "RdBu_r", -1, 1),
    ]
    for ax, (image, title, cmap, lo, hi) in zip(axes, panels):
        shown = ax.imshow(image, cmap=cmap, vmin=lo, vmax=hi, interpolation="nearest")
        ax.set_title(title)
        fig.colorbar(shown, ax=ax, shrink=0.8)
    fig.savefig(args.output, dpi=90)
    print(f"wrote {args.output}")

    if args.check and (args.workers or args.scheduler):
        single = stochtex.studies.instance_statistics(make_source(), **options)
        same = all(
            np.array_equal(getattr(single, name), getattr(stats, name))
            for name in ("mean", "variance", "correlation", "correlation_row", "probe_correlation")
        )
        print("identical to the single-process run" if same else "DIFFERS from the single-process run")
        raise SystemExit(0 if same else 1)


if __name__ == "__main__":
    main()

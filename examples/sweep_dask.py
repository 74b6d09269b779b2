"""A parameter sweep on Dask: the estimators' rendered error (paper Figure
4's protocol) as the noise spectrum's cutoff and the colormap change, one
task per point, plotted with matplotlib (docs/PYTHON.md). Every study is
deterministic, so each point's report is the one this process would make.

    PYTHONPATH=build/python python3 examples/sweep_dask.py
    PYTHONPATH=build/python python3 examples/sweep_dask.py --scheduler scheduler:8786 --cutoffs 2,4,8,16,32,64
"""
import argparse
import copy
import functools
import json
import os
import time

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt
import numpy as np
from dask.distributed import Client, LocalCluster

import stochtex

HERE = os.path.dirname(os.path.abspath(__file__))
COLORMAPS = {
    "painted": None,  # the preset's own: camouflage's painted sectors
    "gaussian": {"type": "gaussian"},
}


def variant(base, cutoff, colormap):
    """The camouflage preset with both noises' low-pass cutoff and the colormap swapped."""
    pattern = copy.deepcopy(base)
    pattern["name"] = f"cutoff {cutoff:g}, {colormap}"
    for axis in ("noise_x", "noise_y"):
        pattern[axis]["components"][0]["cutoff"] = cutoff
    if COLORMAPS[colormap] is not None:
        pattern["colormap"] = COLORMAPS[colormap]
    return pattern


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="address of a running scheduler (default: a local cluster)")
    parser.add_argument("--workers", type=int, default=2, help="local cluster's worker processes")
    parser.add_argument("--cutoffs", default="4,8,16,32", help="low-pass cutoffs of the noises' spectrum")
    parser.add_argument("--footprints", default="2,4,8,16,32", help="footprint sides in texels")
    parser.add_argument("--size", type=int, default=96, help="image side per footprint")
    parser.add_argument("--reference-samples", type=int, default=16)
    parser.add_argument("--check", action="store_true", help="also run the first point here and compare")
    parser.add_argument("-o", "--output", default="sweep_dask.png")
    args = parser.parse_args()

    with open(os.path.join(HERE, "..", "data", "presets", "camouflage.json")) as f:
        base = json.load(f)
    points = [(float(c), m) for c in args.cutoffs.split(",") for m in COLORMAPS]
    footprints = [int(s) for s in args.footprints.split(",")]
    study = functools.partial(stochtex.studies.figure4, footprints=footprints, size=args.size,
                              reference_samples=args.reference_samples)

    cluster = None if args.scheduler else LocalCluster(n_workers=args.workers, threads_per_worker=1,
                                                       dashboard_address=None)
    with Client(args.scheduler or cluster) as client:
        start = time.perf_counter()
        futures = client.map(study, [variant(base, c, m) for c, m in points], pure=True)
        reports = client.gather(futures)  # in the points' order
        print(f"{len(points)} points on {len(client.scheduler_info()['workers'])} workers: "
              f"{time.perf_counter() - start:.1f} s")
    if cluster is not None:
        cluster.close()

    fig, ax = plt.subplots(figsize=(9, 4.5), constrained_layout=True)
    for (cutoff, colormap), report in zip(points, reports):
        table = report.tables["figure4.csv"]
        ax.plot(table["footprint"], table["mean_error_estimators"], "-o" if colormap == "painted" else "--s",
                label=f"cutoff {cutoff:g}, {colormap}")
        print(f"cutoff {cutoff:5g} {colormap:9} mean |Ŝ − S̄| per footprint: "
              + " ".join(f"{e:.4f}" for e in table["mean_error_estimators"]))
    ax.set_xscale("log", base=2)
    ax.set_xlabel("footprint (texels)")
    ax.set_ylabel("mean |Ŝ − S̄| (estimators)")
    ax.set_title("Estimator error across the noise's cutoff and the colormap")
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))  # beside the axes, not over the curves
    fig.savefig(args.output, dpi=90)
    print(f"wrote {args.output}")

    if args.check:
        here = study(variant(base, *points[0]))
        same = all(
            np.array_equal(values, reports[0].tables["figure4.csv"][key], equal_nan=True)
            if isinstance(values, np.ndarray) else values == reports[0].tables["figure4.csv"][key]
            for key, values in here.tables["figure4.csv"].items()
        )
        print("the first point is identical to this process's run" if same else "the first point DIFFERS")
        raise SystemExit(0 if same else 1)


if __name__ == "__main__":
    main()

"""Paper Table 1 on a Dask cluster: the footprints are measured in chunks by
the workers and merged into exactly the single-process table (docs/PYTHON.md).

    PYTHONPATH=build/python python3 examples/table1_dask.py --count 2000
    PYTHONPATH=build/python python3 examples/table1_dask.py --scheduler scheduler:8786 --count 100000
"""
import argparse
import time

from dask.distributed import Client, LocalCluster

import stochtex
import stochtex.dask


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="address of a running scheduler (default: a local cluster)")
    parser.add_argument("--workers", type=int, default=2, help="local cluster's worker processes")
    parser.add_argument("--count", type=int, default=1000, help="footprints per size")
    parser.add_argument("--footprints", default="2,4,8,16,32,64,128")
    parser.add_argument("--chunk", type=int, default=250, help="footprints per task")
    parser.add_argument("--check", action="store_true", help="also run it in this process and compare")
    args = parser.parse_args()
    footprints = [int(s) for s in args.footprints.split(",")]

    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None)
        client = Client(cluster)
    with client:
        start = time.perf_counter()
        result = stochtex.dask.table1(client, count=args.count, footprints=footprints, chunk=args.chunk)
        print(f"Table 1 on {len(client.scheduler_info()['workers'])} workers: {time.perf_counter() - start:.1f} s")
    if cluster is not None:
        cluster.close()
    data = result["data"]
    print(f"{'noise':6} {'size':>5} {'estimator':15} {'mean |σ̂ − σ|/σ':>16}")
    for i in range(data.rows()):
        print(f"{data['noise'][i]:6} {int(data['footprint'][i]):5d} {data['estimator'][i]:15} {data['sigma_rel'][i]:16.4f}")
    if args.check:
        single = stochtex.studies.table1(count=args.count, footprints=footprints)["data"]
        same = all(
            (single[k] == data[k]) if isinstance(data[k], list) else (single[k] == data[k]).all() for k in data
        )
        print("identical to the single-process run" if same else "DIFFERS from the single-process run")
        raise SystemExit(0 if same else 1)


if __name__ == "__main__":
    main()

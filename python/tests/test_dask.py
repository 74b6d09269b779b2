# Table 1 on a Dask cluster of two worker processes: exactly the
# single-process result, also when a worker dies mid-run.
import os
import signal
import threading
import time

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

import stochtex
import stochtex.dask

OPTIONS = dict(count=30, footprints=[4, 16, 64], seed=5, noise_seed=4, max_samples=64)


def assert_same(a, b):
    assert list(a["data"]) == list(b["data"])
    for key, values in a["data"].items():
        if isinstance(values, np.ndarray):
            assert np.array_equal(values, b["data"][key]), key
        else:
            assert values == b["data"][key], key


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


@pytest.fixture(scope="module")
def single():
    return stochtex.studies.table1(**OPTIONS)


def test_table1_on_two_workers_equals_one_process(client, single):
    assert_same(stochtex.dask.table1(client, chunk=7, **OPTIONS), single)


def test_a_worker_lost_mid_run_changes_nothing(client, single):
    pids = client.run(os.getpid)
    assert len(pids) == 2
    victim_address, victim = next(iter(pids.items()))
    killed = {}

    def kill_while_it_works():
        # Mid-run: once the victim has chunks in hand.
        deadline = time.perf_counter() + 30
        while time.perf_counter() < deadline:
            busy = client.processing().get(victim_address, ())
            if busy:
                killed["busy"] = len(busy)
                os.kill(victim, signal.SIGKILL)
                killed["at"] = time.perf_counter()
                return
            time.sleep(0.002)

    killer = threading.Thread(target=kill_while_it_works, daemon=True)
    killer.start()
    start = time.perf_counter()
    result = stochtex.dask.table1(client, chunk=1, **OPTIONS)
    done = time.perf_counter()
    killer.join(10)
    assert "at" in killed, "the victim never had a chunk in hand"
    assert killed["at"] < done, "the worker died after the run had finished"
    print(f"killed {killed['at'] - start:.2f} s into a {done - start:.2f} s run")
    assert_same(result, single)
    # The cluster replaced it.
    client.wait_for_workers(2, timeout=30)


def test_bad_options_raise_before_any_task(client):
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.dask.table1(client, count=0)
    assert caught.value.parameter == "count"


def test_the_stability_study_on_two_workers_equals_one_process(client):
    options = dict(filters=["none", "smooth"], frames=6, size=16, to=8.0, truth_samples=8)
    single = stochtex.studies.stability("marble", **options)
    seen = []
    spread = stochtex.dask.stability(client, "marble", chunk=2, progress=lambda f, step: seen.append(f), **options)
    assert seen == [1 / 3, 2 / 3, 1.0]
    for name, table in single.tables.items():
        for key, values in table.items():
            if isinstance(values, np.ndarray):
                assert np.array_equal(values, spread.tables[name][key], equal_nan=True), (name, key)
            else:
                assert values == spread.tables[name][key], (name, key)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.dask.stability(client, "marble", frames=1)
    assert caught.value.parameter == "frames"

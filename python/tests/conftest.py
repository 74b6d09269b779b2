# The build tree's package (PYTHONPATH=build/python, set by ctest) and the
# CLI beside it (STOCHTEX_CLI), which some tests compare against.
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("STOCHTEX_CLI")
    if not path or not os.path.exists(path):
        pytest.fail("STOCHTEX_CLI must name the stochtex command (ctest sets it)")

    def run(*args, check=True):
        return subprocess.run([path, *args], capture_output=True, text=True, check=check)

    return run


@pytest.fixture(scope="module")
def client():
    """A Dask client of a LocalCluster of two worker processes, one thread each."""
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


@pytest.fixture
def worker_killed_mid_run(client):
    """A context manager: while its body runs, one worker is killed (SIGKILL)
    as soon as it holds a task; on leaving, it asserts the worker died before
    the body was done and waits for the cluster to replace it. It yields a
    dict that gets "at" (perf_counter) and "busy" (the tasks it held)."""
    import contextlib
    import os
    import signal
    import threading
    import time

    @contextlib.contextmanager
    def killing():
        client.wait_for_workers(2, timeout=30)
        victim_address, victim = next(iter(client.run(os.getpid).items()))
        killed = {}

        def kill_while_it_works():
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
        yield killed
        done = time.perf_counter()
        killer.join(10)
        assert "at" in killed, "the victim never had a task in hand"
        assert killed["at"] < done, "the worker died after the run had finished"
        client.wait_for_workers(2, timeout=30)

    return killing

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
def worker_killed_mid_run(client, tmp_path):
    """A context manager: while its body runs, one worker kills itself
    (SIGKILL) the moment it starts executing a task; on leaving, it asserts the
    worker died before the body was done and waits for the cluster to replace
    it. It yields a dict that gets "at" (time.monotonic() of the kill) and
    "busy" (the tasks the worker held).

    The kill is a worker plugin on the victim rather than a thread here polling
    the scheduler for the victim's tasks: polling raced the run (a short run
    could end between two polls) and died with the scheduler connection when a
    loaded machine closed it (CommClosedError in CI), so "the victim never had
    a task in hand" failed a run that had nothing wrong with it."""
    import contextlib
    import os
    import signal
    import time

    from distributed.diagnostics.plugin import WorkerPlugin

    # Defined here, not at module level, so cloudpickle sends the class by
    # value: the workers cannot import this conftest.
    class KillOnFirstTask(WorkerPlugin):
        def __init__(self, victim_pid, record):
            self.victim_pid = victim_pid
            self.record = record

        def setup(self, worker):
            self.worker = worker

        def transition(self, key, start, finish, **kwargs):
            # The replacement worker gets this plugin too; only the victim's
            # process (its pid) dies.
            if finish != "executing" or os.getpid() != self.victim_pid:
                return
            busy = len(self.worker.state.tasks)
            with open(self.record, "w") as f:
                f.write(f"{time.monotonic()!r} {busy}")
            os.kill(os.getpid(), signal.SIGKILL)

    @contextlib.contextmanager
    def killing():
        client.wait_for_workers(2, timeout=30)
        victim = next(iter(client.run(os.getpid).values()))
        record = tmp_path / "killed"
        name = "stochtex-kill-on-first-task"
        client.register_worker_plugin(KillOnFirstTask(victim, str(record)), name=name)
        killed = {}
        try:
            yield killed
            done = time.monotonic()
        finally:
            client.unregister_worker_plugin(name)
        assert record.exists(), "the victim never had a task in hand"
        at, busy = record.read_text().split()
        killed["at"], killed["busy"] = float(at), int(busy)
        assert killed["at"] < done, "the worker died after the run had finished"
        client.wait_for_workers(2, timeout=30)
        assert victim not in client.run(os.getpid).values(), "the victim still runs"

    return killing

# Table 1 on a Dask cluster of two worker processes: exactly the
# single-process result, also when a worker dies mid-run.
import time

import numpy as np
import pytest

pytest.importorskip("distributed")

import stochtex
import stochtex.dask
from report_util import assert_same_report

OPTIONS = dict(count=30, footprints=[4, 16, 64], seed=5, noise_seed=4, max_samples=64)


def assert_same(a, b):
    assert list(a["data"]) == list(b["data"])
    for key, values in a["data"].items():
        if isinstance(values, np.ndarray):
            assert np.array_equal(values, b["data"][key]), key
        else:
            assert values == b["data"][key], key


@pytest.fixture(scope="module")
def single():
    return stochtex.studies.table1(**OPTIONS)


def test_table1_on_two_workers_equals_one_process(client, single):
    assert_same(stochtex.dask.table1(client, chunk=7, **OPTIONS), single)


def test_a_worker_lost_mid_run_changes_nothing(client, single, worker_killed_mid_run):
    start = time.monotonic()
    with worker_killed_mid_run() as killed:
        result = stochtex.dask.table1(client, chunk=1, **OPTIONS)
    print(f"killed {killed['at'] - start:.2f} s into the run, holding {killed['busy']} chunk(s)")
    assert_same(result, single)


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
    assert_same_report(spread, single)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.dask.stability(client, "marble", frames=1)
    assert caught.value.parameter == "frames"


def test_the_flicker_on_two_workers_equals_one_process(client):
    import functools
    import os

    value_noise = os.path.join(os.environ.get("STOCHTEX_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", "..")),
                               "data", "shadertoy", "value-noise")
    for make, options in (
        (functools.partial(stochtex.ZoomTexture, layers=4, offsets="hashed", base_size=64), dict(size=48, frames=7)),
        (functools.partial(stochtex.Shadertoy, value_noise, width=48, height=48), dict(size=48, frames=6, time_step=0.25)),
    ):
        single = stochtex.studies.frame_analysis(make(), ["flicker"], **options)
        spread = stochtex.dask.flicker(client, make, chunk=2, **options)
        assert_same_report(spread, single)

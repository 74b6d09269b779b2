# Statistics over instances of a source (the zoom texture, a ShaderToy
# program): the chunks merged in order are the result, they pickle, they
# equal the CLI's statistics, and a Dask cluster (a worker killed mid-run
# included) gives exactly the single-process result.
import csv
import functools
import os
import pickle

import numpy as np
import pytest

import stochtex
import stochtex.dask

SOURCE_DIR = os.environ.get("STOCHTEX_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
VALUE_NOISE = os.path.join(SOURCE_DIR, "data", "shadertoy", "value-noise")
MAPS = ("mean", "variance", "correlation", "correlation_row", "probe_correlation")
ZOOM = dict(layers=4, offsets="hashed", base_size=64, seed=3)
OPTIONS = dict(size=(40, 32), instances=45, chunk=8, point_x=11, point_y=7)


def assert_same(a, b):
    assert a.count == b.count and tuple(a.point) == tuple(b.point)
    for name in MAPS:
        assert np.array_equal(getattr(a, name), getattr(b, name)), name


def zoom():
    return stochtex.ZoomTexture(**ZOOM)


def test_the_chunks_merged_in_order_are_the_result():
    source = zoom()
    whole = stochtex.studies.instance_statistics(source, **OPTIONS)
    assert whole.count == 45 and tuple(whole.point) == (11, 7)
    assert stochtex.studies.instance_chunk_count(**OPTIONS) == 6
    merged = stochtex.InstanceStatistics(**OPTIONS)
    for index in range(6):
        merged.merge(pickle.loads(pickle.dumps(stochtex.studies.instance_chunk(source, index, **OPTIONS))))
    assert_same(merged, whole)
    assert whole.mean.shape == (32, 40) and whole.probe_correlation.shape == (40, 40)
    assert whole.correlation[7, 11] == pytest.approx(1.0, abs=1e-6)  # the point with itself
    # White noise in [0, 1) through the layers: mean ½ within 5 standard errors.
    assert abs(float(whole.mean.mean()) - 0.5) < 5 * (1 / 12 / 45) ** 0.5


def test_the_chunk_is_part_of_the_definition_and_only_rounds():
    source = zoom()
    a = stochtex.studies.instance_statistics(source, **OPTIONS)
    b = stochtex.studies.instance_statistics(source, **{**OPTIONS, "chunk": 45})
    for name in MAPS:
        assert np.max(np.abs(getattr(a, name) - getattr(b, name))) < 1e-5, name


def test_the_zoom_texture_s_window_is_its_render():
    frame = zoom().render(size=(40, 32), instance=3)
    assert frame.shape == (32, 40) and 0.0 <= frame.min() and frame.max() < 1.0
    one = stochtex.studies.instance_statistics(zoom(), size=(40, 32), instances=2, chunk=1)
    first, second = zoom().render(size=(40, 32), instance=0), zoom().render(size=(40, 32), instance=1)
    assert np.allclose(one.mean, (first + second) / 2, atol=1e-6)


def test_progress_is_called_and_can_stop_the_run():
    seen = []
    stochtex.studies.instance_statistics(zoom(), progress=lambda f, step: seen.append(f), **OPTIONS)
    assert len(seen) == 6 and seen == sorted(seen) and 0 <= seen[0] and seen[-1] < 1

    def stop(fraction, step):
        if fraction > 0.3:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        stochtex.studies.instance_statistics(zoom(), progress=stop, **OPTIONS)


@pytest.mark.parametrize(
    "options, parameter",
    [
        (dict(instances=1), "instances"),
        (dict(chunk=0), "chunk"),
        (dict(point_x=40), "point"),
        (dict(size=2), "size"),
        (dict(probe_row=32), "probe_row"),
        (dict(colour=1), "colour"),
    ],
)
def test_bad_options_raise_naming_them(options, parameter):
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.instance_statistics(zoom(), **{**OPTIONS, **options})
    assert caught.value.parameter == parameter


def test_a_program_s_statistics_equal_the_cli_s(tmp_path, cli):
    program = stochtex.Shadertoy(VALUE_NOISE, width=64, height=48)
    stats = stochtex.studies.instance_statistics(program, size=(64, 48), instances=40)
    report = stochtex.studies.instance_report(stats)
    ours = report.tables["statistics.csv"]
    cli("shadertoy", VALUE_NOISE, "--size", "64,48", "--analyse", "statistics", "--instances", "40", "-o",
        str(tmp_path / "out"))
    with open(tmp_path / "out" / "statistics.csv") as f:
        theirs = list(csv.DictReader(f))[0]
    assert list(theirs) == list(ours)
    for key in ours:  # the CSV holds 6 significant digits
        assert float(theirs[key]) == pytest.approx(float(ours[key][0]), rel=1e-5, abs=1e-9), key
    assert [f.file for f in report.figures] == [
        "statistics_mean.png", "statistics_variance.png", "statistics_correlation.png"]
    # The field is stationary: the correlation bump is about a cell (12 px) wide.
    assert 40 < float(ours["area"][0]) < 400


def test_a_program_without_an_instance_uniform_is_refused():
    swirl = stochtex.Shadertoy(os.path.join(SOURCE_DIR, "data", "shadertoy", "swirl"), width=64, height=48)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.instance_statistics(swirl, size=(64, 48), instances=4)
    assert caught.value.parameter == "instances"


def test_on_two_workers_equals_one_process(client):
    single = stochtex.studies.instance_statistics(zoom(), **OPTIONS)
    assert_same(stochtex.dask.instance_statistics(client, functools.partial(stochtex.ZoomTexture, **ZOOM), **OPTIONS),
                single)
    make_program = functools.partial(stochtex.Shadertoy, VALUE_NOISE, width=48, height=48)
    program_options = dict(size=48, instances=24, chunk=4, time=1.5)
    assert_same(stochtex.dask.instance_statistics(client, make_program, **program_options),
                stochtex.studies.instance_statistics(make_program(), **program_options))


def test_a_worker_lost_mid_run_changes_nothing(client, worker_killed_mid_run):
    options = {**OPTIONS, "size": 96, "instances": 160, "chunk": 2, "point_x": -1, "point_y": -1}
    single = stochtex.studies.instance_statistics(zoom(), **options)
    with worker_killed_mid_run():
        result = stochtex.dask.instance_statistics(client, functools.partial(stochtex.ZoomTexture, **ZOOM), **options)
    assert_same(result, single)


def test_bad_options_raise_before_any_task(client):
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.dask.instance_statistics(client, zoom, instances=0)
    assert caught.value.parameter == "instances"

# Footprint statistics and the Table 1 study from Python: the library's
# values (the CLI's table1.csv), the chunked terms merge to the same table,
# and the GIL is released while the C++ works.
import csv
import threading
import time

import numpy as np
import pytest

import stochtex

TABLE1 = dict(count=24, footprints=[4, 32], seed=3, noise_seed=2)


@pytest.fixture(scope="module")
def table1():
    return stochtex.studies.table1(**TABLE1)


def test_table1_equals_the_cli_csv(tmp_path, cli, table1):
    cli("reproduce", "table1", "--count", "24", "--footprints", "4,32", "--footprint-seed", "3", "--seed", "2",
        "-o", str(tmp_path))
    with open(tmp_path / "table1.csv") as f:
        rows = list(csv.DictReader(f))
    data = table1["data"]
    assert data.rows() == len(rows) == 2 * 2 * 6  # noises × footprints × (five estimators, global)
    assert data["noise"] == [r["noise"] for r in rows]
    assert data["estimator"] == [r["estimator"] for r in rows]
    for key in ("footprint", "mu_abs", "mu_rel", "sigma_abs", "sigma_rel", "mean_mu", "mean_sigma", "values"):
        # The CSV holds 6 significant digits.
        np.testing.assert_allclose(data[key], [float(r[key]) for r in rows], rtol=5e-6, atol=0)
    assert table1["tables"][0].title.startswith("Estimator: paper")
    assert all(f.image.ndim == 3 and f.image.shape[0] > 100 for f in table1["figures"])


def test_table1_from_chunked_terms_is_exactly_table1(table1):
    options = dict(TABLE1)
    terms = [[], []]
    for noise in (0, 1):
        sampler = stochtex.studies.Table1Sampler(noise, **options)
        for s in options["footprints"]:
            # Uneven chunks, measured out of order: only the merge order matters.
            chunks = {first: sampler.terms(s, first, size) for first, size in [(16, 8), (0, 5), (5, 11)]}
            terms[noise].append(np.concatenate([chunks[0], chunks[5], chunks[16]]))
    assert terms[0][0].shape == (24, stochtex.studies.Table1Sampler.terms_per_footprint)
    merged = stochtex.studies.table1_from_terms(terms, **options)
    for key, values in table1["data"].items():
        if isinstance(values, np.ndarray):
            assert np.array_equal(merged["data"][key], values), key
        else:
            assert merged["data"][key] == values, key


def test_estimates_are_close_to_the_exact_statistics():
    stats = stochtex.FootprintStatistics(stochtex.pattern("camouflage"))
    rng = np.random.default_rng(7)
    n = 400
    uv = rng.uniform(0, 8, size=(n, 2))
    side = 8.0 / stats.example_size  # 8-texel square footprints
    jacobian = np.tile(np.array([[side, 0.0], [0.0, side]]), (n, 1, 1))
    mean, cov = stats.estimate(uv, jacobian)
    exact_mean, exact_cov = stats.exact(uv, jacobian)
    assert mean.shape == (n, 2) and cov.shape == (n, 2, 2) and mean.dtype == np.float32
    assert np.array_equal(cov[:, 0, 1], cov[:, 1, 0])
    spread = np.sqrt(np.mean(exact_cov[:, 0, 0] + exact_mean[:, 0] ** 2))  # the noise's own scale
    # The paper's estimator at 8 texels: mean |μ̂ − μ| a small part of the noise's scale.
    assert np.mean(np.abs(mean - exact_mean)) < 0.25 * spread
    assert np.all(cov[:, 0, 0] >= 0) and np.all(exact_cov[:, 0, 0] >= 0)


def test_footprints_out_of_the_grids_reach_raise():
    stats = stochtex.FootprintStatistics(stochtex.pattern("camouflage"))
    good = np.full((3, 2, 2), [[0.01, 0.0], [0.0, 0.01]])
    for uv in (np.array([[0.5, 0.5], [np.nan, 0.1], [0.2, 0.2]]), np.array([[0.5, 0.5], [-1e19, 0.1], [0.2, 0.2]])):
        for call in (stats.estimate, stats.exact):
            with pytest.raises(stochtex.InputError, match="at footprint 1") as caught:
                call(uv, good)
            assert caught.value.parameter == "uv"
    bad = good.copy()
    bad[2, 1, 1] = np.inf
    with pytest.raises(stochtex.InputError) as caught:
        stats.exact(np.zeros((3, 2)), bad)
    assert caught.value.parameter == "jacobian"


def test_the_gil_is_released_while_rendering():
    renderer = stochtex.Renderer(stochtex.pattern("camouflage"), filter="smooth")
    span = {}

    def work():
        span["start"] = time.perf_counter()
        renderer.render(size=1536, scale=4.7, threads=1)  # ≥ 0.3 s on the 2-core VM (512² took 40 ms)
        span["end"] = time.perf_counter()

    ticks = []
    thread = threading.Thread(target=work)
    thread.start()
    while thread.is_alive():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    thread.join()
    assert span["end"] - span["start"] > 0.05, "the render was too short to tell"
    inside = [t for t in ticks if span["start"] + 0.01 < t < span["end"] - 0.01]
    # Holding the GIL, the render would have stopped this thread throughout.
    assert len(inside) >= 5, f"{len(inside)} ticks of this thread during a {span['end'] - span['start']:.2f} s render"


def test_figure4_equals_the_cli_csv(tmp_path, cli):
    cli("reproduce", "figure4", "--size", "32", "--reference-samples", "8", "-o", str(tmp_path))
    with open(tmp_path / "figure4.csv") as f:
        rows = list(csv.DictReader(f))
    report = stochtex.studies.figure4("camouflage", size=32, reference_samples=8)
    table = report.tables["figure4.csv"]
    assert table.rows() == len(rows) == 8
    for key in table:
        if isinstance(table[key], np.ndarray):
            expected = [float(r[key]) if r[key] else np.nan for r in rows]
            np.testing.assert_allclose(table[key], expected, rtol=5e-6, atol=0, err_msg=key)
    assert report.figures and all(f.image.ndim == 3 for f in report.figures)
    assert report.title


def test_a_study_s_numbers_are_its_option_table_s():
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.figure4("camouflage", size=8)
    assert caught.value.parameter == "size"
    with pytest.raises(stochtex.InputError, match="its numbers: size, reference_samples") as caught:
        stochtex.studies.figure4("camouflage", sise=32)
    assert caught.value.parameter == "sise"

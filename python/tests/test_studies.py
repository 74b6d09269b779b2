# The studies as report values equal the CLI's CSV files: the paper's
# figures (their numbers as keywords from the studies' option tables) and
# the frame studies of any texture source (a ShaderToy program, a pattern's
# view, the zoom texture).
import csv
import os

import numpy as np
import pytest

import stochtex
from report_util import assert_same_report

SOURCE_DIR = os.environ.get("STOCHTEX_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
VALUE_NOISE = os.path.join(SOURCE_DIR, "data", "shadertoy", "value-noise")


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def assert_table_is_csv(table, path, rtol=1e-5):
    """Every column of a report's table equals the CSV the CLI wrote (6
    significant digits: rtol 1e-5); text columns exactly."""
    rows = read_csv(path)
    assert table.rows() == len(rows), path
    assert list(table) == list(rows[0]), path
    for key, values in table.items():
        if isinstance(values, np.ndarray):
            expected = [float(r[key]) if r[key] not in ("", "—") else np.nan for r in rows]
            np.testing.assert_allclose(values, expected, rtol=rtol, atol=1e-12, err_msg=f"{path}: {key}")
        else:
            assert values == [r[key] for r in rows], f"{path}: {key}"


def assert_report_is_cli_s(report, folder):
    written = sorted(f for f in os.listdir(folder) if f.endswith(".csv"))
    assert sorted(report.tables) == written
    for name, table in report.tables.items():
        assert_table_is_csv(table, os.path.join(folder, name))
    assert all(f.image.ndim == 3 and f.image.size for f in report.figures)


@pytest.mark.parametrize(
    "study, flags, call",
    [
        ("figure10", ["--size", "64", "--comparison-size", "32"], lambda: stochtex.studies.figure10(size=64, comparison_size=32)),
        ("figure12", ["--size", "64", "--reference-samples", "4"],
         lambda: stochtex.studies.figure12(size=64, reference_samples=4)),
        ("figure14", ["--size", "16", "--reference-samples", "4", "--footprints", "4,16"],
         lambda: stochtex.studies.figure14(size=16, reference_samples=4, footprints=[4, 16])),
        ("estimators", ["--presets", "marble,figure14", "--scales", "8", "--size", "16", "--reference-samples", "4"],
         lambda: stochtex.studies.estimator_renders(presets=["marble", "figure14"], scales=[8], size=16,
                                                     reference_samples=4)),
    ],
)
def test_paper_studies_equal_the_cli_s(tmp_path, cli, study, flags, call):
    cli("reproduce", study, *flags, "-o", str(tmp_path))
    assert_report_is_cli_s(call(), tmp_path)


def test_frame_studies_of_a_program_equal_shadertoy_analyse(tmp_path, cli):
    analyses = ["spectrum", "flow", "coherence", "flicker", "statistics"]
    cli("shadertoy", VALUE_NOISE, "--size", "64,48", "--analyse", ",".join(analyses), "--frames", "4", "--instances",
        "16", "-o", str(tmp_path))
    program = stochtex.Shadertoy(VALUE_NOISE, width=64, height=48)
    seen = []
    report = stochtex.studies.frame_analysis(program, analyses, size=(64, 48), frames=4, instances=16,
                                             progress=lambda f, step: seen.append(f))
    assert_report_is_cli_s(report, tmp_path)
    assert [s.heading for s in report.sections][0].startswith("Power spectrum")
    assert seen and seen == sorted(seen)
    assert "value-noise" in report.title
    assert report.figures


def test_frame_studies_of_a_pattern_and_of_the_zoom_texture_equal_their_commands(tmp_path, cli):
    cli("spectrum", "-o", str(tmp_path / "spectrum"), "--size", "64", "pattern", "--preset", "camouflage")
    view = stochtex.Renderer(stochtex.pattern("camouflage")).source()
    assert_report_is_cli_s(stochtex.studies.frame_analysis(view, ["spectrum"], size=64), tmp_path / "spectrum")
    # frame_analysis' flow is DIS (the flow command's default is Farnebäck).
    cli("flow", "-o", str(tmp_path / "flow"), "--size", "64", "--frames", "4", "--method", "dis", "zoom", "--layers", "4")
    zoom = stochtex.ZoomTexture(layers=4)
    report = stochtex.studies.frame_analysis(zoom, ["flow"], size=64, frames=4)
    assert_table_is_csv(report.tables["flow.csv"], tmp_path / "flow" / "flow.csv")


def test_a_pattern_s_statistics_over_instances_move_its_window():
    view = stochtex.Renderer(stochtex.pattern("camouflage")).source(scale=2.0)
    stats = stochtex.studies.instance_statistics(view, size=48, instances=24, chunk=8)
    # Each instance is another draw of the tile offsets: the per-pixel
    # variance over instances is that of the pattern, not zero.
    assert float(stats.variance.mean()) > 1e-3
    assert stats.correlation[24, 24] == pytest.approx(1.0, abs=1e-6)


def test_bad_study_options_raise_naming_them():
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.figure10(size=8)
    assert caught.value.parameter == "size"
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.frame_analysis(stochtex.ZoomTexture(), ["spectra"])
    assert caught.value.parameter == "analyses"
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.figure14(colour=3)
    assert caught.value.parameter == "colour"


STABILITY = dict(filters=["none", "paper"], frames=5, size=16, to=8.0, truth_samples=8)


def test_the_stability_study_equals_the_cli_s(tmp_path, cli):
    cli("stability", "--preset", "marble", "--filters", "none,paper", "--frames", "5", "--size", "16", "--to", "8",
        "--truth-samples", "8", "-o", str(tmp_path))
    report = stochtex.studies.stability("marble", **STABILITY)
    assert sorted(report.tables) == ["stability-frames.csv", "stability.csv"]
    for name, table in report.tables.items():
        assert_table_is_csv(table, tmp_path / name)


def test_the_stability_study_in_frame_ranges_is_the_study():
    whole = stochtex.studies.stability("marble", **STABILITY)
    sampler = stochtex.studies.StabilitySampler(stochtex.pattern("marble"), **STABILITY)
    assert sampler.frame_count == 5
    parts = [sampler.frames(0, 2), sampler.frames(2, 1), sampler.frames(3, 2)]
    joined = stochtex.studies.stability_from_frames(parts, "marble", **STABILITY)
    assert_same_report(joined, whole)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.stability_from_frames(parts[:2], "marble", **STABILITY)
    assert caught.value.parameter == "parts"
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.stability("marble", **{**STABILITY, "from": 0.0})
    assert caught.value.parameter == "from_"  # a Python keyword: PEP 8's trailing underscore
    assert stochtex.studies.stability("marble", **{**STABILITY, "from_": 2.0}).tables["stability.csv"].rows() == 2


def test_a_table_as_a_pandas_frame():
    pandas = pytest.importorskip("pandas")
    table = stochtex.studies.figure10(size=64, comparison_size=32).tables["figure10.csv"]
    frame = table.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(table) and len(frame) == table.rows()
    for key, values in table.items():
        if isinstance(values, np.ndarray):
            assert np.array_equal(frame[key].to_numpy(), values, equal_nan=True), key
        else:
            assert list(frame[key]) == values, key
    assert frame.attrs["units"] == table.units and frame.attrs["title"] == table.title


def test_the_correlation_study_equals_the_cli_s(tmp_path, cli):
    cli("correlation", "-o", str(tmp_path), "--variant", "sliding,random", "--layers-list", "4,2", "--instances", "32",
        "--size", "16", "--base-size", "64")
    report = stochtex.studies.correlation(stochtex.ZoomTexture(base_size=64), variants=["sliding", "random"],
                                          layers=[4, 2], instances=32, plot_size=16)
    assert_report_is_cli_s(report, tmp_path)
    assert report.tables["correlation.csv"]["variant"] == ["sliding", "sliding", "random", "random"]


def test_the_stimulus_set_equals_the_cli_s(tmp_path, cli):
    cli("stimuli", "-o", str(tmp_path), "--size", "32", "--tiles", "8,16", "--correlations", "0,1", "--repeats", "2",
        "--seed", "3")
    report = stochtex.studies.stimuli(size=32, tiles=[8, 16], correlations=[0, 1], repeats=2, seed=3)
    assert_report_is_cli_s(report, tmp_path)
    with open(tmp_path / "experiment.html") as f:
        assert report.files["experiment.html"] in f.read()  # the page's body, which the writer wraps
    # Each figure is the stimulus the CLI wrote (8-bit display codes).
    for figure in report.figures[:3]:
        written = stochtex.read_image(str(tmp_path / figure.file))
        assert np.abs(written[..., 0] - figure.image[..., 0]).max() <= 0.5 / 255 + 1e-6, figure.file
    one = stochtex.studies.stimulus(size=32, tile=8, correlation=1.0, seed=5)
    assert one.shape == (32, 32) and np.array_equal(one[:8, :8], one[8:16, 16:24])  # correlation 1: tiles repeat


def test_reports_show_themselves_in_a_notebook(tmp_path):
    report = stochtex.studies.figure10(size=64, comparison_size=32)
    page = report._repr_html_()
    assert page.count("<table>") == len(report.tables) and page.count("data:image/png;base64,") >= 1
    assert report.title in page
    figure = report.figures[0]
    png = figure._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    (tmp_path / "f.png").write_bytes(png)
    shown = stochtex.read_image(str(tmp_path / "f.png"))
    assert shown.shape == figure.image.shape
    assert np.abs(shown - np.clip(figure.image, 0, 1)).max() <= 0.5 / 255 + 1e-6  # display codes, as written
    # Linear light by default: the bytes write_image writes.
    pixels = np.linspace(0, 1, 48, dtype=np.float32).reshape(4, 4, 3)
    stochtex.write_image(str(tmp_path / "w.png"), pixels)
    assert stochtex.encode_image(pixels) == (tmp_path / "w.png").read_bytes()
    with pytest.raises(stochtex.InputError):
        stochtex.encode_image(pixels, format="gif")


def test_a_report_pickles_as_it_is():
    import pickle

    report = stochtex.studies.figure10(size=64, comparison_size=32)
    back = pickle.loads(pickle.dumps(report))
    assert_same_report(back, report)
    for name, table in report.tables.items():
        assert back.tables[name].units == table.units and back.tables[name].title == table.title


def test_the_flicker_in_parts_is_the_flicker_of_the_run():
    program = stochtex.Shadertoy(VALUE_NOISE, width=48, height=48)
    options = dict(size=48, frames=6, time_step=0.25)
    whole = stochtex.studies.frame_analysis(program, ["flicker"], **options)
    parts = [stochtex.studies.flicker_pairs(program, first, count, **options) for first, count in ((0, 2), (2, 3))]
    assert_same_report(stochtex.studies.flicker_from_pairs(program, parts, **options), whole)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.flicker_pairs(program, 4, 2, **options)
    assert caught.value.parameter == "count"
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.flicker_from_pairs(program, parts[1:], **options)
    assert caught.value.parameter == "parts"


def test_figure11_figures7to9_and_contrast_equal_the_cli_s(tmp_path, cli):
    cli("reproduce", "figure11", "--size", "32", "--reference-samples", "8", "-o", str(tmp_path / "f11"))
    assert_report_is_cli_s(stochtex.studies.figure11(size=32, reference_samples=8), tmp_path / "f11")
    cli("contrast", "-o", str(tmp_path / "contrast"), "--size", "64", "--time", "0.06")
    zoom = stochtex.ZoomTexture(layers=16, time=0.06)
    assert_report_is_cli_s(stochtex.studies.contrast(zoom, size=64), tmp_path / "contrast")
    cli("reproduce", "figures7-9", "--size", "64", "-o", str(tmp_path / "f79"))
    sheets = stochtex.studies.figures7to9(size=64)
    assert [f.file for f in sheets.figures][:3] == ["figure7.png", "figure8.png", "figure9.png"]
    for figure in sheets.figures[:3]:
        written = stochtex.read_image(str(tmp_path / "f79" / figure.file))
        assert written.shape == figure.image.shape
        assert np.abs(written - np.clip(figure.image, 0, 1)).max() <= 0.5 / 255 + 1e-6, figure.file


def test_the_marble_study_equals_the_cli_s(tmp_path, cli):
    cli("marble", "-o", str(tmp_path), "--size", "64", "--correlation-size", "32", "--instances", "16",
        "--spectrum-instances", "1", "--frames", "3", "--step", "16", "--level", "4")
    report = stochtex.studies.marble(size=64, correlation_size=32, instances=16, spectrum_instances=1, frames=3,
                                     flow_step=16, level=4.0)
    assert sorted(report.tables) == ["correlation.csv", "sliding.csv", "spectra.csv"]
    for name, table in report.tables.items():
        assert_table_is_csv(table, tmp_path / name)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.marble(level=99.0)
    assert caught.value.parameter == "level"


def test_fractalize_equals_the_cli_s_from_paths_or_arrays(tmp_path, cli):
    stone, weld = (os.path.join(SOURCE_DIR, "data", "textures", n + ".png") for n in ("stone", "weld"))
    cli("fractalize", stone, weld, "-o", str(tmp_path), "--size", "32", "--instances", "16", "--layers", "6")
    report = stochtex.studies.fractalize([stone, weld], size=32, instances=16, layers=6)
    assert_report_is_cli_s(report, tmp_path)
    assert report.tables["fractalize.csv"]["image"] == [stone, weld]
    # The same images as arrays (as read_image gives them) under the same names: the same report.
    arrays = stochtex.studies.fractalize({stone: stochtex.read_image(stone), weld: weld}, size=32, instances=16,
                                         layers=6)
    assert_same_report(arrays, report)
    for bad, parameter in (({"x": np.zeros((4, 4, 5), np.float32)}, "images"), ("stone.png", "images")):
        with pytest.raises(stochtex.InputError) as caught:
            stochtex.studies.fractalize(bad) if isinstance(bad, dict) else stochtex._stochtex.fractalize(bad)
        assert caught.value.parameter == parameter
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.fractalize([stone], instances=1)
    assert str(caught.value) == "instances must be in [2, 100000], got 1"


def test_analyze_equals_the_cli_s_page(tmp_path, cli):
    flags = ["--instances", "8", "--plot-size", "16", "--layers-list", "4", "--size", "64", "--frame-size", "32",
             "--coherence-layers", "3,8"]
    cli("analyze", "-o", str(tmp_path), *flags)
    report = stochtex.studies.analyze(instances=8, plot_size=16, layers=[4], size=64, frame_size=32,
                                      coherence_layers=[3, 8])
    written = sorted(os.path.relpath(os.path.join(d, f), tmp_path) for d, _, files in os.walk(tmp_path)
                     for f in files if f.endswith(".csv"))
    assert sorted(report.tables) == written
    for name, table in report.tables.items():
        assert_table_is_csv(table, tmp_path / name)
    figures = [f.file for f in report.figures]  # by their paths in the CLI's folder, as the tables
    assert "correlation/figure2_10.png" in figures and any(f.startswith("marble/") for f in figures)
    assert all(os.path.exists(tmp_path / f) for f in figures)
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.studies.analyze(frame_sizes=32)
    assert caught.value.parameter == "frame_sizes"
    assert "frame_size" in str(caught.value) and "plot_size" in str(caught.value)

# Bad input raises stochtex.InputError with the library's message, the one
# the CLI prints after its flag; its parameter is the keyword at fault.
import json

import numpy as np
import pytest

import stochtex


def cli_message(cli, *args):
    done = cli(*args, check=False)
    assert done.returncode == 2, done.stderr
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("stochtex: error: ")
    return line[len("stochtex: error: ") :]


def test_a_bad_file_names_the_file_and_pointer_as_the_cli_does(tmp_path, cli):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"size": -3, "noise_x": {"type": "spectrum"}, "colormap": {"type": "gaussian"}}))
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.pattern(str(path))
    assert str(caught.value) == cli_message(cli, "render", str(path), "-o", str(tmp_path / "x.png"))
    assert "/size" in str(caught.value)
    assert caught.value.parameter is None
    assert not (tmp_path / "x.png").exists()


def test_a_parameter_out_of_range_names_the_keyword(tmp_path, cli):
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.Renderer(stochtex.pattern("camouflage"), filter="smooth", aniso=0)
    assert caught.value.parameter == "aniso"
    assert isinstance(caught.value, ValueError)
    # The CLI prints the same message after its flag.
    assert cli_message(cli, "render", "--preset", "camouflage", "--filter", "smooth", "--aniso", "0", "-o",
                       str(tmp_path / "x.png")) == "--aniso: " + str(caught.value)


@pytest.mark.parametrize(
    "call, parameter",
    [
        (lambda: stochtex.render("camouflage", scale=0), "scale"),
        (lambda: stochtex.render("camouflage", size=(0, 8)), "size"),
        (lambda: stochtex.render("camouflage", filter="blurry"), "filter"),
        (lambda: stochtex.render("camouflage", estimator="median"), "estimator"),
        (lambda: stochtex.render("camouflage", camera="fisheye"), "camera"),
        (lambda: stochtex.render("camouflage", camera="plane", tilt_deg=95), "tilt_deg"),
        (lambda: stochtex.Pattern.preset("no-such-preset"), None),
        (lambda: stochtex.studies.table1(count=0), "count"),
        (lambda: stochtex.Renderer(stochtex.pattern("camouflage")).render(size=8, threads=-1), "threads"),
        (lambda: stochtex.studies.Table1Sampler(0, count=10, footprints=[4]).terms(4, 5, 6), "count"),
        (lambda: stochtex.studies.Table1Sampler(0, count=10, footprints=[4]).terms(4, 11, 0), "first"),
        (lambda: stochtex.studies.table1_from_terms([[np.zeros((22, 10))], [np.zeros((22, 10))]], count=10,
                                                    footprints=[4]), "terms"),
        (lambda: stochtex.studies.table1(footprints=[4, 4096]), "footprints"),
        (lambda: stochtex.FootprintStatistics(stochtex.pattern("camouflage"), field=3), "field"),
        (lambda: stochtex.write_image("/nonexistent-folder/x.png", np.zeros((2, 2, 3), np.float32)), None),
        (lambda: stochtex.write_image("x.bmp", np.zeros((2, 2, 3), np.float32)), None),
    ],
)
def test_each_bad_argument_raises_input_error(call, parameter):
    with pytest.raises(stochtex.InputError) as caught:
        call()
    assert caught.value.parameter == parameter, str(caught.value)
    assert str(caught.value)


def test_a_did_you_mean_for_a_typo():
    with pytest.raises(stochtex.InputError, match='did you mean smooth'):
        stochtex.render("camouflage", filter="smoth")


def test_bad_footprint_arrays():
    stats = stochtex.FootprintStatistics(stochtex.pattern("camouflage"))
    with pytest.raises(stochtex.InputError) as caught:
        stats.estimate(np.zeros((4, 3)), np.zeros((4, 2, 2)))
    assert caught.value.parameter == "uv"
    with pytest.raises(stochtex.InputError) as caught:
        stats.estimate(np.zeros((4, 2)), np.zeros((5, 2, 2)))
    assert caught.value.parameter == "jacobian"

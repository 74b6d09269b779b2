# Large images in bands of rows: Renderer.bake and stochtex.dask.bake write
# the same bytes as `stochtex bake-image` (PNG and EXR), also when a worker
# dies mid-run, and wider than one render (tiles of 16384 columns);
# ImageStream writes a file only when it is complete.
import os

import numpy as np
import pytest

import stochtex
import stochtex.dask

VIEW = dict(size=(200, 150), scale=3.0)


def bake_image(cli, tmp_path, name, *flags):
    path = str(tmp_path / name)
    cli("bake-image", "--preset", "marble", "--size", "200,150", "--scale", "3", "--filter", "smooth", *flags,
        "-o", path)
    with open(path, "rb") as f:
        return f.read()


def read(path):
    with open(path, "rb") as f:
        return f.read()


@pytest.fixture(scope="module")
def marble():
    return stochtex.Renderer(stochtex.pattern("marble"), filter="smooth")


def test_a_bake_is_bake_image_s_file(tmp_path, cli, marble):
    for ext, flags in ((".exr", ["--band", "40"]), (".png", ["--band", "40", "--bits", "16"])):
        expected = bake_image(cli, tmp_path, "cli" + ext, *flags)
        marble.bake(str(tmp_path / ("py" + ext)), band=40, bits=16 if ext == ".png" else 8, **VIEW)
        assert read(tmp_path / ("py" + ext)) == expected, ext


def test_a_band_is_its_rows_of_the_view(marble):
    whole = marble.render(**VIEW)
    for y0, y1 in ((0, 1), (40, 80), (149, 150)):
        assert np.array_equal(marble.render(rows=(y0, y1), **VIEW), whole[y0:y1])
    with pytest.raises(stochtex.InputError) as caught:
        marble.render(rows=(100, 151), **VIEW)
    assert caught.value.parameter == "rows"
    with pytest.raises(stochtex.InputError) as caught:
        marble.render(rows=(0, 10), camera="plane", **VIEW)
    assert caught.value.parameter == "camera"


def test_a_bake_wider_than_a_render_is_its_tiles_side_by_side(tmp_path, cli, client, marble):
    # 20000 columns: a tile of 16384 and one of 3616, each a render of its
    # own whose offset is moved right by its first column.
    wide = dict(size=(20000, 6), scale=3.0, offset=(0.0, 0.0))
    path = str(tmp_path / "wide.exr")
    marble.bake(path, band=4, **wide)
    image = stochtex.read_image(path)
    assert image.shape == (6, 20000, 3)
    assert np.array_equal(image[:, :16384], marble.render(size=(16384, 6), scale=3.0, offset=(0.0, 0.0)))
    assert np.array_equal(image[:, 16384:], marble.render(size=(3616, 6), scale=3.0, offset=(16384 * 3.0, 0.0)))
    assert np.array_equal(marble.render(rows=(2, 5), **wide), image[2:5])
    cli("bake-image", "--preset", "marble", "--size", "20000,6", "--scale", "3", "--offset", "0,0", "--filter",
        "smooth", "--band", "4", "-o", str(tmp_path / "cli.exr"))
    assert read(tmp_path / "cli.exr") == read(path)
    stochtex.dask.bake(client, "marble", str(tmp_path / "dask.exr"), band=4, filter="smooth", **wide)
    assert read(tmp_path / "dask.exr") == read(path)
    # A band of a view 65536 wide holds 64 rows (16384 × 256 pixels).
    assert stochtex.band_rows(65536, 256) == 64 and stochtex.band_rows(20000, 4) == 4
    assert marble.view(size=65536, baked=True)["width"] == 65536
    with pytest.raises(stochtex.InputError) as caught:
        marble.view(size=(65537, 8), baked=True)
    assert caught.value.parameter == "size"


def test_an_image_stream_appears_only_when_complete(tmp_path):
    path = str(tmp_path / "s.exr")
    stream = stochtex.ImageStream(path, 8, 4)
    stream.write_rows(np.full((3, 8, 3), 0.25, np.float32))
    with pytest.raises(stochtex.InputError) as caught:
        stream.finish()  # a row is missing
    assert caught.value.parameter == "rows"
    with pytest.raises(stochtex.InputError):
        stream.write_rows(np.zeros((2, 8, 3), np.float32))  # one row too many
    with pytest.raises(stochtex.InputError):
        stream.write_rows(np.zeros((1, 7, 3), np.float32))  # the wrong width
    assert not os.path.exists(path)
    stream.write_rows(np.full((1, 8, 3), 0.5, np.float32))
    stream.finish()
    image = stochtex.read_image(path)
    assert image.shape == (4, 8, 3) and image[0, 0, 0] == 0.25 and image[3, 7, 2] == 0.5
    dropped = stochtex.ImageStream(str(tmp_path / "d.png"), 8, 4)
    dropped.write_rows(np.zeros((2, 8, 3), np.float32))
    del dropped
    assert os.listdir(tmp_path) == ["s.exr"]  # no file, no temporary left
    with pytest.raises(stochtex.InputError):
        stochtex.ImageStream(str(tmp_path / "x.jpg"), 8, 4)  # not written in bands


def test_a_dask_bake_is_bake_image_s_file(tmp_path, cli, client):
    expected = bake_image(cli, tmp_path, "cli.exr", "--band", "40")
    seen = []
    stochtex.dask.bake(client, "marble", str(tmp_path / "dask.exr"), band=40, filter="smooth",
                       progress=lambda f, step: seen.append(f), **VIEW)
    assert read(tmp_path / "dask.exr") == expected
    assert seen[-1] == 1.0 and len(seen) == 4
    expected = bake_image(cli, tmp_path, "cli.png", "--band", "7")
    stochtex.dask.bake(client, "marble", str(tmp_path / "dask.png"), band=7, pending=1, filter="smooth", **VIEW)
    assert read(tmp_path / "dask.png") == expected


def test_a_worker_lost_mid_bake_changes_nothing(tmp_path, cli, client, worker_killed_mid_run):
    expected = bake_image(cli, tmp_path, "cli.exr", "--band", "2")
    with worker_killed_mid_run():
        stochtex.dask.bake(client, "marble", str(tmp_path / "dask.exr"), band=2, filter="smooth", **VIEW)
    assert read(tmp_path / "dask.exr") == expected


def test_bad_bake_options_raise_before_any_task(tmp_path, client):
    with pytest.raises(stochtex.InputError) as caught:
        stochtex.dask.bake(client, "marble", str(tmp_path / "x.exr"), filter="smoth")
    assert caught.value.parameter == "filter"
    with pytest.raises(stochtex.InputError):
        stochtex.dask.bake(client, "marble", str(tmp_path / "x.gif"))
    with pytest.raises(TypeError):
        stochtex.dask.bake(client, stochtex.pattern("marble"), str(tmp_path / "x.exr"))
    assert not os.listdir(tmp_path)

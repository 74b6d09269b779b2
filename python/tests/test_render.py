# Rendering from Python: the same pixels as the CLI, linear light, no copy
# surprises, and the thread count does not change them.
import os
import threading

import numpy as np
import pytest

import stochtex


def test_presets_are_listed():
    names = stochtex.presets()
    assert "camouflage" in names and "figure14" in names
    assert names == sorted(names)


@pytest.mark.parametrize(
    "preset, args",
    [
        ("camouflage", dict(filter="none", scale=1.5)),
        ("camouflage", dict(filter="smooth", scale=4.7)),
        ("figure14", dict(filter="paper", scale=3)),
        ("marble", dict(filter="smooth", scale=2, camera="plane", tilt_deg=70)),
    ],
)
def test_render_equals_the_cli_exr(tmp_path, cli, preset, args):
    exr = tmp_path / "cli.exr"
    flags = ["render", "--preset", preset, "--size", "48,40", "-o", str(exr)]
    for key, value in args.items():
        flags += [{"camera": "--view", "tilt_deg": "--tilt"}.get(key, "--" + key), str(value)]
    cli(*flags)
    from_cli = stochtex.read_image(str(exr))
    image = stochtex.render(preset, size=(48, 40), **args)
    assert image.dtype == np.float32 and image.shape == (40, 48, 3)
    assert from_cli.shape[:2] == (40, 48)
    # A float EXR holds the floats exactly: the two are one computation.
    assert np.max(np.abs(image - from_cli[:, :, :3])) <= 1e-6
    assert 0.05 < image.mean() < 0.95  # a pattern, not a blank


def test_a_renderer_renders_many_views_and_threads_do_not_matter():
    r = stochtex.Renderer(stochtex.pattern("camouflage"), filter="smooth")
    assert r.device == "CPU" and r.example_size == 256 and r.filter == "smooth"
    one = r.render(size=64, scale=3, threads=1)
    two = r.render(size=64, scale=3, threads=2)
    assert np.array_equal(one, two)
    moved = r.render(size=64, scale=3, offset=(64 * 3, 0))  # one view width to the right
    assert not np.array_equal(one, moved)
    wide = r.render(size=(128, 64), scale=3)
    # The same pixels, at other places in the rows' vectors: within the
    # lanes' stated 1e-5 of the scalar kernel.
    assert np.max(np.abs(wide[:, :64] - one)) <= 1e-5 and np.max(np.abs(wide[:, 64:] - moved)) <= 1e-5


def test_simd_and_scalar_kernels_agree():
    p = stochtex.pattern("camouflage")
    simd = stochtex.Renderer(p, filter="smooth", kernel="simd").render(size=64, scale=4.7)
    scalar = stochtex.Renderer(p, filter="smooth", kernel="scalar").render(size=64, scale=4.7)
    assert np.max(np.abs(simd - scalar)) <= 1e-5


def test_a_pattern_from_a_dict_equals_its_file(tmp_path):
    members = {
        "name": "two-noises",
        "size": 32,
        "seed": 5,
        "noise_x": {"type": "spectrum", "size": 64, "components": [{"shape": "lowpass", "cutoff": 8}]},
        "noise_y": {"type": "spectrum", "size": 64, "components": [{"shape": "ring", "frequency": 8, "bandwidth": 2}]},
        "colormap": {"type": "gaussian"},
    }
    import json

    path = tmp_path / "p.json"
    path.write_text(json.dumps(members))
    from_dict = stochtex.pattern(members)
    from_file = stochtex.pattern(path)
    assert from_dict.name == "two-noises" and from_dict.width == 32 and from_dict.seed == 5
    assert np.array_equal(stochtex.render(from_dict), stochtex.render(from_file))
    reseeded = stochtex.render(members, seed=6)
    assert not np.array_equal(reseeded, stochtex.render(from_dict))


def test_images_round_trip(tmp_path):
    pixels = np.linspace(0, 1, 4 * 5 * 3, dtype=np.float32).reshape(4, 5, 3)
    stochtex.write_image(str(tmp_path / "a.exr"), pixels)
    assert np.array_equal(stochtex.read_image(str(tmp_path / "a.exr"))[:, :, :3], pixels)
    stochtex.write_image(str(tmp_path / "a.png"), pixels, bits=16)
    codes = stochtex.read_image(str(tmp_path / "a.png"))[:, :, :3]
    # A PNG holds sRGB codes of the linear pixels; read_image gives them back as written.
    srgb = np.where(pixels <= 0.0031308, 12.92 * pixels, 1.055 * np.power(pixels, 1 / 2.4) - 0.055)
    assert np.max(np.abs(codes - srgb)) <= 1 / 65535


def test_the_gpu_renders_the_same_view():
    p = stochtex.pattern("camouflage")
    try:
        gpu = stochtex.Renderer(p, filter="smooth", gpu=True)
    except stochtex.GpuUnavailable:
        pytest.skip("no OpenGL context on this machine")
    cpu = stochtex.Renderer(p, filter="smooth")
    a = gpu.render(size=64, scale=3)
    b = cpu.render(size=64, scale=3)
    assert gpu.device != "CPU"
    # The CPU/GPU render parity of docs/TESTING.md: mean |Δ| ≤ 0.05/255.
    assert np.mean(np.abs(a - b)) <= 0.05 / 255


SHADERTOY = os.path.join(os.environ.get("STOCHTEX_SOURCE_DIR", "."), "data", "shadertoy")


def test_a_shadertoy_program_s_frames_as_arrays():
    try:
        life = stochtex.Shadertoy(os.path.join(SHADERTOY, "life"), width=64, height=48)
    except stochtex.GpuUnavailable:
        pytest.skip("no OpenGL context on this machine")
    frames = life.frames(4)
    assert frames.shape == (4, 48, 64, 3) and frames.dtype == np.float32
    assert life.frame == 4 and life.name == "life"
    assert np.array_equal(life.frames(4), frames)  # from frame 0 again: the same frames
    assert not np.array_equal(frames[0], frames[3])  # the game went on
    life.reset()
    assert np.array_equal(life.next(), frames[0])


def test_gpu_objects_work_from_any_thread():
    # Their GL context lives on a thread of their own: calls from other
    # Python threads, even at once, are served there one after the other.
    try:
        life = stochtex.Shadertoy(os.path.join(SHADERTOY, "life"), width=32, height=32)
        gpu = stochtex.Renderer(stochtex.pattern("camouflage"), filter="smooth", gpu=True)
    except stochtex.GpuUnavailable:
        pytest.skip("no OpenGL context on this machine")
    expected = (life.frames(3), gpu.render(size=32, scale=2))
    results = []

    def work():
        results.append((life.frames(3), gpu.render(size=32, scale=2)))

    threads = [threading.Thread(target=work) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len(results) == 3
    for frames, image in results:
        assert np.array_equal(frames, expected[0]) and np.array_equal(image, expected[1])


def test_examples_and_colormaps_equal_the_cli_s(tmp_path, cli):
    noise = {"type": "spectrum", "size": 64, "seed": 3, "components": [{"shape": "ring", "frequency": 6, "bandwidth": 2}]}
    import json

    cli("noise", json.dumps(noise), "-o", str(tmp_path / "n.exr"))
    example = stochtex.example(noise)
    assert example.shape == (64, 64) and example.dtype == np.float32
    assert np.array_equal(example, stochtex.read_image(str(tmp_path / "n.exr"))[:, :, 0])
    assert not np.array_equal(stochtex.example(noise, seed=4), example)
    assert 0.3 < example.mean() < 0.7 and example.std() > 0.05

    table = stochtex.colormap({"type": "gaussian"})
    assert table.ndim == 3 and table.shape[2] == 3
    ry, rx, _ = table.shape
    # H = x (grey, its sRGB value x in linear light): rising along a row from
    # black to white, the same on every row.
    assert np.all(np.diff(table[0, :, 0]) > 0) and table[0, 0, 0] == 0 and table[0, -1, 0] == pytest.approx(1, abs=1e-6)
    assert np.array_equal(table, np.broadcast_to(table[:1], table.shape))
    with pytest.raises(stochtex.InputError, match="<dict>"):
        stochtex.colormap({"type": "no-such-colormap"})

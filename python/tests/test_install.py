# `pip install --no-build-isolation .` (setup.py) installs a package that
# imports and renders on its own, without the build tree on the path, and
# downloads nothing (--no-index).
import os
import subprocess
import sys


def test_pip_installs_a_working_package(tmp_path):
    source = os.environ["STOCHTEX_SOURCE_DIR"]
    target = tmp_path / "site"
    env = dict(os.environ, STOCHTEX_BUILD_DIR=os.environ["STOCHTEX_BUILD_DIR"], PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)
    subprocess.run(
        [sys.executable, "-m", "pip", "install", "-q", "--no-build-isolation", "--no-index", "--no-deps", "--target",
         str(target), source],
        check=True, env=env, cwd=tmp_path,
    )
    files = sorted(os.listdir(target / "stochtex"))
    for name in ("__init__.py", "_stochtex.pyi", "dask.py", "libstochtex_media.so", "py.typed", "studies.py"):
        assert name in files
    assert any(f.startswith("_stochtex.") and f.endswith(".so") for f in files)
    check = (
        "import stochtex, numpy as np\n"
        f"assert stochtex.__file__.startswith({str(target)!r}), stochtex.__file__\n"
        "image = stochtex.render('camouflage', size=16, filter='smooth', scale=2)\n"
        "assert image.shape == (16, 16, 3) and 0 < image.mean() < 1\n"
        f"stochtex.write_image({str(tmp_path / 'x.exr')!r}, image)\n"  # the media plugin beside the module
        f"assert np.array_equal(stochtex.read_image({str(tmp_path / 'x.exr')!r})[:, :, :3], image)\n"
    )
    subprocess.run([sys.executable, "-c", check], check=True, env=dict(env, PYTHONPATH=str(target)), cwd=tmp_path)

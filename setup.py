"""pip install --no-build-isolation .   (docs/PYTHON.md)

Builds the extension stochtex._stochtex with the project's CMake (the
target stochtex_python) in STOCHTEX_BUILD_DIR (default: build/, reused if it
is configured already) for the interpreter running pip, and installs it with
the package's Python files (python/stochtex). Nothing is downloaded: the
build needs only what scripts/install-deps.sh installs from Debian.
"""
import glob
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
BUILD = os.path.abspath(os.environ.get("STOCHTEX_BUILD_DIR", os.path.join(ROOT, "build")))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = BUILD
        configure = ["cmake", "-S", ROOT, "-B", build, f"-DPython3_EXECUTABLE={sys.executable}"]
        configured = configured_python(build)
        if configured is None:
            configure.append("-DCMAKE_BUILD_TYPE=Release")  # a configured build keeps its own
        elif os.path.realpath(configured) != os.path.realpath(sys.executable):
            raise RuntimeError(
                f"setup.py: {build} builds the module for {configured}, not {sys.executable} (this pip's); "
                "run pip with that interpreter, or set STOCHTEX_BUILD_DIR to another folder"
            )
        subprocess.check_call(configure)
        subprocess.check_call(["cmake", "--build", build, "--target", "stochtex_python", "-j", str(os.cpu_count() or 1)])
        built = glob.glob(os.path.join(build, "python", "stochtex", "_stochtex*.so"))
        if len(built) != 1:
            raise RuntimeError(f"setup.py: expected one _stochtex module in {build}/python/stochtex, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)
        # The media plugin (EXR/JPEG/TIFF, video) is loaded from beside the module.
        plugin = os.path.join(os.path.dirname(built[0]), "libstochtex_media.so")
        shutil.copyfile(plugin, os.path.join(os.path.dirname(target), "libstochtex_media.so"))


def configured_python(build):
    """The interpreter a configured build tree's module is for, or None."""
    cache = os.path.join(build, "CMakeCache.txt")
    if not os.path.exists(cache):
        return None
    with open(cache) as f:
        for line in f:
            if line.startswith("Python3_EXECUTABLE:"):
                return line.split("=", 1)[1].strip()
    return None


def version():
    with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
        for line in f:
            if line.startswith("project(stochtex VERSION "):
                return line.split("VERSION ")[1].split()[0]
    raise RuntimeError("setup.py: no project version in CMakeLists.txt")


setup(
    name="stochtex",
    version=version(),
    description="Colour-mapped noise vector fields, filtered, and the studies of procedural textures' artifacts",
    packages=["stochtex"],
    package_dir={"": "python"},
    package_data={"stochtex": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("stochtex._stochtex", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
    # setuptools' own staging, in a folder of its own in the build tree.
    options={"build": {"build_base": os.path.join(BUILD, "setuptools")}},
)

"""`pip install .` (pyproject.toml): the rollspin package, its extension built
by the project's CMake for the interpreter that runs pip, with the bundled
scenes inside the package (docs/python.md, "Installing")."""
import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext
from setuptools.command.build_py import build_py

ROOT = os.path.dirname(os.path.abspath(__file__))
# CMake's tree for this Python version, beside build/, kept between installs
# (scripts/build_python_module.sh).
BUILD_DIR = os.path.join(ROOT, "build-python-" + sys.implementation.cache_tag)


def project_version() -> str:
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as cmake:
        return re.search(r"project\(rollspin VERSION ([0-9.]+)", cmake.read()).group(1)


class CMakeBuild(build_ext):
    """The extension is CMake's target _rollspin, built for sys.executable."""

    def build_extension(self, ext: Extension) -> None:
        subprocess.run(["bash", os.path.join(ROOT, "scripts", "build_python_module.sh"), BUILD_DIR, sys.executable],
                       check=True)
        built = glob.glob(os.path.join(BUILD_DIR, "python", "rollspin", "_rollspin*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one _rollspin*.so in {BUILD_DIR}/python/rollspin, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


class BuildWithScenes(build_py):
    """The bundled scenes go inside the package: rollspin.load("lollipop") finds them there."""

    def run(self) -> None:
        super().run()
        scenes = os.path.join(self.build_lib, "rollspin", "scenes")
        os.makedirs(scenes, exist_ok=True)
        for pattern in ("*.toml", "*.png", "*.jpg"):
            for file in glob.glob(os.path.join(ROOT, "scenes", pattern)):
                shutil.copyfile(file, os.path.join(scenes, os.path.basename(file)))


os.makedirs(BUILD_DIR, exist_ok=True)
setup(
    version=project_version(),
    packages=["rollspin"],
    package_dir={"rollspin": "python/rollspin"},
    package_data={"rollspin": ["_rollspin.pyi", "py.typed"]},
    ext_modules=[Extension("rollspin._rollspin", sources=[])],
    cmdclass={"build_ext": CMakeBuild, "build_py": BuildWithScenes},
    # setuptools' own files beside CMake's, not in build/ (the project's tree) or the checkout.
    options={"build": {"build_base": os.path.join(BUILD_DIR, "setuptools")}, "egg_info": {"egg_base": BUILD_DIR}},
    zip_safe=False,
)

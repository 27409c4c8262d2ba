"""Where the tests find the build's `dda` command and the repository's scenes.

ctest sets DDA_CLI, DDA_SCENES_DIR and PYTHONPATH (python/CMakeLists.txt);
run by hand, the paths default to the build tree next to the package.
"""
import os
import pathlib

import pytest
from hypothesis import settings

import dda

# No example database in the source tree (.hypothesis/): each run draws afresh.
settings.register_profile("dda", database=None)
settings.load_profile("dda")

REPO = pathlib.Path(__file__).resolve().parents[2]


def _build_dir():
    return pathlib.Path(dda.__file__).resolve().parents[2]  # <build>/python/dda/__init__.py


@pytest.fixture(scope="session")
def cli():
    path = pathlib.Path(os.environ.get("DDA_CLI", _build_dir() / "bin" / "dda"))
    if not path.exists():
        pytest.fail(f"the dda command is not built: {path}")
    return path


@pytest.fixture(scope="session")
def scenes_dir():
    return pathlib.Path(os.environ.get("DDA_SCENES_DIR", REPO / "repro" / "scenes"))


@pytest.fixture(scope="session")
def bad_dir():
    return REPO / "lib" / "io" / "tests" / "bad"


@pytest.fixture(scope="session")
def examples_dir():
    return pathlib.Path(os.environ.get("DDA_EXAMPLES_DIR", REPO / "examples"))

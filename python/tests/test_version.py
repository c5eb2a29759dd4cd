"""The Python package and the library it loaded are the same release (the version is written once,
in CMake's project(); pyproject.toml must follow it)."""
import pathlib
import re

import pflip


def test_library_abi_is_the_mirrored_one():
    assert pflip.version()[:2] == pflip.ABI_VERSION


def test_pyproject_version_is_the_library_version():
    text = (pathlib.Path(__file__).resolve().parents[1] / "pyproject.toml").read_text()
    version = re.search(r'^version\s*=\s*"([^"]+)"', text, re.M).group(1)
    assert version == "%d.%d.%d" % pflip.version()

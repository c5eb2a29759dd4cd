"""`pip install ./python` gives a package that imports and loads the library named by PFLIP_LIBRARY.

The tree is copied first, so the build leaves nothing in the source directory; no index is used
(setuptools comes from the environment: scripts/setup.sh installs it)."""
import os
import pathlib
import shutil
import subprocess
import sys


def test_pip_install_from_the_tree(tmp_path):
    src = pathlib.Path(__file__).resolve().parents[1]
    copy = tmp_path / "src"
    shutil.copytree(src, copy, ignore=shutil.ignore_patterns("tests", "examples", "__pycache__", "build", "*.egg-info"))
    target = tmp_path / "site"
    pip = [sys.executable, "-m", "pip", "install", "-q", "--disable-pip-version-check", "--no-deps", "--no-index",
           "--no-build-isolation", "--target", str(target), str(copy)]
    result = subprocess.run(pip, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    env = dict(os.environ, PYTHONPATH=str(target))
    probe = "import pflip; print(pflip.__file__); print(pflip.__version__)"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    path, version = out.stdout.split()
    assert pathlib.Path(path).is_relative_to(target), "imported the source tree, not the installed copy"
    assert version == "%d.%d.%d" % __import__("pflip").version()

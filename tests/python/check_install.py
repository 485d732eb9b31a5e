"""Installs the growthuq Python package as tools/python/README.md says, without network
(pip install --no-build-isolation, here into a scratch --target so the system stays as it is),
from a copy of the sources (pip builds in the source folder, which must stay clean), and checks
that the installed package is the one imported, with every module (load, the CLI wrappers and
the exceptions).
Usage: check_install.py PACKAGE_DIR. Exits non-zero with pip's output on a failure."""
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

package = Path(sys.argv[1])
with tempfile.TemporaryDirectory(prefix="growthuq-install-") as scratch:
    source, target = Path(scratch) / "source", Path(scratch) / "site"
    shutil.copytree(package, source, ignore=shutil.ignore_patterns("__pycache__", "build", "*.egg-info"))
    environment = dict(os.environ, PIP_NO_INDEX="1", PIP_FIND_LINKS="")  # offline: nothing fetched
    install = subprocess.run([sys.executable, "-m", "pip", "install", "--no-build-isolation", "--no-deps",
                              "--target", str(target), str(source)],
                             capture_output=True, text=True, env=environment, check=False)
    if install.returncode != 0:
        sys.exit("pip install failed:\n" + install.stdout + install.stderr)
    probe = subprocess.run([sys.executable, "-c", "import growthuq; print(growthuq.__file__); "
                            "print(all(callable(getattr(growthuq, name)) for name in growthuq.__all__))"],
                           capture_output=True, text=True, env=dict(os.environ, PYTHONPATH=str(target)),
                           cwd=scratch, check=False)
    lines = probe.stdout.split()
    if probe.returncode != 0 or len(lines) != 2 or not lines[0].startswith(str(target)) or lines[1] != "True":
        sys.exit("the installed package is not the one imported:\n" + probe.stdout + probe.stderr)
print("growthuq installed offline and imported from", target)

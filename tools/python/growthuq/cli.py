"""The growthuq CLI from Python: `run` a campaign, `eval_tubes` a frame of measured tubes. The
binary is the `cli` argument, else the environment variable GROWTHUQ_CLI, else `growthuq` on
PATH. A failing command raises CliError carrying the CLI's own message (its stderr)."""
import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import pandas as pd

from .results import load


class CliError(RuntimeError):
    """growthuq exited with an error. str(error) is its message; `returncode` and `command`
    (the argument list) tell what ran."""

    def __init__(self, message, returncode, command):
        super().__init__(message)
        self.returncode = returncode
        self.command = command


def find_cli(cli=None):
    """The growthuq binary: `cli`, else $GROWTHUQ_CLI, else growthuq on PATH. FileNotFoundError
    saying where it looked when there is none, or when the one named is not executable."""
    where = "the cli argument" if cli else "GROWTHUQ_CLI" if os.environ.get("GROWTHUQ_CLI") else "PATH"
    candidate = cli or os.environ.get("GROWTHUQ_CLI") or shutil.which("growthuq")
    if not candidate:
        raise FileNotFoundError("growthuq: the CLI was not found (expected cli=PATH, the environment variable "
                                "GROWTHUQ_CLI, or growthuq on PATH)")
    if not (os.path.isfile(candidate) and os.access(candidate, os.X_OK)):
        raise FileNotFoundError(f"{candidate}: not an executable file (expected the growthuq CLI; from {where})")
    return str(candidate)


def _options(options):
    """Keyword arguments as CLI options: samples=40 -> --samples 40, k_sys=2 -> --k-sys 2,
    lines=["a", "b"] -> --lines a,b, force=True -> --force (False and None: left out)."""
    arguments = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + key.replace("_", "-")
        if value is True:
            arguments.append(flag)
        elif isinstance(value, (list, tuple)):
            arguments += [flag, ",".join(str(item) for item in value)]
        else:
            arguments += [flag, str(value)]
    return arguments


def _call(cli, arguments, cwd=None):
    # subprocess would raise "ValueError: embedded null byte", naming no option: no file name or
    # option value can hold a NUL, so it is refused here naming the argument.
    for argument in [*arguments, *([str(cwd)] if cwd is not None else [])]:
        if "\0" in str(argument):
            raise ValueError(f"growthuq: the argument {str(argument)!r} contains a NUL character (\\0), which no "
                             "file name or option value can hold")
    command = [find_cli(cli), *arguments]
    completed = subprocess.run(command, cwd=cwd, capture_output=True, text=True, check=False)
    if completed.returncode != 0:
        message = completed.stderr.strip() or completed.stdout.strip() or f"exited with {completed.returncode}"
        raise CliError(message, completed.returncode, command)
    return completed


# The first line of the run report names the output directory (src/campaign/campaign_outputs.cpp).
_RESULTS_IN = re.compile(r"^campaign '.*': .* results in (.+)$", re.MULTILINE)


def run(campaign, *, cli=None, cwd=None, quiet=True, **overrides):
    """Runs `growthuq run CAMPAIGN` with `overrides` as its options (samples=40, seed=7,
    out="results/x", lines=["wild_type", "pme48"], force=True; see `growthuq run --help`) in `cwd`
    and returns load() of its output directory, with the run's stdout as `report`. The campaign
    must write hdf5 (its formats, or formats=["csv", "hdf5"]). CliError with the CLI's message when
    the run fails."""
    completed = _call(cli, ["run", str(campaign), *_options(overrides), *(["--quiet"] if quiet else [])], cwd)
    out = overrides.get("out")
    if out is None:
        found = _RESULTS_IN.search(completed.stdout)
        if found is None:
            raise CliError("growthuq run: the report names no output directory (expected a line "
                           "\"campaign '...': ... results in DIR\"); pass out=DIR", 0, [str(campaign)])
        out = found.group(1)
    directory = Path(out) if Path(out).is_absolute() else Path(cwd or ".") / out
    results = load(directory)
    results.report = completed.stdout
    return results


def eval_tubes(frame, rho_um, *, cli=None, **options):
    """Inverts the tubes of `frame` (columns k_N_per_m, d_um, d0_um and optionally h_nm, or the
    same quantities in other units, e.g. h_um) with `growthuq eval --in`, probe radius `rho_um`,
    `options` as its other options (nu=0.3, k_sys=2.5, fidelity="shell_fe"), and returns its
    results as a frame: the input columns, p_MPa, E_MPa, ..., status (NaN where a tube has no
    value), with `frame`'s index. CliError with the CLI's message for bad tubes or options."""
    with tempfile.TemporaryDirectory(prefix="growthuq-eval-") as scratch:
        tubes, out = Path(scratch) / "tubes.csv", Path(scratch) / "results.csv"
        frame.to_csv(tubes, index=False)  # shortest round-trip text: the CLI reads the same doubles
        _call(cli, ["eval", "--in", str(tubes), "--out", str(out), "--rho-um", str(rho_um), *_options(options)])
        # round_trip: the doubles the CLI wrote (pandas' default parser may miss by an ulp)
        results = pd.read_csv(out, keep_default_na=False, na_values=[""], float_precision="round_trip")
    results.index = frame.index
    return results

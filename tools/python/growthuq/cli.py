"""The growthuq CLI from Python: `run` and `check` a campaign, measure its `tradeoff`, `synth` a
raw data set, `fit_line` raw data, `eval_tubes` a frame of measured tubes. The binary is the `cli`
argument, else the environment variable GROWTHUQ_CLI, else `growthuq` on PATH. A failing command
raises the CliError subclass of its exit status (errors.py) carrying the CLI's own message."""
import os
import re
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from .errors import ArgumentError, CliError, CliNotFoundError
from .process import call
from .results import load


def find_cli(cli=None):
    """The growthuq binary: `cli`, else $GROWTHUQ_CLI, else growthuq on PATH. CliNotFoundError (a
    FileNotFoundError) saying where it looked when there is none, or when the one named is not
    executable."""
    where = "the cli argument" if cli else "GROWTHUQ_CLI" if os.environ.get("GROWTHUQ_CLI") else "PATH"
    candidate = cli or os.environ.get("GROWTHUQ_CLI") or shutil.which("growthuq")
    if not candidate:
        raise CliNotFoundError("growthuq: the CLI was not found (expected cli=PATH, the environment variable "
                               "GROWTHUQ_CLI, or growthuq on PATH)")
    if not (os.path.isfile(candidate) and os.access(candidate, os.X_OK)):
        raise CliNotFoundError(f"{candidate}: not an executable file (expected the growthuq CLI; from {where})")
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


def _call(cli, arguments, cwd=None, quiet=True):
    """Runs growthuq with `arguments` in `cwd`; its stderr (progress) is shown live on sys.stderr
    unless `quiet`. Returns (stdout, stderr); raises the CliError of its exit status."""
    # subprocess would raise "ValueError: embedded null byte", naming no option: no file name or
    # option value can hold a NUL, so it is refused here naming the argument.
    for argument in [*arguments, *([str(cwd)] if cwd is not None else [])]:
        if "\0" in str(argument):
            raise ArgumentError(f"growthuq: the argument {str(argument)!r} contains a NUL character (\\0), which no "
                                "file name or option value can hold")
    return call([find_cli(cli), *(str(argument) for argument in arguments)], cwd, show_progress=not quiet)


def _quiet_flag(quiet):
    return [] if not quiet else ["--quiet"]


def _in(cwd, path):
    """`path` as the CLI run in `cwd` sees it."""
    return Path(path) if Path(path).is_absolute() else Path(cwd or ".") / path


# The first line of the run report names the output directory (src/campaign/campaign_outputs.cpp).
_RESULTS_IN = re.compile(r"^campaign '.*': .* results in (.+)$", re.MULTILINE)


def run(campaign, *, cli=None, cwd=None, quiet=True, **overrides):
    """Runs `growthuq run CAMPAIGN` with `overrides` as its options (samples=40, seed=7,
    out="results/x", lines=["wild_type", "pme48"], force=True; see `growthuq run --help`) in `cwd`
    and returns load() of its output directory, with the run's stdout as `report`. quiet=False
    shows the run's progress live on sys.stderr. The campaign must write hdf5 (its formats, or
    formats=["csv", "hdf5"]). InputError with the CLI's message when the run refuses its input."""
    stdout, _ = _call(cli, ["run", campaign, *_options(overrides), *_quiet_flag(quiet)], cwd, quiet)
    out = overrides.get("out")
    if out is None:
        found = _RESULTS_IN.search(stdout)
        if found is None:
            raise CliError("growthuq run: the report names no output directory (expected a line "
                           "\"campaign '...': ... results in DIR\"); pass out=DIR", 0, [str(campaign)])
        out = found.group(1)
    results = load(_in(cwd, out))
    results.report = stdout
    return results


def check(campaign, *, cli=None, cwd=None, quiet=True, **options):
    """Runs `growthuq check CAMPAIGN` with `options` as a run's (samples=, out=, lines=, formats=,
    fidelity=, force=) in `cwd` and returns its plan (stdout) when the run would start; the
    InputError of the run's message when it would not. Nothing is sampled or written. quiet=False
    shows the raw-data lines' curve fits live on sys.stderr."""
    stdout, _ = _call(cli, ["check", campaign, *_options(options), *_quiet_flag(quiet)], cwd, quiet)
    return stdout


_TABLE_AT = re.compile(r"^table: (.+) \(\d+ rows\)$", re.MULTILINE)


def tradeoff(campaign, *, cli=None, cwd=None, quiet=True, **options):
    """Runs `growthuq tradeoff CAMPAIGN` (samples_list=[100, 1000], fidelities=, fe_samples_list=,
    target="1%", out=, force=, lines=, seed=) in `cwd` and returns the table it wrote (one row per
    fidelity, sample count, line and quantity; the CSV's doubles exactly), with its printed verdict
    in `table.attrs["report"]` and the table's path in `table.attrs["path"]`. Without `out` the
    table goes where the CLI puts it (tradeoff.csv in the campaign's output_dir)."""
    stdout, _ = _call(cli, ["tradeoff", campaign, *_options(options), *_quiet_flag(quiet)], cwd, quiet)
    found = _TABLE_AT.search(stdout)
    if found is None:
        raise CliError("growthuq tradeoff: the report names no table (expected a line \"table: FILE (N rows)\")",
                       0, [str(campaign)])
    path = _in(cwd, found.group(1))
    table = pd.read_csv(path, keep_default_na=False, na_values=[""], float_precision="round_trip")
    table.attrs.update(report=stdout, path=path)
    return table


_SYNTH_LINE = re.compile(r"^growthuq synth: (.+): \d+ files, .* in (.+) \([0-9.]+ s\)$", re.MULTILINE)


def synth(line_files, out, *, cli=None, cwd=None, **options):
    """Runs `growthuq synth` on `line_files` (one path or a list) into `out` with `options`
    (seed=, tubes="20:60", curves=, force_curves=, force=, ...) and returns {line: raw.ini} of the
    SYNTHETIC raw data sets it drew, each ready for `fit_line` or a campaign's `raw =`."""
    files = [line_files] if isinstance(line_files, (str, os.PathLike)) else list(line_files)
    stdout, _ = _call(cli, ["synth", *files, "--out", out, *_options(options)], cwd)
    return {name: _in(cwd, folder) / "raw.ini" for name, folder in _SYNTH_LINE.findall(stdout)}


@dataclass
class LineFit:
    """What `growthuq fit-line` gives: the fitted line file's `text` (distributions/<line>.ini
    format), the fit `report` it prints, and the `path` it was written to (None when not kept)."""
    text: str
    report: str
    path: Path = None

    def __repr__(self):
        first = self.report.splitlines()[0] if self.report else ""
        return f"LineFit({first!r}, path={str(self.path) if self.path else None!r})"


def fit_line(raw, *, out=None, cli=None, cwd=None, quiet=True, **options):
    """Runs `growthuq fit-line RAW.ini` (rho_um=, nu=, force=) and returns a LineFit: the fitted
    line file's text and the fit report. With `out` the line file is also written there (refused
    when it exists, unless force=True). quiet=False shows the curve fits' progress live."""
    with tempfile.TemporaryDirectory(prefix="growthuq-fit-line-") as scratch:
        target = Path(scratch) / "line.ini" if out is None else out
        stdout, _ = _call(cli, ["fit-line", raw, "--out", target, *_options(options), *_quiet_flag(quiet)], cwd, quiet)
        text = _in(cwd, target).read_text()
    if out is None:  # the report's last line names the scratch file, gone with it
        stdout = "".join(line for line in stdout.splitlines(keepends=True) if not line.startswith(f"wrote {target}"))
    return LineFit(text, stdout, None if out is None else _in(cwd, out))


def eval_tubes(frame, rho_um, *, cli=None, quiet=True, **options):
    """Inverts the tubes of `frame` (columns k_N_per_m, d_um, d0_um and optionally h_nm, or the
    same quantities in other units, e.g. h_um) with `growthuq eval --in`, probe radius `rho_um`,
    `options` as its other options (nu=0.3, k_sys=2.5, fidelity="shell_fe"), and returns its
    results as a frame: the input columns, p_MPa, E_MPa, ..., status (NaN where a tube has no
    value), with `frame`'s index. quiet=False shows the finite-element inverse's progress live.
    InputError with the CLI's message for bad tubes or options."""
    with tempfile.TemporaryDirectory(prefix="growthuq-eval-") as scratch:
        tubes, out = Path(scratch) / "tubes.csv", Path(scratch) / "results.csv"
        frame.to_csv(tubes, index=False)  # shortest round-trip text: the CLI reads the same doubles
        _call(cli, ["eval", "--in", tubes, "--out", out, "--rho-um", rho_um, *_options(options), *_quiet_flag(quiet)],
              None, quiet)
        # round_trip: the doubles the CLI wrote (pandas' default parser may miss by an ulp)
        results = pd.read_csv(out, keep_default_na=False, na_values=[""], float_precision="round_trip")
    results.index = frame.index
    return results

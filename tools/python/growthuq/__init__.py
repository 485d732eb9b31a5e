"""growthuq from Python: `load` a campaign's results (results.h5) as pandas frames and an xarray
Dataset; `run`, `check` and `tradeoff` a campaign, `synth` and `fit_line` raw data and
`eval_tubes` measured tubes through the growthuq CLI. Every error is a GrowthuqError.

    import growthuq
    results = growthuq.load("results/quick")
    results.samples            # one row per sample, lines in campaign order
    results.long               # line, sample, quantity, value, unit
    results.dataset["p_MPa"]   # (line, sample), attrs units = "MPa"

See tools/python/README.md."""
from .cli import LineFit, check, eval_tubes, find_cli, fit_line, run, synth, tradeoff
from .errors import (ArgumentError, CliError, CliNotFoundError, GrowthuqError, InputError, InternalError,
                     Interrupted, OutOfMemoryError, ResultsError)
from .results import Results, load

__all__ = ["ArgumentError", "CliError", "CliNotFoundError", "GrowthuqError", "InputError", "InternalError",
           "Interrupted", "LineFit", "OutOfMemoryError", "Results", "ResultsError", "check", "eval_tubes",
           "find_cli", "fit_line", "load", "run", "synth", "tradeoff"]
__version__ = "0.2.0"

"""growthuq from Python: `load` a campaign's results (results.h5) as pandas frames and an xarray
Dataset, `run` a campaign and `eval_tubes` measured tubes through the growthuq CLI.

    import growthuq
    results = growthuq.load("results/quick")
    results.samples            # one row per sample, lines in campaign order
    results.dataset["p_MPa"]   # (line, sample), attrs units = "MPa"

See tools/python/README.md."""
from .cli import CliError, eval_tubes, find_cli, run
from .results import Results, ResultsError, load

__all__ = ["CliError", "Results", "ResultsError", "eval_tubes", "find_cli", "load", "run"]
__version__ = "0.1.0"

"""Other shapes of the same results: the samples as one long (tidy) frame, the summary as a
DataArray of the Dataset, and the few lines a Results shows when printed."""
import textwrap

import numpy as np
import pandas as pd
import xarray as xr

# The statistics of a summary row (summary.csv's numeric columns), in its order.
SUMMARY_STATISTICS = ["n", "n_flagged", "median", "q1", "q3", "iqr", "p10", "p90", "mean", "sd",
                      "median_ci_low", "median_ci_high", "data_ci_low", "data_ci_high"]


def long_frame(samples, dataset):
    """One row per sample and quantity that holds a value: line, sample, quantity (p, E, k, ...),
    value (in the Dataset's unit, the quantity's default), unit. A cell the sample lacks (a
    flagged sample's NaN) has no row, so the rows of a quantity are those its summary counts."""
    columns = [name for name in samples.columns if name not in ("line", "sample", "status")]
    frame = samples.melt(id_vars=["line", "sample"], value_vars=columns, var_name="column", value_name="value")
    frame = frame[frame["value"].notna()]
    quantity = {name: dataset[name].attrs.get("quantity", name) for name in columns}
    unit = {name: dataset[name].attrs.get("units", "") for name in columns}
    frame.insert(2, "quantity", pd.Categorical(frame["column"].map(quantity),
                                               categories=list(dict.fromkeys(quantity.values())), ordered=True))
    frame["unit"] = frame["column"].map(unit)
    frame = frame.drop(columns="column").sort_values(["line", "quantity", "sample"], kind="stable")
    return frame.reset_index(drop=True)


def summary_array(summary, lines):
    """The summary as (line, quantity, statistic) with the row's unit as the coordinate `unit` on
    (line, quantity): an input keeps its line file's unit there (einf in % or as a fraction), as
    summary.csv gives it. NaN where a line lacks the quantity or the statistic is undefined."""
    quantities = list(dict.fromkeys(summary["quantity"]))
    values = np.full((len(lines), len(quantities), len(SUMMARY_STATISTICS)), np.nan)
    units = np.full((len(lines), len(quantities)), "", dtype=object)
    line_index = {line: i for i, line in enumerate(lines)}
    quantity_index = {quantity: j for j, quantity in enumerate(quantities)}
    for row in summary.itertuples(index=False):
        i, j = line_index[str(row.line)], quantity_index[row.quantity]
        values[i, j] = [float(getattr(row, statistic)) for statistic in SUMMARY_STATISTICS]
        units[i, j] = row.unit
    return xr.DataArray(values, dims=("line", "quantity", "statistic"),
                        coords={"line": lines, "quantity": quantities, "statistic": SUMMARY_STATISTICS,
                                "unit": (("line", "quantity"), units)},
                        attrs={"long_name": "summary.csv's statistics per line and quantity"})


def short_repr(results):
    """A few lines: the file, the lines and their samples, and each non-empty table's size."""
    attrs = results.attrs
    head = (f"growthuq.Results({str(results.path)!r}): {len(results.lines)} lines x "
            f"{attrs.get('samples_per_line', '?')} samples, seed {attrs.get('seed', '?')}, "
            f"growthuq {attrs.get('engine_version', '?')}")
    lines = ", ".join(results.lines)
    if len(lines) > 100:
        lines = lines[:97] + "..."
    tables = [f"{name} {len(frame)}x{frame.shape[1]}" for name, frame in results.tables().items() if len(frame)]
    tables = textwrap.fill("tables (rows x columns): " + ", ".join(tables), width=100, initial_indent="  ",
                           subsequent_indent="    ")
    return "\n".join([head, f"  lines: {lines}", tables,
                      f"  dataset: {', '.join(f'{k} {v}' for k, v in results.dataset.sizes.items())}; "
                      f"{len(results.dataset.data_vars)} variables"])

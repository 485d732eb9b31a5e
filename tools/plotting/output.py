"""Writing figures as growthuq writes results: every file through a temporary name renamed when
complete (an interrupted run leaves no half-written plot), and no existing plot overwritten
unless asked. PDFs carry no creation date, so the same results give the same files."""
import os
from pathlib import Path

import matplotlib

from .errors import PlotInputError
from .style import RC

PNG_DPI = 150


def target_paths(out_dir, names, formats):
    return [Path(out_dir) / f"{name}.{extension}" for name in names for extension in formats]


def refuse_overwrite(paths):
    existing = [path for path in paths if path.exists()]
    if existing:
        more = f" (and {len(existing) - 1} more of the plots)" if len(existing) > 1 else ""
        raise PlotInputError(f"{existing[0]}: already exists{more}; give --force to replace them")


def save_figure(figure, path):
    """Writes `figure` to `path` (format from its extension) atomically."""
    path = Path(path)
    partial = path.with_name(path.name + ".partial")
    metadata = {"CreationDate": None} if path.suffix == ".pdf" else {"Software": "growthuq tools/plot"}
    try:
        with matplotlib.rc_context(RC):
            figure.savefig(partial, format=path.suffix[1:], dpi=PNG_DPI, metadata=metadata)
        os.replace(partial, path)
    except OSError as error:
        raise PlotInputError(f"{path}: cannot write ({error.strerror})") from None
    finally:
        partial.unlink(missing_ok=True)  # gone after the rename; left only by a failure


def save_text(text, path):
    """Writes `text` to `path` atomically, as save_figure does a figure."""
    path = Path(path)
    partial = path.with_name(path.name + ".partial")
    try:
        partial.write_text(text, encoding="utf-8")
        os.replace(partial, path)
    except OSError as error:
        raise PlotInputError(f"{path}: cannot write ({error.strerror})") from None
    finally:
        partial.unlink(missing_ok=True)

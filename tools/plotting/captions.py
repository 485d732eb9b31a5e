"""Each figure's caption, kept outside the figure (a paper prints its caption under the figure,
not in it): tools/plot writes them to captions.md beside the plots, `growthuq report` under each
embedded figure."""
from .boxes import box_caption

FIXED = {
    "growth_rate": "Predicted against measured growth rate per line: hatched boxes are draws from the line's "
                   "fitted v_exp law (not its tubes), filled ones the predicted v of its samples; kappa is "
                   "calibrated on the reference line, which therefore agrees by construction.",
    "correlogram": "Inputs and outputs of one line (samples with status ok): histograms on the diagonal, scatter "
                   "below (first 2000 samples), Spearman coefficients above.",
    "sensitivity": "First-order sensitivity S = Var(E[output | input]) / Var(output) of every input for every "
                   "output, with its 95 % interval: which input drives which output.",
    "pca": "Explained variance of the principal components of the standardized inputs and outputs, per "
           "component and cumulative.",
    "relaxation": "Force-relaxation curves of the raw-data lines (points) and their generalized Maxwell fits "
                  "(lines).",
    "force_curves": "Force-indentation curves of the raw-data lines whose k comes from force curves: recorded force "
                    "(points), baseline offset and tilt (dashed), contact point (ring), fit window (bar along the bottom) and the "
                    "window line; right, each tube's k with its 95 % interval (k ± 1.96 u) and its curves' k (dots).",
    "tradeoff": "Errors of the medians and IQRs and the CI half-width against the sample count, and the run's "
                "time (growthuq tradeoff).",
}


def caption(stem, results):
    """The caption of the figure saved as `stem` (a family name, or family_<line>)."""
    if stem == "boxes":
        return box_caption(results)
    family = next((name for name in FIXED if stem == name or stem.startswith(name + "_")), None)
    return FIXED.get(family, "")


def captions_markdown(stems, results):
    """captions.md: one paragraph per figure, its file stem in bold."""
    return "".join(f"**{stem}**: {caption(stem, results)}\n\n" for stem in stems)

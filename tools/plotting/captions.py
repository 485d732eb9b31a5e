"""Each figure's caption, kept outside the figure (a paper prints its caption under the figure,
not in it): tools/plot writes them to captions.md beside the plots, `growthuq report` under each
embedded figure."""
from .boxes import box_caption
from .growth_rate import growth_rate_caption

FIXED = {
    "correlogram": "Inputs and outputs of one line (samples with status ok): histograms on the diagonal, scatter "
                   "below (first 2000 samples), Spearman coefficients above.",
    "sensitivity": "First-order sensitivity S = Var(E[output | input]) / Var(output) of every input for every "
                   "output, with its 95 % interval: which input drives which output.",
    "pca": "Explained variance of the principal components of the standardized inputs and outputs, per "
           "component and cumulative.",
    "relaxation": "Force-relaxation curves of the raw-data lines (points) and their generalized Maxwell fits "
                  "(lines), t = 0 at the force maximum; under each panel the residuals F - F_fit of the fitted "
                  "curves.",
    "force_curves": "Force-indentation curves of the raw-data lines whose k comes from force curves: recorded force "
                    "(points), baseline offset and tilt (dashed), contact point (ring), fit window (bar along the bottom) and the "
                    "window line; right, each tube's k with its 95 % interval (k ± 1.96 u) and its curves' k (dots).",
    "tradeoff": "Precision of the medians against the samples per line (growthuq tradeoff), log-log: lines, the "
                "half-width of each line's 95 % confidence interval of the median in % of the median; open points, "
                "the measured |median error| against the largest run; dashed, the target precision. Last panel: "
                "the wall time of the run.",
}


def caption(stem, results):
    """The caption of the figure saved as `stem` (a family name, or family_<line>)."""
    if stem == "boxes":
        return box_caption(results)
    if stem == "growth_rate":
        return growth_rate_caption(results)
    family = next((name for name in FIXED if stem == name or stem.startswith(name + "_")), None)
    return FIXED.get(family, "")


def captions_markdown(stems, results):
    """captions.md: one paragraph per figure, its file stem in bold."""
    return "".join(f"**{stem}**: {caption(stem, results)}\n\n" for stem in stems)

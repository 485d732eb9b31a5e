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
                  "(lines).",
    "tradeoff": "Errors of the medians and IQRs and the CI half-width against the sample count, and the run's "
                "time (growthuq tradeoff).",
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

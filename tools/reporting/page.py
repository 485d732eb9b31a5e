"""The report as one HTML page: a self-contained file (inline CSS, PNGs as data: URLs, no script)
that any browser opens offline and prints."""
from html import escape

from .methods import methods_paragraph, references, warnings
from .tables import comparisons_table, fits_table, letters_table, summary_table, sensitivity_table

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; border-bottom: 1px solid #ccc; margin-top: 2em; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.9em; }
caption { caption-side: bottom; text-align: left; font-size: 0.85em; color: #555; padding-top: 0.4em; }
th, td { border: 1px solid #bbb; padding: 0.25em 0.6em; text-align: left; }
th { background: #eef2f7; }
tbody tr:nth-child(even) { background: #f8f8f8; }
.warning { background: #fff4e0; border-left: 4px solid #e69500; padding: 0.5em 1em; margin: 0.4em 0; }
figure { margin: 1.5em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #444; margin-top: 0.3em; }
.methods { line-height: 1.5; }
"""


def _section(title, content, section_id):
    return f'<section id="{section_id}"><h2>{escape(title)}</h2>\n{content}\n</section>'


def report_html(run, figures, notes):
    provenance = run.provenance
    title = f"growthuq report: {provenance['campaign_name']}" if provenance else f"growthuq report: {run.directory}"
    parts = [f"<h1>{escape(title)}</h1>",
             f"<p>Results directory {escape(str(run.directory))}, written {escape(run.written)}.</p>"]
    found = warnings(provenance, run.summary)
    if found:
        parts.append(_section("Warnings", "\n".join(f'<p class="warning">{escape(w)}</p>' for w in found), "warnings"))
    if provenance:
        parts.append(_section("Methods", f'<p class="methods">{escape(methods_paragraph(provenance, run.written))}</p>',
                              "methods"))
    parts.append(_section("Data intervals and summary", summary_table(run.summary), "summary-section"))
    if run.letters:
        parts.append(_section("Line comparisons", letters_table(run.letters) +
                              (comparisons_table(run.comparisons) if run.comparisons else ""), "comparisons-section"))
    if run.sensitivity:
        parts.append(_section("Sensitivity", sensitivity_table(run.sensitivity), "sensitivity-section"))
    if run.fits:
        parts.append(_section("Fit reports", "\n".join(fits_table(line, rows) for line, rows in run.fits.items()),
                              "fits-section"))
    if figures:
        blocks = [f'<figure id="figure-{escape(stem)}"><img alt="{escape(stem)}" src="data:image/png;base64,{data}">'
                  f"<figcaption>{escape(text)}</figcaption></figure>" for stem, text, data in figures]
        parts.append(_section("Figures", "\n".join(blocks), "figures"))
    if notes:
        parts.append(_section("Notes", "<ul>" + "".join(f"<li>{escape(n)}</li>" for n in notes) + "</ul>", "notes"))
    if provenance:
        items = "".join(f"<li>[{index}] {escape(reference)} (used for: {escape(', '.join(names))})</li>"
                        for index, (names, reference) in enumerate(references(provenance), start=1))
        parts.append(_section("References", f'<ol class="references">{items}</ol>', "references"))
    body = "\n".join(parts)
    return (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>{escape(title)}</title>\n'
            f"<style>{STYLE}</style>\n</head>\n<body>\n{body}\n</body>\n</html>\n")

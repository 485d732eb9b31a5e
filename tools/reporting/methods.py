"""The methods paragraph, the references and the warnings of a report, all made from the run's
own provenance.json (what growthuq run recorded), so the text a lab pastes into a paper states
what was run, not what the campaign template says."""
from collections import Counter

from .inputs import number
from .tables import significant

QUANTITY_NAMES = {"p": "turgor pressure p", "E": "wall modulus E", "eta": "wall viscosity η",
                  "v": "tip growth rate v", "v_exp": "the measured growth rate v_exp"}


def _listed(items):
    items = list(items)
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def references(provenance):
    """[(model names, reference)] in order of first use, each reference once."""
    found = {}
    for model in provenance.get("models", []):
        reference = model.get("reference", "")
        if reference:
            found.setdefault(reference, []).append(model["name"])
    return [(names, reference) for reference, names in found.items()]


def methods_paragraph(provenance, written):
    """One paragraph, with [n] pointing into references(provenance)."""
    numbers = {}
    for index, (names, _) in enumerate(references(provenance), start=1):
        for name in names:
            numbers[name] = index

    def cite(*names):
        cited = sorted({numbers[name] for name in names if name in numbers})
        return f" [{', '.join(map(str, cited))}]" if cited else ""

    lines = provenance.get("lines", [])
    fidelity = Counter(line["fidelity"] for line in lines)
    fidelity_text = _listed(f"{name} ({count} of {len(lines)} lines)" if len(fidelity) > 1 else name
                            for name, count in fidelity.items())
    models = {model["name"] for model in provenance.get("models", [])}
    outputs = [QUANTITY_NAMES.get(name, name) for name in provenance.get("outputs", [])]
    text = [f"Results were computed with growthuq {provenance['growthuq_version']} from the campaign "
            f"{provenance.get('campaign_name', '')} (file {provenance.get('campaign_path', '')}, SHA-256 "
            f"{provenance.get('campaign_sha256', '')}), written {written}."]
    correlated = [line["name"] for line in lines if line.get("correlation", "none") != "none"]
    subject = (f"The plant line {lines[0]['name']} was" if len(lines) == 1 else
               f"Each of the {len(lines)} plant lines ({_listed(line['name'] for line in lines)}) was")
    text.append(f"{subject} sampled with "
                f"{provenance['samples_per_line']} Latin hypercube samples{cite('latin_hypercube')} (seed "
                f"{provenance['seed']})" +
                (f", the rank correlation of the inputs imposed by Iman and Conover's method{cite('iman_conover')} "
                 f"for {len(correlated)} of them" if correlated else "") + ".")
    text.append(f"Outputs: {_listed(outputs)}.")
    mechanics = [name for name in ("thin_shell_turgor", "thin_shell_modulus", "corrected_turgor_modulus",
                                   "shell_fe_turgor_modulus") if name in models]
    if mechanics:
        text.append(f"Turgor and modulus were obtained from each sample's stiffness, diameters and wall thickness at "
                    f"fidelity {fidelity_text}{cite(*mechanics)}, with " +
                    (f"the probe radius, not known, drawn per sample from the law {provenance['probe_radius_law']} "
                     f"(median {significant(number(str(provenance['probe_radius_um'])))} µm)"
                     if provenance.get("probe_radius_law") else
                     f"a probe radius of {significant(number(str(provenance['probe_radius_um'])))} µm") +
                    f" and a Poisson ratio of "
                    f"{significant(provenance['poisson_ratio'])}" +
                    ("" if provenance.get("sensor_stiffness_N_per_m") is None else
                     f", correcting for a sensor stiffness of {significant(provenance['sensor_stiffness_N_per_m'])} N/m")
                    + ".")
    if "viscosity" in models:
        text.append(f"The wall viscosity is η = τ (1 − e∞) E from a generalized Maxwell relaxation{cite('viscosity')}.")
    if "growth" in models:
        text.append(f"The growth rate follows Lockhart's and Ortega's law{cite('growth')} with a yield pressure of "
                    f"{significant(provenance['yield_pressure_MPa'])} MPa, its factor κ calibrated on the line "
                    f"{provenance['reference_line']} (its predicted median growth rate equals its measured one).")
    replicates = provenance.get("data_interval_replicates", 0)
    if replicates:
        text.append(f"Data 95 % intervals of the medians come from a parametric bootstrap over tubes: "
                    f"{replicates} replicates of {provenance['data_interval_samples']} samples per line, the laws "
                    f"of the raw-data lines refitted to tubes redrawn from them each time.")
    else:
        text.append("No line is given by raw data, so the intervals are Monte Carlo intervals only: they say "
                    "how precisely the samples fix each statistic, not how precisely the data do.")
    if "published_data" in models:
        text.append(f"Line files restating published medians and IQRs come from the published study{cite('published_data')}.")
    return " ".join(text)


def _audit_warnings(audit):
    """Per audited line, the bias this run measured of its fast fidelity ([audit]): the figure
    for these tubes, beside the documented one above."""
    if not audit:
        return []
    found = []
    rows = {}
    for row in audit["rows"]:
        rows.setdefault((row["line"], row["fidelity"]), []).append(row)
    for (line, fidelity), measured in rows.items():
        biases = "; ".join(
            f"{row['quantity']} {significant(row['bias'])} {row['unit']} "
            f"(95 % interval {significant(row['bias_ci_low'])} to {significant(row['bias_ci_high'])}, {row['pairs']} pairs)"
            for row in measured)
        found.append(f"{line}: {fidelity} measured against {audit['high_fidelity']} (mesh {audit['mesh']}) in this run, "
                     f"on its first {audit['samples_per_line']} samples: bias ({audit['high_fidelity']} minus "
                     f"{fidelity}) {biases} (audit.csv).")
    return found


def warnings(provenance, summary):
    """Lines of text a reader must not miss: each fidelity's measured error (and the bias an audit
    measured in this run), flagged samples, a run without provenance."""
    found = []
    if provenance is None:
        found.append("This run has no provenance.json (a growthuq older than the report, or a results directory "
                     "copied without it): the methods paragraph and the references are missing; rerun the "
                     "campaign to get them.")
        return found
    seen = set()
    for model in provenance.get("models", []):
        error = model.get("measured_error", "")
        if error and error not in seen:
            seen.add(error)
            found.append(f"Measured error of {model['name']}: {error}.")
    found.extend(_audit_warnings(provenance.get("audit")))
    for line in provenance.get("lines", []):
        if line.get("illustrative"):
            found.append(f"{line['name']}: the laws of {', '.join(line['illustrative'])} are illustrative (they fill "
                         "gaps of the published table), not measured (distributions/README.md).")
    flagged = {}  # line: ({quantity: count}, samples)
    for row in summary:
        count = int(row["n_flagged"])
        if count > 0:
            quantities, _ = flagged.setdefault(row["line"], ({}, int(row["n"]) + count))
            quantities[row["quantity"]] = count
    for line, (quantities, total) in flagged.items():
        counts = ", ".join(f"{quantity} {count}" for quantity, count in quantities.items())
        found.append(f"{line}: flagged samples (of {total}) without a value, left out of the summary and the "
                     f"figures: {counts} (samples.csv gives each sample's status).")
    return found

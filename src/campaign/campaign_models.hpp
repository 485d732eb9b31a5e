// The models a campaign plans from: a list of evaluators, each declaring the columns it reads
// and writes (evaluator.hpp). For each line the planner takes, in this order of preference,
// the first evaluator that writes a needed quantity and only those the requested outputs need;
// a fidelity is then a choice of which evaluator in the list provides p and E.
#pragma once

#include <memory>
#include <vector>

#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/evaluation/evaluator.hpp"

namespace growthuq {

// The models of a fidelity: its turgor and modulus (closed_form: p from k, d, d0 and E from p, d,
// d0, h; corrected and shell_fe: p and E together from k, d, d0, h; for the campaign's
// instrument and [shell_fe] options), the viscosity (eta from tau, einf, E) and the growth law (v from
// p, d, eta, h) at the campaign's yield pressure, with kappa = 1: the run calibrates kappa on the
// reference line and scales v after (kappa.hpp).
std::vector<std::unique_ptr<const Evaluator>> campaign_models(const Campaign& campaign, Fidelity fidelity);

}  // namespace growthuq

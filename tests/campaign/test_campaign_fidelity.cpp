// The fidelity keys of a campaign file: the names (and the old one), the per-line override, the
// [shell_fe] section's values and one clear error per mistake; and the models each fidelity
// plans with.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "campaign/campaign_models.hpp"
#include "growthuq/campaign/campaign_file.hpp"
#include "growthuq/campaign/campaign_run.hpp"
#include "growthuq/core/error.hpp"
#include "growthuq/fe/shell_fe_evaluator.hpp"
#include "support/campaign_text.hpp"

using namespace growthuq;
using namespace growthuq::testing;
namespace fs = std::filesystem;

namespace {

const std::string valid =
    "[campaign]\nname = test\nseed = 7\nsamples = 10\noutputs = p, E\noutput_dir = out\n"
    "[instrument]\nprobe_radius_um = 0.5\n"
    "[line wt]\ndistributions = wt.ini\n"
    "[line m1]\ndistributions = m1.ini\n";

std::vector<std::string> model_names(const Campaign& campaign, Fidelity fidelity) {
  std::vector<std::string> names;
  for (const auto& model : campaign_models(campaign, fidelity)) names.emplace_back(model->name());
  return names;
}

}  // namespace

TEST_CASE("fidelity: the three names, the old name, the default, and a line's own") {
  const CampaignFolder folder("campaign_fidelity", {"wt.ini", "m1.ini"});
  CHECK(parse_campaign(valid, folder.path()).fidelity == Fidelity::closed_form);
  const auto with = [&](const std::string& name) {
    return parse_campaign(replaced(valid, "output_dir = out\n", "output_dir = out\nfidelity = " + name + "\n"), folder.path());
  };
  CHECK(with("closed_form").fidelity == Fidelity::closed_form);
  CHECK(with("thin_shell").fidelity == Fidelity::closed_form);
  CHECK(with("corrected").fidelity == Fidelity::corrected);
  CHECK(with("shell_fe").fidelity == Fidelity::shell_fe);
  for (const Fidelity fidelity : {Fidelity::closed_form, Fidelity::corrected, Fidelity::shell_fe}) {
    CHECK(parse_fidelity(to_string(fidelity), "here", "fidelity") == fidelity);
  }

  const Campaign mixed = parse_campaign(replaced(valid, "distributions = m1.ini\n", "distributions = m1.ini\nfidelity = shell_fe\n"),
                                        folder.path());
  CHECK(mixed.fidelity_of(mixed.lines[0]) == Fidelity::closed_form);
  CHECK(mixed.fidelity_of(mixed.lines[1]) == Fidelity::shell_fe);
}

TEST_CASE("a line's chunks follow its models' stated cost: finite-element samples one by one") {
  // wild_type runs shell_fe, pme48 corrected, xeg113 closed_form (the campaign's).
  const PreparedCampaign prepared(read_campaign(std::string(GROWTHUQ_SOURCE_DIR) + "/tests/campaign/data/fidelity_campaign.ini"));
  REQUIRE(prepared.lines().size() == 3);
  for (const PreparedLine& line : prepared.lines()) {
    const bool fe = prepared.campaign().fidelity_of(line.campaign_line) == Fidelity::shell_fe;
    CAPTURE(line.campaign_line.name);
    CHECK(prepared.has_slow_samples(line) == fe);
    CHECK(prepared.chunk_size_of(line) == (fe ? 1u : 4096u));
    if (fe) CHECK(seconds_per_sample(line.plan) == shell_fe_seconds_per_sample(ShellFeMesh::coarse));
    if (!fe) CHECK(seconds_per_sample(line.plan) == 0.0);
  }
}

TEST_CASE("[shell_fe]: every key read into the model's options") {
  const CampaignFolder folder("campaign_fidelity", {"wt.ini", "m1.ini"});
  const Campaign campaign = parse_campaign(
      valid + "[shell_fe]\nlaw = stvk\nmesh = coarse\nsubstrate = off\nbending = off\nhalf_model = off\n"
              "tube_length_um = 80\nprobe_distance_um = 12.5\nforce_window_uN = 0.5, 3\nchunk_size = 3\n",
      folder.path());
  const ShellFeOptions& o = campaign.shell_fe;
  CHECK(o.law == ShellFeLaw::saint_venant_kirchhoff);
  CHECK(o.mesh == ShellFeMesh::coarse);
  CHECK_FALSE(o.substrate);
  CHECK_FALSE(o.bending);
  CHECK_FALSE(o.half_model);
  CHECK(o.tube_length == doctest::Approx(80e-6).epsilon(1e-15));
  CHECK(o.probe_distance == doctest::Approx(12.5e-6).epsilon(1e-15));
  CHECK(o.force_window[0] == doctest::Approx(0.5e-6).epsilon(1e-15));
  CHECK(o.force_window[1] == doctest::Approx(3e-6).epsilon(1e-15));
  CHECK(campaign.shell_fe_chunk_size == 3);
  // The defaults are the model's own.
  const ShellFeOptions defaults = parse_campaign(valid, folder.path()).shell_fe;
  CHECK(defaults.law == ShellFeLaw::hencky);
  CHECK(defaults.mesh == ShellFeMesh::standard);
  CHECK(defaults.substrate);
  CHECK(defaults.tube_length == 100e-6);
}

TEST_CASE("fidelity and [shell_fe] mistakes: one error naming file, line, key, value and what was expected") {
  const CampaignFolder folder("campaign_fidelity", {"wt.ini", "m1.ini"});
  const std::string file = folder.path();
  const auto error_of = [&](const std::string& text) { return parse_error(text, file); };
  CHECK(error_of(replaced(valid, "output_dir = out\n", "output_dir = out\nfidelity = fem\n")) ==
        file + ":7: fidelity = 'fem': expected closed_form (the thin shell's closed forms; old name thin_shell), corrected (the "
               "closed form corrected to the finite-element model) or shell_fe (the finite-element model)");
  CHECK(error_of(replaced(valid, "distributions = wt.ini\n", "distributions = wt.ini\nfidelity = FE\n"))
            .starts_with(file + ":11: fidelity = 'FE': expected closed_form"));
  const std::string section = valid + "[shell_fe]\n";  // at line 13, its keys from line 14
  CHECK(error_of(section + "law = neo_hookean\n") ==
        file + ":14: law = 'neo_hookean': expected log (Hencky: Kirchhoff stress = Hooke of the log strain) or stvk (Saint "
               "Venant-Kirchhoff)");
  CHECK(error_of(section + "mesh = medium\n") == file + ":14: mesh = 'medium': expected coarse, default, fine or finer");
  CHECK(error_of(section + "substrate = yes\n") == file + ":14: substrate = 'yes': expected on or off");
  CHECK(error_of(section + "tube_length_um = 2\n") == file + ":14: tube_length_um = '2': expected a tube length in [5, 1e6] um (default 100)");
  CHECK(error_of(section + "force_window_uN = 4,0.4\n") ==
        file + ":14: force_window_uN = '4,0.4': expected two forces 'LOW,HIGH' in uN with 0 <= LOW < HIGH (default 0.4,4)");
  CHECK(error_of(section + "force_window_uN = 4\n").starts_with(file + ":14: force_window_uN = '4': expected two forces"));
  CHECK(error_of(section + "chunk_size = 0\n") == file + ":14: chunk_size = '0': expected a whole number from 1 to 10000");
  CHECK(error_of(section + "geometry = sphere\n") ==
        file + ":14: unknown key 'geometry' in [shell_fe] (allowed: law, mesh, contact, substrate, bending, half_model, tube_length_um, "
               "probe_distance_um, force_window_uN, chunk_size)");
  // The probe must sit on the tube: a distance beyond its length is refused as the model refuses it,
  // at the key's own line (15), not the section's (13).
  CHECK(error_of(section + "tube_length_um = 20\nprobe_distance_um = 30\n") ==
        file + ":15: probe_distance_um = '30': expected the probe's distance behind the apex in [0, tube_length) um (default 10)");
}

TEST_CASE("each fidelity plans its own turgor and modulus models, the rest alike") {
  const CampaignFolder folder("campaign_fidelity", {"wt.ini", "m1.ini"});
  const Campaign campaign = parse_campaign(valid, folder.path());
  CHECK(model_names(campaign, Fidelity::closed_form) ==
        std::vector<std::string>{"thin_shell_turgor", "thin_shell_modulus", "viscosity", "growth"});
  // The fidelities that write p and E together also give the closed form's wall stresses.
  CHECK(model_names(campaign, Fidelity::shell_fe) ==
        std::vector<std::string>{"shell_fe_turgor_modulus", "wall_stress", "viscosity", "growth"});
  CHECK(model_names(campaign, Fidelity::corrected) ==
        std::vector<std::string>{"corrected_turgor_modulus", "wall_stress", "viscosity", "growth"});
}

TEST_CASE("fidelity corrected refuses model options it was not fitted for, naming the key") {
  const CampaignFolder folder("campaign_fidelity", {"wt.ini", "m1.ini"});
  const auto models_of = [&](const std::string& section) {
    return campaign_models(parse_campaign(valid + "[shell_fe]\n" + section, folder.path()), Fidelity::corrected);
  };
  CHECK_THROWS_WITH_AS(models_of("law = stvk\n"),
                       doctest::Contains("law = 'stvk': expected log, the value fidelity corrected was fitted for"), InputError);
  // By the key, as the file spells it (eval names its flag instead: tests/mechanics/test_cli.cpp).
  std::string refusal;
  try {
    models_of("law = stvk\n");
  } catch (const InputError& error) {
    refusal = error.what();
  }
  CHECK(refusal.starts_with(folder.path() + ": law = 'stvk'"));
  CHECK_THROWS_WITH_AS(models_of("substrate = off\n"), doctest::Contains("substrate = 'off': expected on"), InputError);
  CHECK_THROWS_WITH_AS(models_of("probe_distance_um = 20\n"), doctest::Contains("probe_distance_um = '20': expected 10"),
                       InputError);
  // The force window is one of the correction's groups: a window it was fitted over gives a value,
  // one whose bottom is too close to its top is refused by the key.
  CHECK_NOTHROW(models_of("force_window_uN = 0.4,3\n"));
  CHECK_THROWS_WITH_AS(models_of("force_window_uN = 2,3\n"),
                       doctest::Contains("force_window_uN = '2,3': expected a force window whose bottom is 0.05 to 0.5 of its top"),
                       InputError);
  // The mesh is not one of them: the correction stands for the coarse mesh's inverse whatever the campaign's.
  CHECK_NOTHROW(models_of("mesh = coarse\n"));
}

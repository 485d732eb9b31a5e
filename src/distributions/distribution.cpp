// The variant Distribution: one std::visit per call, and for batches one per batch, so the
// per-value loop runs on the concrete family without dispatch.
#include "growthuq/distributions/distribution.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "distributions/checks.hpp"
#include "distributions/vector_exp.hpp"
#include "growthuq/distributions/standard_normal.hpp"

namespace growthuq {
namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace

double pdf(const Distribution& distribution, double x) {
  return std::visit([x](const auto& d) { return pdf(d, x); }, distribution);
}

double cdf(const Distribution& distribution, double x) {
  return std::visit([x](const auto& d) { return cdf(d, x); }, distribution);
}

double quantile(const Distribution& distribution, double u) {
  return std::visit([u](const auto& d) { return quantile(d, u); }, distribution);
}

void quantiles(const Distribution& distribution, std::span<const double> u, std::span<double> x) {
  if (u.size() != x.size()) throw std::invalid_argument("quantiles: spans of different sizes");
  std::visit(Overloaded{
                 [&](const Lognormal& d) {
                   // The hot path of Latin hypercube designs: Phi^-1 in one pass, then the
                   // exponential map in a second, branch-free pass.
                   standard_normal_quantiles(u, x);
                   detail::exp_affine(x.data(), x.data(), x.size(), d.mu(), d.sigma());
                 },
                 [&](const Normal& d) {
                   standard_normal_quantiles(u, x);
                   const double mean = d.mean();
                   const double sd = d.sd();
                   for (double& value : x) value = mean + sd * value;
                 },
                 [&](const auto& d) {
                   for (std::size_t i = 0; i < u.size(); ++i) x[i] = quantile(d, u[i]);
                 }},
             distribution);
}

std::string_view family_name(const Distribution& distribution) {
  return std::visit(Overloaded{[](const Lognormal&) { return std::string_view("lognormal"); },
                               [](const Normal&) { return std::string_view("normal"); },
                               [](const TruncatedNormal&) { return std::string_view("truncated_normal"); },
                               [](const Uniform&) { return std::string_view("uniform"); },
                               [](const Gamma&) { return std::string_view("gamma"); },
                               [](const Weibull&) { return std::string_view("weibull"); },
                               [](const Beta&) { return std::string_view("beta"); },
                               [](const Empirical&) { return std::string_view("empirical"); }},
                    distribution);
}

std::vector<std::pair<std::string, double>> parameter_values(const Distribution& distribution) {
  using Parameters = std::vector<std::pair<std::string, double>>;
  return std::visit(
      Overloaded{
          [](const Lognormal& d) { return Parameters{{"mu", d.mu()}, {"sigma", d.sigma()}}; },
          [](const Normal& d) { return Parameters{{"mean", d.mean()}, {"sd", d.sd()}}; },
          [](const TruncatedNormal& d) {
            return Parameters{{"mean", d.mean()}, {"sd", d.sd()}, {"lower", d.lower()}, {"upper", d.upper()}};
          },
          [](const Uniform& d) { return Parameters{{"lower", d.lower()}, {"upper", d.upper()}}; },
          [](const Gamma& d) { return Parameters{{"shape", d.shape()}, {"scale", d.scale()}}; },
          [](const Weibull& d) { return Parameters{{"shape", d.shape()}, {"scale", d.scale()}}; },
          [](const Beta& d) { return Parameters{{"alpha", d.alpha()}, {"beta", d.beta()}, {"upper", d.upper()}}; },
          [](const Empirical& d) {
            return Parameters{{"n", static_cast<double>(d.sorted_data().size())}, {"min", d.lower()}, {"max", d.upper()}};
          }},
      distribution);
}

std::string describe(const Distribution& distribution) {
  std::string body;
  for (const auto& [name, value] : parameter_values(distribution)) {
    // empirical's n is a count, printed in full
    const std::string text = name == "n" ? std::to_string(static_cast<std::size_t>(value)) : number(value);
    body += (body.empty() ? "" : ", ") + name + "=" + text;
  }
  if (const auto* lognormal = std::get_if<Lognormal>(&distribution)) {
    body += "; median=" + number(lognormal->median()) + ", iqr=" + number(lognormal->iqr());
  }
  return std::string(family_name(distribution)) + "(" + body + ")";
}

}  // namespace growthuq

// Every distribution family the engine knows, each an immutable value with free functions
// pdf, cdf and quantile (u = 0 and u = 1 give the ends of the support; u outside [0, 1] or NaN
// is an InputError). The variant `Distribution` over them is in distribution.hpp.
#pragma once

#include "growthuq/distributions/beta.hpp"
#include "growthuq/distributions/empirical.hpp"
#include "growthuq/distributions/gamma.hpp"
#include "growthuq/distributions/lognormal.hpp"
#include "growthuq/distributions/normal.hpp"
#include "growthuq/distributions/truncated_normal.hpp"
#include "growthuq/distributions/uniform.hpp"
#include "growthuq/distributions/weibull.hpp"

#include "cvode_handles.hpp"

#include <new>
#include <stdexcept>

#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

namespace growthuq::growth_detail {

CvodeHandles::CvodeHandles(sunindextype size, int method) {
  SUNContext context = nullptr;
  if (SUNContext_Create(nullptr, &context) != 0 || context == nullptr) throw std::bad_alloc();
  context_.reset(context);
  state_.reset(N_VNew_Serial(size, context));
  if (!state_) throw std::bad_alloc();
  N_VConst(0.0, state_.get());
  memory_.reset(CVodeCreate(method, context));
  if (!memory_) throw std::bad_alloc();
}

void CvodeHandles::use_fixed_point_solver() {
  solver_.reset(SUNNonlinSol_FixedPoint(state_.get(), 0, context_.get()));
  if (!solver_) throw std::bad_alloc();
  if (CVodeSetNonlinearSolver(memory_.get(), solver_.get()) != CV_SUCCESS) {
    throw std::logic_error("CVodeSetNonlinearSolver failed");
  }
}

}  // namespace growthuq::growth_detail

// Owning handles for the SUNDIALS objects one CVODE integration needs (context, vector,
// nonlinear solver, integrator memory), released in reverse order on every path out,
// exceptions included.
#pragma once

#include <memory>
#include <type_traits>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_nonlinearsolver.h>

namespace growthuq::growth_detail {

class CvodeHandles {
 public:
  // A serial vector of `size` zeros and a CVODE memory for `method` (CV_ADAMS or CV_BDF);
  // std::bad_alloc when SUNDIALS cannot allocate them.
  CvodeHandles(sunindextype size, int method);

  SUNContext context() const noexcept { return context_.get(); }
  N_Vector state() const noexcept { return state_.get(); }
  void* memory() const noexcept { return memory_.get(); }

  // Attaches a fixed-point nonlinear solver (owned here): right for non-stiff problems and
  // needs no Jacobian.
  void use_fixed_point_solver();

 private:
  struct FreeContext {
    void operator()(SUNContext context) const noexcept { SUNContext_Free(&context); }
  };
  struct FreeVector {
    void operator()(N_Vector vector) const noexcept { N_VDestroy(vector); }
  };
  struct FreeSolver {
    void operator()(SUNNonlinearSolver solver) const noexcept { SUNNonlinSolFree(solver); }
  };
  struct FreeMemory {
    void operator()(void* memory) const noexcept { CVodeFree(&memory); }
  };

  // Declaration order is construction order; CVODE memory goes first, the context last.
  std::unique_ptr<std::remove_pointer_t<SUNContext>, FreeContext> context_;
  std::unique_ptr<std::remove_pointer_t<N_Vector>, FreeVector> state_;
  std::unique_ptr<std::remove_pointer_t<SUNNonlinearSolver>, FreeSolver> solver_;
  std::unique_ptr<void, FreeMemory> memory_;
};

}  // namespace growthuq::growth_detail

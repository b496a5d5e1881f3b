#include <coaxfit/alpha_controller.h>
#include <coaxfit/input_error.h>

namespace coaxfit
{
  FixedAlphaController::FixedAlphaController(const double alpha)
    : value(alpha)
  {}



  std::string
  FixedAlphaController::name() const
  {
    return "fixed";
  }



  void
  FixedAlphaController::update(const NeumannState &)
  {}



  double
  FixedAlphaController::alpha(const unsigned int) const
  {
    return value;
  }



  double
  FixedAlphaController::representative_alpha() const
  {
    return value;
  }



  std::unique_ptr<AlphaController>
  make_alpha_controller(const Parameters &parameters)
  {
    if (parameters.alpha_controller == "fixed")
      return std::make_unique<FixedAlphaController>(parameters.alpha);
    throw InputError("parameter Coupling/Alpha controller = "
                     + parameters.alpha_controller
                     + " is not known: allowed is fixed.");
  }
} // namespace coaxfit

#ifndef coaxfit_tests_yielding_hub_example_h
#define coaxfit_tests_yielding_hub_example_h

#include <coaxfit/design/radial_plastic_fit.h>

#include "run_executable.h"

#include <filesystem>
#include <iostream>
#include <string>

/**
 * The scene of prm/examples/yielding_hub.prm for the tests of elastic-plastic
 * fits: the file, a run of it, and the radial model of its rings.
 */
namespace coaxfit_test
{
  /** prm/examples/yielding_hub.prm. */
  inline const std::string yielding_hub_example
    = std::string(COAXFIT_SOURCE_DIR) + "/prm/examples/yielding_hub.prm";

  /**
   * Run the example with @p arguments into @p dir (emptied first); print
   * the exit code and what the run said on standard error.
   */
  inline RunResult
  run_example(const std::string &dir, const std::string &arguments)
  {
    std::filesystem::remove_all(dir);
    const RunResult r
      = run_coaxfit(dir, arguments + " " + yielding_hub_example);
    std::cout << "  exit code " << r.exit_code;
    if (!r.message.empty())
      std::cout << ", " << r.lines << " line(s): " << r.message;
    else
      std::cout << '\n';
    return r;
  }

  /**
   * The example's rings (a solid elastic steel shaft D 50 mm in a steel hub
   * D 50-100 mm yielding at 300 MPa, perfectly plastic) as the radial model
   * in @p state, 500 elements per body.
   */
  inline coaxfit::RadialPlasticFit
  radial_model(const coaxfit::RadialPlasticFit::State state)
  {
    coaxfit::Material steel;
    steel.E               = 210000.;
    steel.nu              = 0.3;
    coaxfit::Material hub = steel;
    hub.yield_strength    = 300.;
    hub.plastic           = true;
    return coaxfit::RadialPlasticFit({0., 25., steel},
                                     {25., 50., hub},
                                     state,
                                     500);
  }
} // namespace coaxfit_test

#endif

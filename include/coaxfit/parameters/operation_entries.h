#ifndef coaxfit_operation_entries_h
#define coaxfit_operation_entries_h

#include <string>

/**
 * @file The entries of `Operation` that are text: temperatures (empty: the
 * assembly temperature) and the joining clearance (`auto`).
 */
namespace coaxfit
{
  /** Absolute zero in degrees C. */
  constexpr double absolute_zero = -273.15;

  /** The hottest operating or assembly temperature allowed (degrees C). */
  constexpr double hottest_temperature = 1000.;

  /**
   * The temperature of the entry @p text in degrees C: empty (or blank) is
   * @p assembly, the assembly temperature; NaN if @p text is not one
   * number.
   */
  double
  temperature_entry(const std::string &text, double assembly);

  /**
   * Refuse the temperature @p value read from @p text for the entry
   * @p name unless it is a number with -273.15 < T <= 1000 (an InputError
   * naming the entry and the allowed range).
   */
  void
  check_temperature_entry(double             value,
                          const std::string &text,
                          const std::string &name);
  /**
   * The joining clearance (mm, diametral) of the entry @p text at the
   * joint diameter @p D: `auto` (or empty) is DIN 7190's guide value
   * 0.001 D; NaN if @p text is not one number.
   */
  double
  joining_clearance_entry(const std::string &text, double D);
} // namespace coaxfit

#endif

// No error of the concurrent body work may be lost: coaxfit::concurrently()
// runs two jobs (the shaft's and the hub's factorization, condensation or
// solve) and must re-throw an exception of either, after both finished,
// whatever the order in which they fail. Each case prints what reached the
// caller and whether both jobs ran to their end.

#include <coaxfit/base/concurrency.h>
#include <coaxfit/base/input_error.h>

#include <atomic>
#include <chrono>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>

namespace
{
  /** A job that works @p ms milliseconds, then fails if @p fail. */
  auto
  job(std::atomic<int> &finished,
      const bool        fail,
      const int         ms,
      const std::string name)
  {
    return [&finished, fail, ms, name]() {
      std::this_thread::sleep_for(std::chrono::milliseconds(ms));
      ++finished;
      if (fail)
        throw coaxfit::ResourceError("out of memory in the " + name);
    };
  }

  void
  check(const std::string &label,
        const bool         shaft_fails,
        const int          shaft_ms,
        const bool         hub_fails,
        const int          hub_ms)
  {
    std::atomic<int> finished(0);
    std::string      outcome = "no exception";
    try
      {
        coaxfit::concurrently(job(finished, shaft_fails, shaft_ms, "shaft"),
                              job(finished, hub_fails, hub_ms, "hub"));
      }
    catch (const coaxfit::ResourceError &e)
      {
        outcome = std::string("ResourceError: ") + e.what();
      }
    catch (...)
      {
        outcome = "an exception of another type";
      }
    std::cout << label << ": " << outcome << "; jobs finished: " << finished
              << " of 2" << std::endl;
  }
} // namespace



int
main()
{
  check("none fails", false, 10, false, 10);
  check("shaft fails first", true, 0, false, 50);
  check("shaft fails last", true, 50, false, 0);
  check("hub fails first", false, 50, true, 0);
  check("hub fails last", false, 0, true, 50);
  // Both fail: the hub's (the caller's own job) is reported; the shaft's is
  // not lost silently either way, the call throws.
  check("both fail", true, 0, true, 50);
}

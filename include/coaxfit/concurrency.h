#ifndef coaxfit_concurrency_h
#define coaxfit_concurrency_h

#include <deal.II/base/thread_management.h>

#include <exception>

namespace coaxfit
{
  /**
   * Run two jobs concurrently (the two bodies of a step) and wait for both.
   * An exception thrown by either job is re-thrown here, after both have
   * finished: deal.II 9.4's Threads::Task::join() does not re-throw, so the
   * job on the task captures its exception itself.
   */
  template <typename F1, typename F2>
  void
  concurrently(const F1 &job1, const F2 &job2)
  {
    std::exception_ptr          error;
    dealii::Threads::Task<void> task = dealii::Threads::new_task([&]() {
      try
        {
          job1();
        }
      catch (...)
        {
          error = std::current_exception();
        }
    });
    try
      {
        job2();
      }
    catch (...)
      {
        task.join();
        throw;
      }
    task.join();
    if (error)
      std::rethrow_exception(error);
  }
} // namespace coaxfit

#endif

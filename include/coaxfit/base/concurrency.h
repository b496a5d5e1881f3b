#ifndef coaxfit_concurrency_h
#define coaxfit_concurrency_h

#include <deal.II/base/thread_management.h>

#include <exception>
#include <functional>
#include <system_error>
#include <thread>
#include <vector>

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


  /**
   * Run @p job for every element of @p items concurrently (each body of a
   * scene) and wait for all: the last on this thread, the others as tasks;
   * for two items what concurrently() does. The first exception thrown, in
   * the order of the items, is re-thrown after every job has finished.
   */
  template <typename Container, typename F>
  void
  for_each_concurrently(Container &items, const F &job)
  {
    const std::size_t                        n = items.size();
    std::vector<std::exception_ptr>          errors(n);
    std::vector<dealii::Threads::Task<void>> tasks;
    for (std::size_t i = 0; i + 1 < n; ++i)
      tasks.push_back(dealii::Threads::new_task([&, i]() {
        try
          {
            job(items[i]);
          }
        catch (...)
          {
            errors[i] = std::current_exception();
          }
      }));
    if (n > 0)
      try
        {
          job(items[n - 1]);
        }
      catch (...)
        {
          errors[n - 1] = std::current_exception();
        }
    for (auto &task : tasks)
      task.join();
    for (const std::exception_ptr &error : errors)
      if (error)
        std::rethrow_exception(error);
  }

  /**
   * Run every job of @p jobs on a thread of its own and wait for all of
   * them (result writers: a job may wait for a child process, so it gets
   * a thread, not a task of the pool). The first exception thrown, in the
   * order of the jobs, is re-thrown here after every job has finished;
   * none is lost or left running.
   */
  inline void
  each_on_own_thread(const std::vector<std::function<void()>> &jobs)
  {
    std::vector<std::exception_ptr> errors(jobs.size());
    std::vector<std::thread>        threads;
    threads.reserve(jobs.size());
    for (unsigned int i = 0; i < jobs.size(); ++i)
      {
        auto run = [&jobs, &errors, i]() {
          try
            {
              jobs[i]();
            }
          catch (...)
            {
              errors[i] = std::current_exception();
            }
        };
        try
          {
            threads.emplace_back(run);
          }
        catch (const std::system_error &) // no thread to be had: run here
          {
            run();
          }
      }
    for (std::thread &thread : threads)
      thread.join();
    for (const std::exception_ptr &error : errors)
      if (error)
        std::rethrow_exception(error);
  }
} // namespace coaxfit

#endif

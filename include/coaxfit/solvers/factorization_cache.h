#ifndef coaxfit_factorization_cache_h
#define coaxfit_factorization_cache_h

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace coaxfit
{
  /**
   * The one factorization cache policy of the project: a body's matrix
   * depends only on which interface points are prescribed, so each set of
   * prescribed points (the key) gets one factorization, made by the given
   * function when it is first asked for and kept for reuse; the oldest is
   * dropped when more than @p capacity are kept. Used by the full body
   * solver (sparse Cholesky factors) and the condensed one (dense LU of the
   * compliance block).
   */
  template <typename Factor>
  class FactorizationCache
  {
  public:
    using Key = std::vector<bool>;

    explicit FactorizationCache(const unsigned int capacity = 4)
      : capacity(capacity)
    {}

    /** The factorization for @p key, made by @p make if not cached. */
    const Factor &
    get(const Key &key, const std::function<std::unique_ptr<Factor>()> &make)
    {
      const auto found = factors.find(key);
      if (found != factors.end())
        return *found->second;
      std::unique_ptr<Factor> factor = make();
      ++count;
      if (order.size() >= capacity)
        {
          factors.erase(order.front());
          order.pop_front();
        }
      order.push_back(key);
      return *(factors[key] = std::move(factor));
    }

    /** Forget every factorization (the matrix changed). */
    void
    clear()
    {
      factors.clear();
      order.clear();
    }

    /** Number of factorizations made so far. */
    unsigned int
    n_factorizations() const
    {
      return count;
    }

  private:
    const unsigned int                     capacity;
    std::map<Key, std::unique_ptr<Factor>> factors;
    std::deque<Key>                        order;
    unsigned int                           count = 0;
  };
} // namespace coaxfit

#endif

// A segment tree over leaves 0..count-1 that holds ranks (size_t) and answers the smallest rank in a leaf range:
// the chord sweep of the exact partition search keeps the cheapest candidate line per angle in it.
//
// reset(count): O(count), every leaf empty (`none`). set(leaf, value): O(log count). query(lo, hi): the minimum
// over leaves [lo, hi), `none` if all are empty or the range is empty, O(log count).
// Preconditions: leaf < count and lo <= hi <= count of the last reset.
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace rtl
{
    namespace detail
    {
        class MinRankTree
        {
        public:
            static constexpr size_t none = std::numeric_limits<size_t>::max();

            void reset(size_t count)
            {
                size = 1;
                while (size < count) size *= 2;
                tree.assign(2 * size, none);
            }
            void set(size_t leaf, size_t value)
            {
                size_t i = leaf + size;
                tree[i] = value;
                for (i /= 2; i > 0; i /= 2)
                    tree[i] = std::min(tree[2 * i], tree[2 * i + 1]);
            }
            [[nodiscard]] size_t query(size_t lo, size_t hi) const
            {
                size_t r = none;
                for (size_t l = lo + size, h = hi + size; l < h; l /= 2, h /= 2)
                {
                    if (l & 1) r = std::min(r, tree[l++]);
                    if (h & 1) r = std::min(r, tree[--h]);
                }
                return r;
            }

        private:
            size_t size{1};   // leaves, a power of two >= count
            std::vector<size_t> tree;   // 1-based heap layout: node i has children 2i, 2i + 1; leaves at [size, 2 size)
        };
    }
}

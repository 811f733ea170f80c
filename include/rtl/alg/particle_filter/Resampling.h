// Systematic (low-variance) resampling: the indices picked by evenly spaced thresholds on the cumulative weights.
// One pass over the weights, O(n + count).
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace rtl
{
    /*!
     * Picks count indices of weights: index i is picked once for every threshold (k + offset) / count, k < count,
     * that falls into its share [W_{i-1}, W_i) of the normalised cumulative weights W. So index i is picked
     * floor or ceil of count * w_i / sum(w) times, and the result is sorted.
     * Negative and non-finite weights count as 0; when no weight is positive, all count equally.
     * \param weights one weight per candidate index.
     * \param count how many indices to pick.
     * \param offset in [0, 1) (values outside are clamped); a uniform random offset makes the expected count exact.
     */
    inline std::vector<size_t> systematicResample(const std::vector<double> &weights, size_t count, double offset)
    {
        std::vector<size_t> picked;
        if (weights.empty() || count == 0)
            return picked;
        std::vector<double> w(weights.size());
        double total = 0;
        for (size_t i = 0; i < weights.size(); ++i)
        {
            w[i] = std::isfinite(weights[i]) && weights[i] > 0 ? weights[i] : 0.0;
            total += w[i];
        }
        if (!(total > 0) || !std::isfinite(total))
        {
            for (double &x : w)
                x = 1.0;
            total = static_cast<double>(w.size());
        }
        offset = offset < 0 ? 0 : (offset >= 1 ? std::nextafter(1.0, 0.0) : offset);
        size_t last = w.size() - 1;     // rounding must not carry a threshold past the last positive weight
        while (last > 0 && w[last] == 0)
            --last;
        picked.reserve(count);
        size_t i = 0;
        double cumulative = w[0] / total;
        for (size_t k = 0; k < count; ++k)
        {
            const double threshold = (static_cast<double>(k) + offset) / static_cast<double>(count);
            while (threshold >= cumulative && i < last)
                cumulative += w[++i] / total;
            picked.push_back(i);
        }
        return picked;
    }
}

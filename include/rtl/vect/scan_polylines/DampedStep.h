// One Levenberg-Marquardt iteration's search for a damping that descends, shared by the radial refinements: the damped
// normal equations are solved for lambda, 4 lambda, 16 lambda, ... (below 1e10) until a trial step lowers the cost;
// then lambda shrinks by 3 (not below 1e-9) for the next iteration. Only descending steps are taken, so a refinement
// built on it never ends above its start.
#pragma once

#include <algorithm>

namespace rtl::scan_polylines
{
    //! `tryStep(lambda, cost)` solves the system damped by lambda and, where it could, evaluates the trial step into
    //! `cost` (false when the system was not solvable); `accept()` makes the trial the current point. Returns whether a
    //! step was taken that lowered `current` by more than 1e-12 relative (false: converged, or no descent found).
    template<class TryStep, class Accept>
    bool dampedStep(double &lambda, double &current, TryStep tryStep, Accept accept)
    {
        while (lambda < 1e10)
        {
            double c = 0;
            if (tryStep(lambda, c) && c < current)
            {
                const double gain = current - c;
                accept();
                current = c;
                lambda = std::max(lambda / 3, 1e-9);
                return gain > 1e-12 * (current + 1e-30);
            }
            lambda *= 4;
        }
        return false;
    }
}

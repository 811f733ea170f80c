// Munkres: assign 3 workers to 3 jobs at the least (and the greatest) total cost.
#include <iostream>

#include "rtl/Algorithms.h"

int main()
{
    rtl::Matrix<3, 3, int> cost;
    const int values[3][3] = {{1, 2, 3}, {2, 4, 6}, {3, 6, 9}};
    for (size_t r = 0; r < 3; ++r)
        for (size_t c = 0; c < 3; ++c)
            cost(r, c) = values[r][c];

    for (bool maximize : {false, true})
    {
        int total = 0;
        std::cout << (maximize ? "maximum:" : "minimum:");
        for (const auto &pair : rtl::Munkres<int, 3>::solve(cost, maximize))
        {
            std::cout << "  row " << pair.row << " -> col " << pair.col << " (" << pair.cost << ")";
            total += pair.cost;
        }
        std::cout << "  total " << total << "\n";
    }

    // Rectangular, runtime size: 2 tracks, 3 detections; the unmatched detection is simply not chosen.
    const std::vector<double> distances = {0.4, 5.0, 1.2,
                                           3.1, 0.2, 4.4};
    const std::vector<size_t> match = rtl::solveAssignment(distances, 2, 3);
    std::cout << "track 0 -> detection " << match[0] << ", track 1 -> detection " << match[1] << "\n";
    return match[0] == 0 && match[1] == 1 ? 0 : 1;
}

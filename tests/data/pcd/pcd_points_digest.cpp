// Prints what rtl::readPcdFile<float> reads from each PCD file given: "OK width height points digest" (FNV-1a over the
// x, y, z bits, every NaN counted as one value) or "ERR message". Used by compare_with_pcl.sh; not part of the build.
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "rtl/io/PcdFile.h"

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
    {
        try
        {
            const auto cloud = rtl::readPcdFile<float>(argv[i]);
            std::uint64_t h = 1469598103934665603ull;
            for (const auto &p : cloud.points)
                for (int d = 0; d < 3; ++d)
                {
                    const float f = p[d];
                    std::uint32_t u = 0x7fc00000u;
                    if (f == f) std::memcpy(&u, &f, 4);
                    h = (h ^ u) * 1099511628211ull;
                }
            std::printf("OK %zu %zu %zu %016llx\n", cloud.width, cloud.height, cloud.points.size(),
                        static_cast<unsigned long long>(h));
        }
        catch (const rtl::PcdError &e)
        {
            std::printf("ERR %s\n", e.what());
        }
    }
}

// libFuzzer harness for the organised LiDAR reader (rtl/io/OrganizedLidar.h). The first byte chooses the layout
// (bit 4) and the beam count (1 + low 4 bits); the rest is the record stream. Any input either gives a cloud that
// keeps the reader's promises or throws its documented std::runtime_error; anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rtl/io/OrganizedLidar.h"

namespace
{
    void require(bool ok) { if (!ok) std::abort(); }

    float recordFloat(const std::string &bytes, std::size_t record, int k)
    {
        float f;
        std::memcpy(&f, bytes.data() + 16 * record + 4 * k, 4);   // (the fuzzing host is little-endian)
        return f;
    }

    template<typename E>
    void run(const std::string &bytes, std::size_t beams, rtl::OrganizedLayout layout)
    {
        try
        {
            std::istringstream in(bytes);
            const auto c = rtl::readOrganizedLidar<E>(in, beams, layout);
            require(c.beams == beams && c.columns * beams * 16 == bytes.size());
            require(c.points.size() == c.columns * beams && c.intensity.size() == c.points.size());
            for (std::size_t b = 0; b < beams; ++b)
                for (std::size_t col = 0; col < c.columns; ++col)
                {
                    const std::size_t rec = layout == rtl::OrganizedLayout::ColumnMajor ? col * beams + b : b * c.columns + col;
                    const float x = recordFloat(bytes, rec, 0), y = recordFloat(bytes, rec, 1), z = recordFloat(bytes, rec, 2);
                    const auto &p = c.at(b, col);
                    if (x == 0.f && y == 0.f && z == 0.f)
                        require(p.hasNaN());
                    else
                        require(p.x() == static_cast<E>(x) || (std::isnan(x) && std::isnan(p.x())));
                }
            if (c.columns > 0)
            {
                require(c.ring(beams - 1).size() == c.columns);
                require(c.column(c.columns - 1).size() == beams);
            }
            bool thrown = false;
            try
            {
                static_cast<void>(c.ring(beams));
            }
            catch (const std::out_of_range &)
            {
                thrown = true;
            }
            require(thrown);
        }
        catch (const std::runtime_error &e)
        {
            const std::string what = e.what();
            require(what.rfind("organised LiDAR", 0) == 0 && bytes.size() % (16 * beams) != 0);
        }
    }
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::size_t beams = 1 + (data[0] & 0x0f);
    const auto layout = (data[0] & 0x10) ? rtl::OrganizedLayout::RowMajor : rtl::OrganizedLayout::ColumnMajor;
    const std::string bytes(reinterpret_cast<const char *>(data + 1), size - 1);
    run<float>(bytes, beams, layout);
    run<double>(bytes, beams, layout);
    return 0;
}

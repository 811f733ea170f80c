// Shared by the program-style harnesses (segmenters, vectorizers): the check that turns a broken invariant into a
// libFuzzer finding, the byte source their opcodes and operands are read from, and the points the vectorizer
// harnesses decode from it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace fuzz
{
    //! Aborts (a libFuzzer finding) naming the harness line of the broken check (__builtin_LINE: clang and gcc).
    inline void require(bool ok, int line = __builtin_LINE())
    {
        if (ok)
            return;
        std::fprintf(stderr, "check failed at line %d\n", line);
        std::abort();
    }

    //! The fuzz input read front to back; reads past the end give 0, so every program is well defined.
    struct Bytes
    {
        const std::uint8_t *p;
        std::size_t n;
        bool empty() const { return n == 0; }
        std::uint8_t next()
        {
            if (n == 0)
                return 0;
            --n;
            return *p++;
        }
    };

    //! One coordinate of element type T: raw, the type's own bytes (any bit pattern: NaN, inf, subnormal, huge);
    //! otherwise a big-endian 16-bit integer times `scale`.
    template<typename T>
    T readCoordinate(Bytes &in, bool raw, double scale)
    {
        if (raw)
        {
            unsigned char b[sizeof(T)];
            for (auto &c : b) c = in.next();
            T x;
            std::memcpy(&x, b, sizeof(T));
            return x;
        }
        const auto hi = in.next(), lo = in.next();
        return static_cast<T>(static_cast<std::int16_t>(hi << 8 | lo) * scale);
    }

    //! Points (a fixed-size vector type with ElementType and operator[]) read until the input ends or `max` points
    //! are read, each coordinate by readCoordinate. With `runs`, each point is followed by a byte: that many copies
    //! of it (runs of identical points), `max` points in all.
    template<class Point, int dim>
    std::vector<Point> readPoints(Bytes &in, bool raw, double scale, std::size_t max, bool runs = false)
    {
        std::vector<Point> pts;
        while (in.n > 0 && pts.size() < max)
        {
            Point v;
            for (int k = 0; k < dim; ++k) v[k] = readCoordinate<typename Point::ElementType>(in, raw, scale);
            pts.push_back(v);
            if (runs)
                for (int copies = in.next(); copies > 0 && pts.size() < max; --copies) pts.push_back(v);
        }
        return pts;
    }
}

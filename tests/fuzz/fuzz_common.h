// Shared by the program-style harnesses (segmenters, vectorizers): the check that turns a broken invariant into a
// libFuzzer finding, and the byte source their opcodes and operands are read from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

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
}

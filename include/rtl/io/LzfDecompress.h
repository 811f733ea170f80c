// Decompressor for LZF streams (the block compression of PCD's binary_compressed data), written from the format's
// description: a stream is a sequence of items, each starting with a control byte c.
//  - c < 32: a literal run; the next c + 1 input bytes are copied to the output.
//  - c >= 32: a back reference of length (c >> 5) + 2, or, when c >> 5 == 7, of 7 + (next byte) + 2 (at most 264);
//    the distance is ((c & 31) << 8) + (next byte) + 1 bytes back from the current output end. The copy runs
//    byte by byte, so a reference may overlap the bytes it produces (a run).
// There is no header, no checksum and no end marker: the stream ends with the input.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rtl
{
    //! Outcome of lzfDecompress. `error` is nullptr on success, else a static description; `input_offset` is the
    //! offset of the item that failed (or the input size), `produced` the output bytes written before it.
    struct LzfResult
    {
        const char *error = nullptr;
        std::size_t input_offset = 0;
        std::size_t produced = 0;
    };

    //! The most output bytes an LZF stream of `input_size` bytes can describe (a 3-byte item gives 264 bytes):
    //! a bound to check a claimed size against before allocating for it.
    constexpr std::size_t lzfMaxOutput(std::size_t input_size)
    {
        return input_size / 3 * 264 + 264;
    }

    /*! Decompresses `input_size` bytes of LZF into `output`, which must hold `output_size` bytes. Succeeds only if
     *  the whole input decodes to exactly `output_size` bytes. A stream that needs more output, a literal run past
     *  the input's end, a reference before the output's start or a truncated item is an error: nothing is ever read
     *  or written outside the two buffers, whatever the input. O(input_size + output_size). */
    inline LzfResult lzfDecompress(const std::uint8_t *input, std::size_t input_size, std::uint8_t *output,
                                   std::size_t output_size)
    {
        LzfResult r;
        std::size_t ip = 0, op = 0;
        while (ip < input_size)
        {
            const std::size_t item = ip;
            const unsigned ctrl = input[ip++];
            if (ctrl < 32)
            {
                const std::size_t run = ctrl + 1;
                if (run > input_size - ip)
                    return {"literal run past the end of the input", item, op};
                if (run > output_size - op)
                    return {"literal run past the declared uncompressed size", item, op};
                for (std::size_t k = 0; k < run; ++k) output[op + k] = input[ip + k];
                ip += run;
                op += run;
            }
            else
            {
                std::size_t len = ctrl >> 5;
                if (len == 7)
                {
                    if (ip >= input_size) return {"back reference truncated", item, op};
                    len += input[ip++];
                }
                if (ip >= input_size) return {"back reference truncated", item, op};
                const std::size_t distance = ((static_cast<std::size_t>(ctrl & 31) << 8) | input[ip++]) + 1;
                len += 2;
                if (distance > op) return {"back reference before the start of the output", item, op};
                if (len > output_size - op)
                    return {"back reference past the declared uncompressed size", item, op};
                for (std::size_t k = 0; k < len; ++k, ++op) output[op] = output[op - distance];
            }
        }
        if (op != output_size) return {"stream ends before the declared uncompressed size", input_size, op};
        r.input_offset = input_size;
        r.produced = op;
        return r;
    }
}

// rtl::detail::tokens: the whitespace-separated tokens of one line of a text format (CARMEN logs, PCD headers).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace rtl::detail
{
    //! The tokens of s separated by spaces, tabs and carriage returns, as views into s (valid while s is).
    //! O(|s|); never throws except std::bad_alloc.
    inline std::vector<std::string_view> tokens(std::string_view s)
    {
        std::vector<std::string_view> t;
        std::size_t i = 0;
        while (i < s.size())
        {
            while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
            const std::size_t b = i;
            while (i < s.size() && s[i] != ' ' && s[i] != '\t' && s[i] != '\r') ++i;
            if (i > b) t.push_back(s.substr(b, i - b));
        }
        return t;
    }
}  // namespace rtl::detail
